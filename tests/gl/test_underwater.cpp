// The view from under water and light through thin crests ([Jerlov1976], [Crest], [Atlas2019];
// docs/frame.md): Snell's window's angular radius asin(1/n) from a flat sea seen straight up,
// the window unclipped with the waves' shape in it and the sun at Snell's angle, the exposure
// that takes back the n² gain, light shafts toward the refracted sun, Beer–Lambert extinction
// per channel at Jerlov type I's Kd, the waterline across a half-dipped camera where the near
// plane meets the water, and the backlit crests' turquoise toward the sun.
#include "gfx/gl.h"
#include "gfx/gpu_bindings.h"
#include "gfx/renderer.h"
#include "gfx/shader.h"
#include "platform/platform.h"
#include "support/test_image.h"
#include "support/shader_probe.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>

using namespace ob;
using test::Image;
using test::loadPng;

namespace {

// Jerlov's oceanic type I: Kd (1/m) at 650, 550 and 450 nm, as tabulated ([Jerlov1976] Table
// XXVI; docs/references.md#under-water-light), typed here from the table, not from the shader.
const glm::dvec3 JERLOV_I_KD(0.36, 0.063, 0.019);

// A camera at `eye` looking along `forward` (`up` its screen up), `fovDeg` vertical, near 0.1 m.
gfx::CameraView cameraAt(glm::vec3 eye, glm::vec3 forward, glm::vec3 up, float fovDeg, float aspect) {
    gfx::CameraView camera;
    camera.position = eye;
    camera.view = glm::lookAtRH(eye, eye + forward, up);
    camera.projection = glm::perspectiveRH_NO(glm::radians(fovDeg), aspect, 0.1f, 2000.0f);
    camera.nearM = 0.1f;
    camera.farM = 2000.0f;
    return camera;
}

Image renderFrame(const gfx::RenderDef& def, const gfx::CameraView& camera, const gfx::WaterView& water, glm::ivec2 size) {
    auto platform = platform::createHeadlessPlatform(size);
    const int errorsBefore = gfx::glErrorCount();
    gfx::Renderer renderer(def);
    renderer.render(camera, water, {}, 0.0, size);
    const std::string path = test::tempPath("underwater.png");
    gfx::writeScreenshot(path, size);
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = loadPng(path);
    REQUIRE(img.w == size.x);
    return img;
}

gfx::RenderDef plainDef() {
    gfx::RenderDef def;
    def.antialias = gfx::Antialias::Off;
    def.dither = false;
    return def;
}

float luma(glm::vec3 c) { return 0.299f * c.x + 0.587f * c.y + 0.114f * c.z; }


} // namespace

TEST_CASE("from under a flat sea, looking straight up: Snell's window spans asin(1/1.333) = 48.6°, the reflected deep outside", "[gl][render][underwater]") {
    gfx::requestDebugOutput(true);
    const int side = 240;
    gfx::RenderDef def = plainDef();
    def.fresnel = gfx::Fresnel::Exact;
    def.sun_direction = glm::vec3(0.0f, 1.0f, 0.0f);  // overhead: the window's centre
    def.glitter = 0.0f;
    const float fov = 120.0f;
    const Image img = renderFrame(def, cameraAt({0.0f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, fov, 1.0f), {}, {side, side});

    // Along the middle row, pixel x looks at atan(|x − centre| / (side/2) · tan(fov/2)) from the zenith.
    const auto angleOf = [&](double x) { return glm::degrees(std::atan(std::abs(x - side / 2.0) / (side / 2.0) * std::tan(glm::radians(fov / 2.0)))); };
    const auto pixelAt = [&](double deg) { return int(side / 2.0 + std::tan(glm::radians(deg)) / std::tan(glm::radians(fov / 2.0)) * side / 2.0); };
    const int row = side / 2;
    const auto lumaAt = [&](int x) { return luma(img.mean(x, row - 1, x + 1, row + 2)); };
    // Inside (40°) against outside (56°…58°): the window is the refracted sky, outside it the
    // deep's own light totally reflected — several times darker, blue-green like the water.
    const glm::vec3 inside = img.mean(pixelAt(38.0), row - 2, pixelAt(42.0), row + 3);
    const glm::vec3 outside = img.mean(pixelAt(56.0), row - 2, pixelAt(58.0), row + 3);
    INFO("inside " << inside.x << " " << inside.y << " " << inside.z << ", outside " << outside.x << " " << outside.y << " " << outside.z);
    CHECK(luma(inside) > 3.0f * luma(outside));
    CHECK(outside.z > outside.x);
    CHECK(outside.y > outside.x);
    // The edge: where the row falls half way from the inside to the outside, on both sides.
    const float half = 0.5f * (luma(inside) + luma(outside));
    for (int direction : {-1, 1}) {
        int x = side / 2 + direction * (pixelAt(40.0) - side / 2);
        while (x > 0 && x < side - 1 && lumaAt(x) > half) x += direction;
        const double edge = angleOf(x + 0.5);
        INFO("edge on side " << direction << " at " << edge << "°");
        CHECK(edge == Approx(glm::degrees(std::asin(1.0 / 1.333))).margin(2.5));
    }
}

namespace {

// Looking straight up from 5 m under the sea (120° field of view, `side` px square, screen up
// toward −z) with the sun 40° high toward +z: the picture, and per pixel its angle from the zenith.
struct WindowView {
    static constexpr int side = 200;
    static constexpr double fovDeg = 120.0;
    Image img;
    double zenithDeg(double x, double y) const {
        const double t = std::tan(glm::radians(fovDeg / 2.0)) / (side / 2.0);
        return glm::degrees(std::atan(t * std::hypot(x + 0.5 - side / 2.0, y + 0.5 - side / 2.0)));
    }
};

const double SUN_ELEVATION_DEG = 40.0;

WindowView windowFrom(const gfx::WaterView& water, float shafts = 0.0f) {
    gfx::RenderDef def = plainDef();
    const double e = glm::radians(SUN_ELEVATION_DEG);
    def.sun_direction = glm::vec3(0.0f, float(std::sin(e)), float(std::cos(e)));
    def.light_shafts = shafts;
    WindowView v;
    v.img = renderFrame(def, cameraAt({0.0f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, float(WindowView::fovDeg), 1.0f), water,
                        {WindowView::side, WindowView::side});
    return v;
}

// Two crossing swells, 12 m and 7 m long, slopes ka = 0.16 and 0.13.
gfx::WaterView twoSwells() {
    gfx::WaterView water;
    const float k1 = 2.0f * float(M_PI) / 12.0f, k2 = 2.0f * float(M_PI) / 7.0f;
    water.gerstner = {glm::vec4(k1 * 0.8f, k1 * 0.6f, 0.3f, 0.0f), glm::vec4(-k2 * 0.5f, k2 * 0.866f, 0.15f, 1.0f)};
    return water;
}

struct WindowStats {
    double clipped = 0.0;   // share of pixels with a channel at 255
    double lumaStd = 0.0;   // standard deviation of the luma (0..255)
    double roughness = 0.0; // mean |luma difference| between pixels 2 apart (0..255)
    int n = 0;
};

// Over the pixels from `minDeg` to `maxDeg` off the zenith.
WindowStats windowStats(const WindowView& v, double minDeg, double maxDeg) {
    WindowStats s;
    double sum = 0.0, sum2 = 0.0, rough = 0.0;
    const auto lumaAt = [&](int x, int y) {
        const unsigned char* p = &v.img.rgb[size_t((y * v.img.w + x) * 3)];
        return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    };
    for (int y = 0; y < v.img.h - 2; ++y)
        for (int x = 0; x < v.img.w - 2; ++x) {
            if (v.zenithDeg(x, y) < minDeg || v.zenithDeg(x, y) > maxDeg) continue;
            const unsigned char* p = &v.img.rgb[size_t((y * v.img.w + x) * 3)];
            if (std::max({p[0], p[1], p[2]}) == 255) s.clipped += 1.0;
            const double l = lumaAt(x, y);
            sum += l, sum2 += l * l;
            rough += 0.5 * (std::abs(l - lumaAt(x + 2, y)) + std::abs(l - lumaAt(x, y + 2)));
            ++s.n;
        }
    s.clipped /= s.n;
    s.lumaStd = std::sqrt(std::max(sum2 / s.n - (sum / s.n) * (sum / s.n), 0.0));
    s.roughness = rough / s.n;
    return s;
}

} // namespace

TEST_CASE("Snell's window from below: not clipped, the waves' shape inside it, the sun where Snell puts it", "[gl][render][underwater]") {
    gfx::requestDebugOutput(true);
    const WindowView flat = windowFrom({}), waves = windowFrom(twoSwells());
    const WindowStats f = windowStats(flat, 0.0, 45.0), w = windowStats(waves, 0.0, 45.0);
    INFO("flat: clipped " << f.clipped << ", luma std " << f.lumaStd << ", roughness " << f.roughness);
    INFO("waves: clipped " << w.clipped << ", luma std " << w.lumaStd << ", roughness " << w.roughness);
    CHECK(f.clipped < 0.02);
    CHECK(w.clipped < 0.02);
    // The waves' shape: the window's sky, the sun's glare and the rim bent by the slopes.
    CHECK(w.lumaStd > 1.5 * f.lumaStd);
    CHECK(w.roughness > 1.5 * f.roughness);
    // Past the critical angle (55°–60°) the swells show too: the window's edge bent into the
    // ring and the mirrored deep, brighter where a slope turns the mirrored ray toward the
    // horizontal; a flat sea's ring is uniform.
    const WindowStats fr = windowStats(flat, 55.0, 60.0), wr = windowStats(waves, 55.0, 60.0);
    INFO("reflected ring: luma std flat " << fr.lumaStd << ", waves " << wr.lumaStd);
    CHECK(wr.lumaStd > 2.0 * fr.lumaStd + 1.0);

    // The sun's spot: the centroid of the flat window's brightest pixels (luma within 5 levels of
    // the top) lies at the refracted sun, sin θw = sin θair / n, toward +z (down the screen).
    double top = 0.0;
    for (int y = 0; y < flat.img.h; ++y)
        for (int x = 0; x < flat.img.w; ++x) top = std::max(top, double(luma(flat.img.mean(x, y, x + 1, y + 1))) * 255.0);
    double cx = 0.0, cy = 0.0, count = 0.0;
    for (int y = 0; y < flat.img.h; ++y)
        for (int x = 0; x < flat.img.w; ++x)
            if (double(luma(flat.img.mean(x, y, x + 1, y + 1))) * 255.0 > top - 5.0) cx += x, cy += y, count += 1.0;
    cx /= count, cy /= count;
    const double expected = glm::degrees(std::asin(std::cos(glm::radians(SUN_ELEVATION_DEG)) / 1.333));
    INFO("sun spot at (" << cx << ", " << cy << "), " << flat.zenithDeg(cx, cy) << "° from the zenith; Snell " << expected << "°");
    CHECK(flat.zenithDeg(cx, cy) == Approx(expected).margin(3.0));
    CHECK(std::abs(cx + 0.5 - WindowView::side / 2.0) < 3.0);
    CHECK(cy > WindowView::side / 2.0);
}

TEST_CASE("just under a flat sea the window's zenith is the sky's zenith seen above water (exposure 1/n^2)", "[gl][render][underwater]") {
    gfx::requestDebugOutput(true);
    // Radiance entering water grows by n² (the same flux in a solid angle n² narrower) times the
    // transmittance 1 − F(0) = 0.98, and 0.3 m of water keeps exp(−0.019·0.3) of the blue: the
    // exposure under water (1/n²) leaves 0.97 of the sky's blue, 2 levels of 255 at most on the
    // sky's zenith (n² more would be 13 levels brighter).
    const glm::ivec2 size(64, 64);
    gfx::RenderDef def = plainDef();
    const double e = glm::radians(SUN_ELEVATION_DEG);
    def.sun_direction = glm::vec3(0.0f, float(std::sin(e)), float(std::cos(e)));
    def.light_shafts = 0.0f;
    const auto zenith = [&](float y) {
        const Image img = renderFrame(def, cameraAt({0.0f, y, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 20.0f, 1.0f), {}, size);
        return img.mean(size.x / 2 - 4, size.y / 2 - 4, size.x / 2 + 4, size.y / 2 + 4) * 255.0f;
    };
    const glm::vec3 sky = zenith(0.3f), window = zenith(-0.3f);
    INFO("blue of the sky's zenith " << sky.z << ", of the window's " << window.z);
    CHECK(window.z <= sky.z + 1.0f);
    CHECK(window.z > sky.z - 4.0f);
}

TEST_CASE("light shafts brighten the water looking toward the refracted sun, far less looking away", "[gl][render][underwater]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(96, 64);
    // The sun 40° high toward +z; from 8 m down, pitched 30° up toward it and away from it.
    const double e = glm::radians(SUN_ELEVATION_DEG);
    const glm::vec3 sun(0.0f, float(std::sin(e)), float(std::cos(e)));
    const auto frame = [&](float z, float shafts) {
        gfx::RenderDef def = plainDef();
        def.sun_direction = sun;
        def.light_shafts = shafts;
        const glm::vec3 forward = glm::normalize(glm::vec3(0.0f, 0.577f, z));
        return renderFrame(def, cameraAt({0.0f, -8.0f, 0.0f}, forward, {0.0f, 1.0f, 0.0f}, 50.0f, 1.5f), {}, size);
    };
    // What the shafts add over the lower half of the frame (the water under the surface).
    const auto added = [&](float z) { return luma(frame(z, 1.0f).mean(0, size.y / 2, size.x, size.y) - frame(z, 0.0f).mean(0, size.y / 2, size.x, size.y)); };
    const float toward = added(1.0f), away = added(-1.0f);
    INFO("added luma toward the sun " << toward << ", away " << away);
    CHECK(toward > 0.02f);  // 5 levels of 255
    CHECK(toward > 3.0f * std::max(away, 0.002f));
}

TEST_CASE("under water an image fades per channel as exp(−Kd·d) toward the water's own light (Jerlov type I)", "[gl][render][underwater]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({16, 16});
    gfx::Program program = test::loadShaderProbe("underwater_probe.comp", "underwater_probe_shaders");
    // The frame's water colour, a high sun and an eye at the surface, as the renderer sets them.
    gfx::glsl::FrameUniforms frame{};
    frame.sunDirectionFresnel = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    frame.waterColorExposure = glm::vec4(0.015f, 0.09f, 0.13f, 1.0f);
    gfx::Buffer uniforms = gfx::createBuffer("probe frame", sizeof frame, &frame);
    glBindBufferBase(GL_UNIFORM_BUFFER, gfx::glsl::FRAME_BLOCK, uniforms.id());
    const std::vector<float> distances = {0.0f, 2.0f, 10.0f, 1e5f};
    gfx::Buffer input = gfx::createBuffer("probe distances", GLsizeiptr(distances.size() * sizeof(float)), distances.data());
    gfx::Buffer result = gfx::createBuffer("probe result", GLsizeiptr(distances.size() * 2 * sizeof(glm::vec4)));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, result.id());
    glUseProgram(program.id());
    glProgramUniform1i(program.id(), 0, int(distances.size()));
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> r(distances.size() * 2);  // per distance: transmittance, a white object's colour
    glGetNamedBufferSubData(result.id(), 0, GLsizeiptr(r.size() * sizeof(glm::vec4)), r.data());

    const glm::vec3 water = glm::vec3(r[7]);  // 100 km: nothing but the water's own light
    CHECK(glm::vec3(r[1]) == glm::vec3(1.0f));  // at the eye: the object as it is
    for (size_t i : {size_t(1), size_t(2)}) {
        const double d = distances[i];
        for (int c = 0; c < 3; ++c) {
            INFO("distance " << d << " m, channel " << c);
            const double expected = std::exp(-JERLOV_I_KD[c] * d);
            CHECK(r[2 * i][c] == Approx(expected).epsilon(1e-4));
            // The white object's colour lies that share of the way from the water's light to white.
            CHECK((r[2 * i + 1][c] - water[c]) / (1.0f - water[c]) == Approx(expected).epsilon(1e-3));
        }
    }
    // Red goes first: after 10 m 3 % of it is left, 83 % of the blue.
    CHECK(r[4].x < 0.03f);
    CHECK(r[4].z > 0.8f);
}

TEST_CASE("a half-dipped camera: below the waterline at the near plane the under-water view, above it the sky", "[gl][render][underwater]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    const gfx::RenderDef def = plainDef();
    const auto level = [&](float y) { return renderFrame(def, cameraAt({0.0f, y, 0.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 0.0f}, 60.0f, 16.0f / 9.0f), {}, size); };
    const Image above = level(1.0f), below = level(-1.0f);
    // References: the sky's top rows from above, the under-water view's bottom rows from below.
    const glm::vec3 sky = above.mean(0, 0, size.x, 40), deep = below.mean(0, size.y - 40, size.x, size.y);
    REQUIRE(glm::length(sky - deep) > 0.3f);
    // The near plane (0.1 m ahead, ±0.1·tan 30° high) meets the water at ndc y = −eye / (0.1·tan 30°):
    // the horizon line for an eye at the surface, a fixed row above or below it for an eye
    // 2 cm under or over it.
    for (float eye : {0.0f, -0.02f, 0.02f}) {
        const Image img = level(eye);
        const double ndc = -eye / (0.1 * std::tan(glm::radians(30.0)));
        const double expected = (1.0 - ndc) / 2.0 * size.y;  // rows top-down
        int boundary = 0;
        for (int y = 0; y < size.y; ++y) {
            const glm::vec3 c = img.mean(0, y, size.x, y + 1);
            if (glm::length(c - deep) < glm::length(c - sky)) break;
            boundary = y + 1;
        }
        INFO("eye at " << eye << " m: the under-water view begins at row " << boundary << ", expected " << expected);
        CHECK(std::abs(boundary - expected) < 3.0);
        // The upper part is sky (its top as seen from above), the lower part the deep.
        CHECK(glm::length(img.mean(0, 0, size.x, 30) - above.mean(0, 0, size.x, 30)) < 0.05f);
        CHECK(glm::length(img.mean(0, size.y - 30, size.x, size.y) - below.mean(0, size.y - 30, size.x, size.y)) < 0.1f);
    }
}

TEST_CASE("thin crests toward the sun glow turquoise, away from the sun or switched off they do not", "[gl][render][water]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(240, 135);
    // One long swell along z (20 m, 0.8 m high) seen from 2.5 m up, looking along −z.
    gfx::WaterView water;
    const float k = 2.0f * float(M_PI) / 20.0f;
    water.gerstner = {glm::vec4(0.0f, -k, 0.8f, 0.0f)};
    const gfx::CameraView camera = cameraAt({0.0f, 2.5f, 0.0f}, glm::normalize(glm::vec3(0.0f, -0.15f, -1.0f)), {0.0f, 1.0f, 0.0f}, 60.0f, 16.0f / 9.0f);
    const auto frame = [&](glm::vec3 sun, float subsurface) {
        gfx::RenderDef def = plainDef();
        def.sun_direction = sun;
        def.subsurface = subsurface;
        def.reflections = false;
        return renderFrame(def, camera, water, size);
    };
    // What the term adds over the sea (the lower half), per channel.
    const auto added = [&](glm::vec3 sun) {
        const Image on = frame(sun, 1.0f), off = frame(sun, 0.0f);
        return on.mean(0, size.y / 2 + 4, size.x, size.y) - off.mean(0, size.y / 2 + 4, size.x, size.y);
    };
    const glm::vec3 toward = added(glm::normalize(glm::vec3(0.0f, 0.2f, -1.0f)));
    const glm::vec3 away = added(glm::normalize(glm::vec3(0.0f, 0.2f, 1.0f)));
    INFO("added toward the sun " << toward.x << " " << toward.y << " " << toward.z << ", away " << away.x << " " << away.y << " " << away.z);
    CHECK(toward.y > 0.006f);            // visible: 1.5 levels of 255 on the mean of the sea (0.013 measured)
    CHECK(toward.y > 5.0f * std::max(away.y, 0.001f));
    CHECK(toward.y > 2.0f * toward.x);   // turquoise: green and blue, little red
    CHECK(toward.z > 2.0f * toward.x);
    CHECK(toward.y < 0.15f);             // and subtle
}
