// Projected grid coverage (docs/references.md#projected-grid, [Lee2007] §3.4): the water pass covers every pixel whose
// view ray points below the horizon, for 2,000 random cameras (0.5–500 m above the local crest,
// pitch −89° to +10°, roll ±35°, any heading, fov 30–100°) over the roughest seas validation
// accepts (wind 60 m/s, choppiness 10, Gerstner steepness at its limits, a ripple patch under
// the camera). Coverage is read from the default framebuffer's depth (antialiasing off, so the
// passes draw there): the water writes depth, the sky does not.
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/gpu/ocean_textures.h"
#include "ocean/spectrum.h"
#include "platform/platform.h"
#include "world/camera.h"
#include "core/clock.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "water/composite_water.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <sstream>

using namespace ob;

namespace {

// 64×36 keeps 2,000 frames within seconds under llvmpipe; each pixel is ~1.7° at fov 60.
constexpr glm::ivec2 SIZE(64, 36);
constexpr int RIPPLE_CELLS = 128;
constexpr float RIPPLE_CELL = 0.25f;   // m: a 32 m patch under the camera
constexpr float LOCAL_RADIUS = 10.0f;  // m: the crest the camera keeps clear of is the highest water within this of its footprint

// One sea: the FFT ocean (CPU maps → textures), its Gerstner waves and a ripple patch.
struct Sea {
    ocean::OceanDef def;
    std::vector<ocean::GerstnerWave> waves;
    float rippleAmplitude = 0.0f;  // m
    double time = 0.0;             // s
    std::unique_ptr<ocean::OceanFftCpu> fft;
    std::unique_ptr<ocean::OceanTextures> textures;
    std::unique_ptr<water::CompositeWater> water;  // the CPU surface: where the crests are
    std::vector<float> ripples;

    void build() {
        fft = std::make_unique<ocean::OceanFftCpu>(def);
        fft->update(time);
        textures = std::make_unique<ocean::OceanTextures>(def.resolution, def.cascades);
        textures->upload(*fft);
        textures->generateMipmaps();
        water = std::make_unique<water::CompositeWater>(waves, def.gravity, fft.get());
        water->update(time);
        ripples.resize(size_t(RIPPLE_CELLS) * RIPPLE_CELLS);
        for (int j = 0; j < RIPPLE_CELLS; ++j)
            for (int i = 0; i < RIPPLE_CELLS; ++i)
                ripples[size_t(j * RIPPLE_CELLS + i)] = rippleAmplitude * std::sin(0.4f * float(i)) * std::cos(0.27f * float(j) + 0.3f);
    }

    // What the render phase hands the renderer, with the ripple patch centred under `foot`.
    gfx::WaterView view(glm::vec2 foot, bool withFftBounds = true) const {
        gfx::WaterView v;
        v.displacement = &textures->displacement();
        v.slopes = &textures->slopes();
        v.cascades = def.cascades;
        v.resolution = def.resolution;
        for (int c = 0; c < def.cascades; ++c) v.cascadeSize[size_t(c)] = float(ocean::cascadePatchSize(def, c));
        v.lambda = -def.choppiness;
        v.gravity = def.gravity;
        for (const ocean::GerstnerWave& w : waves) v.gerstner.emplace_back(w.kx, w.kz, w.amplitude, w.phase);
        v.ripples = ripples.data();
        v.rippleCells = RIPPLE_CELLS;
        v.rippleCellSize = RIPPLE_CELL;
        v.rippleOrigin = foot - glm::vec2(0.5f * RIPPLE_CELLS * RIPPLE_CELL);
        if (withFftBounds) {
            const ocean::DisplacementBounds b = fft->displacementBounds();
            v.fftBounds = {b.up, b.down, b.horizontal};
        }
        return v;
    }

    // The highest water that can lie within LOCAL_RADIUS of `foot`: displaced heights of rest
    // points on a 64² lattice over every rest point that can move there, plus the ripples' top.
    float localCrest(glm::vec2 foot) const {
        float sumA = 0.0f;
        for (const ocean::GerstnerWave& w : waves) sumA += w.amplitude;
        const float reach = LOCAL_RADIUS + sumA + fft->displacementBounds().horizontal;
        float crest = -1e30f;
        const int n = 64;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                glm::vec2 rest = foot + reach * (glm::vec2(i, j) * (2.0f / n) - 1.0f);
                glm::vec3 p = water->displace(rest.x, rest.y);
                if (glm::length(glm::vec2(p.x, p.z) - foot) <= reach) crest = std::max(crest, p.y);
            }
        return crest + rippleAmplitude;
    }
};

// The roughest seas the scene validation accepts, and a plain rough one.
Sea stormSwell() {  // wind and choppiness at their maxima; spectrum swell scaled to Σ k·a = 0.99
    Sea s;
    s.def.wind_speed = 60.0f;
    s.def.choppiness = 10.0f;
    s.def.resolution = 64;
    s.def.cascades = 2;
    s.def.wind_direction = {1.0f, 0.6f};
    ocean::GerstnerDef g;
    g.count = 8;
    g.seed = 7;
    s.waves = ocean::generateWaves(g, s.def);
    const double scale = 0.99 / ocean::steepnessSum(s.waves);
    for (ocean::GerstnerWave& w : s.waves) w.amplitude *= float(scale);
    s.rippleAmplitude = 1.5f;
    s.time = 41.7;
    return s;
}

Sea steepTrochoids() {  // every wave at k·a = 0.95 (each < 1 is accepted), crossing directions
    Sea s;
    s.def.wind_speed = 60.0f;
    s.def.choppiness = 10.0f;
    s.def.resolution = 64;
    s.def.cascades = 1;
    s.def.seed = 5;
    const float lengths[4] = {300.0f, 170.0f, 90.0f, 45.0f}, angles[4] = {0.3f, 1.4f, -0.8f, 2.6f};
    for (int m = 0; m < 4; ++m) {
        const float k = 6.2831853f / lengths[m];
        s.waves.push_back({k * std::cos(angles[m]), k * std::sin(angles[m]), 0.95f / k, 0.7f * float(m)});
    }
    s.rippleAmplitude = 0.8f;
    s.time = 12.3;
    return s;
}

Sea roughSea() {  // the showcase's sea with the wind at 30 m/s
    Sea s;
    s.def.wind_speed = 30.0f;
    s.def.choppiness = 1.2f;
    s.def.resolution = 64;
    s.def.cascades = 2;
    s.def.wind_direction = {1.0f, 0.6f};
    ocean::GerstnerDef g;
    g.count = 8;
    g.seed = 7;
    s.waves = ocean::generateWaves(g, s.def);
    s.rippleAmplitude = 0.3f;
    s.time = 28.0;
    return s;
}

struct Shot {
    gfx::CameraView camera;
    std::string text;  // for failure messages
};

// A random camera over `sea` as the test's header describes.
Shot randomCamera(std::mt19937& rng, const Sea& sea) {
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    const glm::vec2 foot(2000.0f * uni(rng) - 1000.0f, 2000.0f * uni(rng) - 1000.0f);
    const float above = 0.5f * std::pow(1000.0f, uni(rng));  // 0.5–500 m, as many low as high
    const float heading = 6.2831853f * uni(rng), pitch = glm::radians(-89.0f + 99.0f * uni(rng));
    const float roll = glm::radians(-35.0f + 70.0f * uni(rng)), fov = 30.0f + 70.0f * uni(rng);
    const float crest = sea.localCrest(foot);
    Shot s;
    gfx::CameraView& c = s.camera;
    c.position = glm::vec3(foot.x, crest + above, foot.y);
    glm::vec3 forward(std::sin(heading) * std::cos(pitch), std::sin(pitch), std::cos(heading) * std::cos(pitch));
    glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    glm::vec3 up = std::cos(roll) * glm::cross(right, forward) - std::sin(roll) * right;
    c.view = glm::lookAtRH(c.position, c.position + forward, up);
    c.projection = glm::perspectiveRH_NO(glm::radians(fov), float(SIZE.x) / float(SIZE.y), c.nearM, c.farM);
    c.waterHeight = crest - above;  // above the water: the ordinary look
    std::ostringstream text;
    text << "eye (" << foot.x << ", " << c.position.y << ", " << foot.y << "), " << above << " m above the crest " << crest
         << ", heading " << glm::degrees(heading) << ", pitch " << glm::degrees(pitch) << ", roll " << glm::degrees(roll)
         << ", fov " << fov;
    s.text = text.str();
    return s;
}

// Pixels whose view ray points below the horizon by at least a pixel (all four outer corners of
// the 3×3 block around the pixel look down: the horizon is a straight line on screen) that the
// water did not cover (depth still at the far plane); `upward`: above the horizon (an eye under
// the water, which sees the surface's underside there).
int holesBelowHorizon(const gfx::CameraView& camera, glm::ivec2 size = SIZE, bool upward = false) {
    std::vector<float> depth(size_t(size.x) * size_t(size.y));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    const glm::dmat4 inv = glm::inverse(glm::dmat4(camera.projection * camera.view));
    const auto looksDown = [&](int px, int py) {
        const glm::dvec2 ndc(2.0 * px / size.x - 1.0, 2.0 * py / size.y - 1.0);
        const glm::dvec4 n = inv * glm::dvec4(ndc, -1.0, 1.0), f = inv * glm::dvec4(ndc, 1.0, 1.0);
        return (f.y / f.w < n.y / n.w) != upward;
    };
    int holes = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            if (looksDown(x - 1, y - 1) && looksDown(x + 2, y - 1) && looksDown(x - 1, y + 2) && looksDown(x + 2, y + 2) &&
                depth[size_t(y * size.x + x)] >= 1.0f)
                ++holes;
    return holes;
}

// Renders `count` random cameras over sea; returns the number that showed a hole.
int camerasWithHoles(gfx::Renderer& renderer, const Sea& sea, int count, uint32_t seed, bool withFftBounds, std::string& first) {
    std::mt19937 rng(seed);
    int failed = 0;
    for (int i = 0; i < count; ++i) {
        const Shot shot = randomCamera(rng, sea);
        const glm::vec2 foot(shot.camera.position.x, shot.camera.position.z);
        renderer.render(shot.camera, sea.view(foot, withFftBounds), {}, sea.time, SIZE);
        const int holes = holesBelowHorizon(shot.camera);
        if (holes > 0 && failed++ == 0) first = "camera " + std::to_string(i) + ": " + std::to_string(holes) + " px open; " + shot.text;
    }
    return failed;
}

gfx::RenderDef coverageRenderDef() {
    gfx::RenderDef def;
    def.reflections = false;  // coverage does not depend on them; the frames are cheaper
    def.refractions = false;
    def.antialias = gfx::Antialias::Off;    // drawn straight into the default framebuffer, whose depth is read
    return def;
}

} // namespace

TEST_CASE("the water covers every pixel below the horizon for 2,000 random cameras over the roughest seas", "[gl][grid]") {
    auto platform = platform::createHeadlessPlatform(SIZE);
    gfx::Renderer renderer(coverageRenderDef());
    struct Case {
        const char* name;
        Sea sea;
        int cameras;
    };
    Case cases[] = {{"storm, spectrum swell at Σ k·a = 0.99", stormSwell(), 800},
                    {"storm, four trochoids at k·a = 0.95", steepTrochoids(), 600},
                    {"rough sea, wind 30 m/s", roughSea(), 600}};
    uint32_t seed = 1;
    for (Case& c : cases) {
        c.sea.build();
        std::string first;
        const int failed = camerasWithHoles(renderer, c.sea, c.cameras, seed++, true, first);
        INFO(c.name << ": " << first);
        CHECK(failed == 0);
    }
}

TEST_CASE("the coverage check sees the hole when the grid ignores the FFT's displacement", "[gl][grid]") {
    // The same check, with the FFT bounds withheld from the renderer: low cameras over a
    // 30 m/s sea (FFT layer only) then see sky through the grid's near edge, as the showcase did.
    auto platform = platform::createHeadlessPlatform(SIZE);
    gfx::Renderer renderer(coverageRenderDef());
    Sea sea = roughSea();
    sea.waves.clear();
    sea.build();
    std::string first;
    CHECK(camerasWithHoles(renderer, sea, 200, 99u, false, first) > 0);
}

TEST_CASE("the showcase's frame 1680, where a wedge of sky once opened under the camera, is water below the horizon",
          "[gl][grid][showcase][long]") {
    // `oceanbox run config/scenes/default.toml --frames 1680` (one fixed step per frame): the
    // followed ship rides a 4.5 m crest and the camera, 6.5 m above it, looked past the grid's
    // near edge. Every frame's coverage is read, not only the last.
    const glm::ivec2 size(160, 90);
    auto platform = platform::createHeadlessPlatform(size);
    // Antialiasing off: the frame is drawn straight into the default framebuffer, whose depth is read.
    game::Sandbox sandbox(game::loadScene(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/default.toml", {"render.antialias=off"}));
    sandbox.attachPlatform(*platform, false);
    FixedStepClock clock(1.0 / sandbox.scene().sim.step_hz);
    int framesWithHoles = 0;
    std::string first;
    for (int f = 0; f < 1680; ++f) {
        sandbox.frame(clock.now());
        if (f % 8 != 7) continue;  // every 8th frame, and the last
        const gfx::CameraView camera = game::cameraView(sandbox.world(), size);
        if (const int holes = holesBelowHorizon(camera, size); holes > 0 && framesWithHoles++ == 0)
            first = "frame " + std::to_string(f + 1) + ": " + std::to_string(holes) + " px open";
    }
    INFO(first);
    CHECK(framesWithHoles == 0);
}

TEST_CASE("seen from under the water, the surface covers every pixel above the horizon, looking up to 89 degrees", "[gl][grid][underwater]") {
    // Cameras 0.5-200 m under the lowest trough the layers can dig, pitched from 10 degrees down
    // to 89 up, any heading, roll and field of view: every upward ray meets the surface's
    // underside (the grid covers the view from below too, and no face is culled).
    auto platform = platform::createHeadlessPlatform(SIZE);
    gfx::Renderer renderer(coverageRenderDef());
    Sea sea = roughSea();
    sea.build();
    float trough = sea.fft->displacementBounds().down + sea.rippleAmplitude;
    for (const ocean::GerstnerWave& w : sea.waves) trough += w.amplitude;
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    int failed = 0;
    std::string first;
    for (int i = 0; i < 300; ++i) {
        const glm::vec2 foot(2000.0f * uni(rng) - 1000.0f, 2000.0f * uni(rng) - 1000.0f);
        const float below = 0.5f * std::pow(400.0f, uni(rng));
        const float heading = 6.2831853f * uni(rng), pitch = glm::radians(-10.0f + 99.0f * uni(rng));
        const float roll = glm::radians(-35.0f + 70.0f * uni(rng)), fov = 30.0f + 70.0f * uni(rng);
        gfx::CameraView c;
        c.position = glm::vec3(foot.x, -trough - below, foot.y);
        const glm::vec3 forward(std::sin(heading) * std::cos(pitch), std::sin(pitch), std::cos(heading) * std::cos(pitch));
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
        const glm::vec3 up = std::cos(roll) * glm::cross(right, forward) - std::sin(roll) * right;
        c.view = glm::lookAtRH(c.position, c.position + forward, up);
        c.projection = glm::perspectiveRH_NO(glm::radians(fov), float(SIZE.x) / float(SIZE.y), c.nearM, c.farM);
        c.waterHeight = 0.0f;
        renderer.render(c, sea.view(foot), {}, sea.time, SIZE);
        const int holes = holesBelowHorizon(c, SIZE, true);
        if (holes > 0 && failed++ == 0)
            first = "camera " + std::to_string(i) + ": " + std::to_string(holes) + " px open, " + std::to_string(below) + " m under the trough, pitch " +
                    std::to_string(glm::degrees(pitch));
    }
    INFO(first);
    CHECK(failed == 0);
}
