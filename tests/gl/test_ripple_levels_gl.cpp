// The water shader's ripple composite (shaders/common_water.glsl rippleHeight: level 0's texture
// and the coarse ewave levels' array layers, made on the GPU from each level's two states and
// the cubic's weights by shaders/ripple_levels.comp, placed by WaterUniforms::rippleLevels and
// cross-faded by rippleFade) against the CPU's RipplePatch::heightAt, docs/ewave.md#levels.
#include "gfx/gl.h"
#include "gfx/gpu_bindings.h"
#include "gfx/shader.h"
#include "gfx/water_layers.h"
#include "gfx/water_pass.h"
#include "interaction/ripple_levels.h"
#include "interaction/ripple_patch.h"
#include "platform/platform.h"
#include "support/shader_probe.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>

using namespace ob;

// Three levels of 32² (0.25 m, 1 m, 4 m) hold a sphere's wake and splash craters, the patch
// and so the levels off-centre after scrolling; the shader's composite is read at points along
// a line through every fade band (level 0's, level 1's) and beyond level 1, and at random
// points, against RipplePatch::heightAt. Both form the same sum of bilinear reads times the
// same smoothstep weights; the shader's texture filter rounds its weights to at least 8 bits
// (GL 4.5 §8.14.2 leaves the precision to the implementation), an error of at most 2^-8 of
// the largest step between neighbouring texels (or to the zero border) per axis, so the bound
// is Σ_L 2·2^-8·step_L plus float rounding of the sums, 1e-6·max|h|. The same probe with level
// 1 placed one cell off, or with the coarse layers left out, must miss it by 10 times.
TEST_CASE("the water shader's ripple composite equals RipplePatch::heightAt across the level fades", "[gl][render][levels]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({16, 16});
    interaction::RippleDef def;
    def.model = interaction::rippleModel("ewave");
    def.backend = Backend::Cpu;
    def.resolution = 32;
    def.cell_size = 0.25f;
    def.levels = 3;
    def.sponge_width = 4;
    def.boundary = interaction::RippleBoundary::Absorbing;
    interaction::RipplePatch patch(def);
    interaction::BoundingSphere sphere;
    sphere.radius = 0.6f;
    sphere.direction = interaction::SphereDirection::Down;
    sphere.heightRatio = 1.0f;
    interaction::SphereContact contact;
    const float dt = 1.0f / 60.0f;
    for (int s = 0; s < 150; ++s) {  // 2.5 s at 4 m/s: the patch scrolls 40 fine cells
        const glm::vec2 ship(-3.0f + 4.0f * float(s) * dt, 0.7f);
        patch.centerOn(ship);
        patch.stampSphere(sphere, contact, glm::vec3(ship.x, 0.0f, ship.y), glm::vec3(4.0f, 0.0f, 0.0f), 1000.0f, 0.0f);
        if (s % 20 == 0) patch.addCrater(ship + glm::vec2(-9.0f, 3.0f + 0.1f * float(s)), -0.01);
        patch.step(dt);
    }
    const interaction::RippleLevels& levels = *patch.levels();

    gfx::WaterView view;
    view.ripples = patch.height().data();
    view.rippleCells = def.resolution;
    view.rippleOrigin = patch.origin();
    view.rippleCellSize = def.cell_size;
    for (int L = 1; L < levels.count(); ++L) {  // the states and the cubic's weights: the heights made on the GPU
        const interaction::LevelDraw d = patch.levelDraw(L);
        view.rippleLevels.push_back({{d.h0.data(), d.h1.data(), d.v0.data(), d.v1.data()}, d.version, d.weights, d.extremes, d.origin, d.cellSize});
    }
    view.rippleFadeCells = levels.sponge();
    gfx::WaterLayers layers;
    gfx::glsl::WaterUniforms u{};
    layers.upload(view, false, false, u);
    gfx::Buffer uniforms = gfx::createBuffer("probe water", sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, gfx::glsl::WATER_BLOCK, uniforms.id());

    // A line through the patch's centre along x, 0.37 m off it in z, from far outside level 1
    // to far past it on the other side (level 2's 128 m), and random points over level 2.
    const glm::vec2 centre = patch.origin() + 0.5f * float(def.resolution - 1) * def.cell_size;
    std::vector<glm::vec2> points;
    for (float x = -70.0f; x <= 70.0f; x += 0.07f) points.push_back(centre + glm::vec2(x, 0.37f));
    uint64_t rng = 12345;
    auto uniform = [&rng] {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        return float(double(rng >> 11) / double(1ull << 53));
    };
    for (int i = 0; i < 2000; ++i) points.push_back(centre + glm::vec2(uniform() - 0.5f, uniform() - 0.5f) * 140.0f);

    gfx::Program program = test::loadShaderProbe("ripple_levels_probe.comp", "probe_shaders_levels");
    gfx::Buffer input = gfx::createBuffer("probe points", GLsizeiptr(points.size() * sizeof(glm::vec2)), points.data());
    gfx::Buffer result = gfx::createBuffer("probe heights", GLsizeiptr(points.size() * sizeof(float)));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, result.id());
    auto shader = [&](const gfx::glsl::WaterUniforms& water) {
        glNamedBufferSubData(uniforms.id(), 0, sizeof water, &water);
        glUseProgram(program.id());
        glProgramUniform1i(program.id(), 0, int(points.size()));
        glDispatchCompute(GLuint((points.size() + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<float> heights(points.size());
        glGetNamedBufferSubData(result.id(), 0, GLsizeiptr(heights.size() * sizeof(float)), heights.data());
        return heights;
    };

    // The bound: per level and axis, 2^-8 of its largest step between neighbouring texels.
    const int n = def.resolution;
    auto steps = [n](std::span<const float> h) {
        double m = 0.0;
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) {
                const float c = h[size_t(z * n + x)];
                const float right = x + 1 < n ? h[size_t(z * n + x + 1)] : 0.0f, down = z + 1 < n ? h[size_t((z + 1) * n + x)] : 0.0f;
                m = std::max({m, double(std::abs(right - c)), double(std::abs(down - c)), double(std::abs(c))});
            }
        return m;
    };
    auto maxAbs = [](std::span<const float> f) {
        double m = 0.0;
        for (float x : f) m = std::max(m, double(std::abs(x)));
        return m;
    };
    double bound = 2.0 * std::ldexp(steps(patch.height()), -8), largest = maxAbs(patch.height());
    for (int L = 1; L < levels.count(); ++L) {
        bound += 2.0 * std::ldexp(steps(levels.height(L)), -8);
        largest = std::max(largest, maxAbs(levels.height(L)));
    }
    bound += 1e-6 * largest;
    auto compare = [&](const std::vector<float>& gpu, size_t& at) {
        double worst = 0.0;
        for (size_t i = 0; i < points.size(); ++i) {
            const double d = std::abs(double(gpu[i]) - double(patch.heightAt(points[i])));
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        return worst;
    };
    double outside = 0.0;  // the waves where the coarse levels show
    for (const glm::vec2& p : points)
        if (patch.fineWeight(p) < 1.0f) outside = std::max(outside, double(std::abs(patch.heightAt(p))));
    size_t at = 0, atShifted = 0;
    const double worst = compare(shader(u), at);
    // The test can fail: level 1 placed one cell off, or the coarse layers left out.
    gfx::glsl::WaterUniforms shifted = u;
    shifted.rippleLevels[0].x += shifted.rippleLevels[0].z;
    const double worstShifted = compare(shader(shifted), atShifted);
    gfx::glsl::WaterUniforms alone = u;
    alone.rippleFade.x = 0.0f;
    const double worstAlone = compare(shader(alone), atShifted);
    INFO("level 1 one cell off: " << worstShifted << " m; level 0 alone: " << worstAlone << " m");
    INFO("largest |shader − heightAt| " << worst << " m at (" << points[at].x - centre.x << ", " << points[at].y - centre.y
                                        << ") from the centre; bound " << bound << "; largest |h| where level 0 fades "
                                        << outside);
    CHECK(outside > 10.0 * bound);
    CHECK(worst <= bound);
    CHECK(worstShifted > 10.0 * bound);
    CHECK(worstAlone > 10.0 * bound);
}
