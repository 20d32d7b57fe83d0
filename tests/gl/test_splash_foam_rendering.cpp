// Splash drops and persistent foam on screen (docs/splash_foam.md §6): the cannon scene
// rendered headless; the hit is located from the simulation (the first emitted drops), and
// screen regions are compared before and after it, and against runs with the drawing off.
#include "foam/foam_map.h"
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "splash/splash_particles.h"
#include "sim/splash_foam_system.h"
#include "support/test_image.h"

#include <catch2/catch.hpp>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <algorithm>
#include <optional>

using namespace ob;
using test::Image;

namespace {

const glm::ivec2 SIZE(320, 180);

// The default framebuffer as an RGB8 image, rows top-down.
Image readFrame() {
    Image img;
    img.w = SIZE.x;
    img.h = SIZE.y;
    std::vector<unsigned char> pixels(size_t(SIZE.x) * size_t(SIZE.y) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glFinish();
    glReadPixels(0, 0, SIZE.x, SIZE.y, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    img.rgb.resize(pixels.size());
    const size_t stride = size_t(SIZE.x) * 3;
    for (int y = 0; y < SIZE.y; ++y) std::memcpy(&img.rgb[stride * size_t(y)], &pixels[stride * size_t(SIZE.y - 1 - y)], stride);
    return img;
}

// Where a world point lands on screen (px, top-down rows), from the scene's camera.
glm::vec2 screenOf(game::Sandbox& sandbox, glm::vec3 p) {
    const gfx::CameraView camera = game::cameraView(sandbox.world(), SIZE);
    const glm::vec4 clip = camera.projection * camera.view * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x * 0.5f + 0.5f) * float(SIZE.x), (0.5f - ndc.y * 0.5f) * float(SIZE.y));
}

float luma(const Image& img, int x, int y) {
    const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
    return (0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]) / 255.0f;
}

// The cannon scene's first ball. Steps before the hit only simulate; from a few frames before
// it every frame is drawn until the hit (the first emitted drops) is seen; after it only the
// frames asked for (counted from the hit) are drawn, the others only simulated (drawing feeds
// nothing back into the simulation).
struct CannonRun {
    std::optional<Image> before;               // the frame before the first drops
    std::vector<std::pair<int, Image>> after;  // (frames after the hit, image)
    glm::vec3 hit{0.0f};                       // the mean launch point of the first drops (world m)
    glm::vec2 hitScreen{0.0f};                 // its pixel (top-down rows)
    int dropsAtFirst = 0;
    float foamAtHit = 0.0f;                    // the foam map's coverage there at the last frame asked for
    bool errorFree = false;
};

CannonRun runCannon(const std::vector<std::string>& overrides, const std::vector<int>& framesAfterHit) {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform(SIZE);
    const int errorsBefore = gfx::glErrorCount();
    std::vector<std::string> settings = {"objects[0].rate=0.1"};  // one ball in the first 10 s
    settings.insert(settings.end(), overrides.begin(), overrides.end());
    game::Sandbox sandbox(game::loadScene("config/scenes/cannon.toml", settings));
    sandbox.attachPlatform(*platform, false);
    const double h = sandbox.schedule().stepSeconds();
    // The first ball lands about 1.6 s after it is fired at t = 0 (9 m/s at 35° from 4 m up).
    const int quiet = int(1.3 / h);
    for (int s = 0; s < quiet; ++s) sandbox.step();
    CannonRun run;
    std::optional<Image> previous;
    int hitStep = -1;
    double now = 0.0;  // the clock of the last drawn frame: each frame then runs exactly one step
    const int last = *std::max_element(framesAfterHit.begin(), framesAfterHit.end());
    for (int s = quiet; s < quiet + 600; ++s) {
        const int k = hitStep < 0 ? -1 : s - hitStep;
        const bool draw = hitStep < 0 || std::find(framesAfterHit.begin(), framesAfterHit.end(), k) != framesAfterHit.end();
        if (draw) sandbox.frame(now += h);
        else sandbox.step();
        const splash::SplashParticles* drops = game::splashParticles(sandbox.world());
        REQUIRE(drops);
        if (hitStep < 0 && drops->stats().emitted > 0) {
            hitStep = s;
            run.before = previous;
            run.dropsAtFirst = drops->size();
            glm::vec3 sum(0.0f);
            for (int i = 0; i < drops->size(); ++i) sum += glm::vec3(drops->x()[size_t(i)], drops->y()[size_t(i)], drops->z()[size_t(i)]);
            run.hit = sum / float(drops->size());
            run.hitScreen = screenOf(sandbox, run.hit);
            if (std::find(framesAfterHit.begin(), framesAfterHit.end(), 0) != framesAfterHit.end()) run.after.emplace_back(0, readFrame());
        } else if (hitStep < 0) {
            previous = readFrame();
        } else if (draw) {
            run.after.emplace_back(k, readFrame());
            if (const foam::FoamMap* foam = game::foamMap(sandbox.world())) run.foamAtHit = foam->sample(run.hit.x, run.hit.z);
            if (k >= last) break;
        }
    }
    run.errorFree = gfx::glErrorCount() == errorsBefore;
    return run;
}

// Alpha-weighted centroid (px, bottom-up) and total alpha of a target's colour texture.
std::pair<glm::vec2, float> alphaCentroid(const gfx::Texture& texture, glm::ivec2 size) {
    std::vector<glm::vec4> texels(size_t(size.x) * size_t(size.y));
    glFinish();
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
    glm::vec2 centroid(0.0f);
    float total = 0.0f;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const float a = texels[size_t(y * size.x + x)].w;
            centroid += a * glm::vec2(float(x) + 0.5f, float(y) + 0.5f);
            total += a;
        }
    return {total > 0.0f ? centroid / total : centroid, total};
}

const Image& imageAt(const CannonRun& run, int k) {
    for (const auto& [frames, img] : run.after)
        if (frames == k) return img;
    FAIL("no image " << k << " frames after the hit");
    return run.after.front().second;
}

} // namespace

TEST_CASE("a cannonball's splash: 20 frames after the hit bright drops stand over the hit point, absent before it and with the drawing off",
          "[gl][render][splash]") {
    const CannonRun on = runCannon({}, {20});
    REQUIRE(on.before);
    REQUIRE(on.dropsAtFirst > 100);
    CHECK(on.errorFree);
    const CannonRun off = runCannon({"render.splash_drops=false"}, {20});
    CHECK(off.hitScreen == on.hitScreen);  // the same simulation
    const Image& drops = imageAt(on, 20);
    const Image& none = imageAt(off, 20);
    // The crown rises from the hit point: the region from 40 px above it to 4 px below it.
    const int x0 = std::max(int(on.hitScreen.x) - 30, 0), x1 = std::min(int(on.hitScreen.x) + 30, SIZE.x);
    const int y0 = std::max(int(on.hitScreen.y) - 40, 0), y1 = std::min(int(on.hitScreen.y) + 4, SIZE.y);
    int newBright = 0, dropPixels = 0, brightBefore = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const float l = luma(drops, x, y);
            newBright += l > 0.7f && l > luma(*on.before, x, y) + 0.15f;
            dropPixels += l > luma(none, x, y) + 0.1f;
            brightBefore += luma(*on.before, x, y) > 0.7f;
        }
    INFO("hit at screen " << on.hitScreen.x << ", " << on.hitScreen.y << "; bright new pixels " << newBright << ", brighter than without drops "
                          << dropPixels << ", bright before the hit " << brightBefore);
    CHECK(newBright > 40);
    CHECK(dropPixels > 40);
    CHECK(brightBefore < newBright / 4);
}

TEST_CASE("foam at a cannonball's hit: 1 s after it the water there is brighter than with [foam] off, and at 5 s still brighter but "
          "fainter than at 1 s",
          "[gl][render][foam]") {
    // Drops not drawn: the region shows the water alone. No current layer: the water the ball
    // pushes as it plunges carries its foam off the spot within seconds (docs/currents.md).
    const CannonRun on = runCannon({"render.splash_drops=false", "currents.enabled=false"}, {60, 300});
    const CannonRun off = runCannon({"render.splash_drops=false", "foam.enabled=false", "currents.enabled=false"}, {60, 300});
    CHECK(on.errorFree);
    CHECK(off.errorFree);
    REQUIRE(on.hitScreen == off.hitScreen);
    // A box on the water around the hit point (16 × 8 px, about 1.2 m × 1.2 m there).
    const auto brightness = [&](const Image& img) {
        const int x = int(on.hitScreen.x), y = int(on.hitScreen.y);
        float sum = 0.0f;
        for (int j = y - 4; j < y + 4; ++j)
            for (int i = x - 8; i < x + 8; ++i) sum += luma(img, i, j);
        return sum / 128.0f;
    };
    const float at1 = brightness(imageAt(on, 60)), at5 = brightness(imageAt(on, 300));
    const float none1 = brightness(imageAt(off, 60)), none5 = brightness(imageAt(off, 300));
    INFO("luma at the hit: foam 1 s " << at1 << ", 5 s " << at5 << "; no foam 1 s " << none1 << ", 5 s " << none5
                                      << "; coverage there at 5 s " << on.foamAtHit);
    CHECK(on.foamAtHit > 0.05f);  // the simulation still holds foam there
    // Foam thins and turns transparent as its coverage decays (common_foam.glsl: opacity
    // 0.1 + 0.9·d²), so half-decayed foam shows faintly.
    CHECK(at1 > none1 + 0.1f);
    CHECK(at5 > none5 + 0.01f);
    CHECK(at5 - none5 < 0.8f * (at1 - none1));  // coverage e^(−4/6) = 0.51 of 1 s (with no new sources)
}

TEST_CASE("landed drops leave soft foam spots, not single white pixels: 2 and 4 s after a cannonball's hit", "[gl][render][foam]") {
    // Drops in flight not drawn, so every bright dot is foam. An isolated dot: a pixel brighter
    // than all eight neighbours by over 0.1 in luma, in an 80 × 40 px box round the hit (the
    // ring where the crown's drops land, ~6 m across).
    const CannonRun on = runCannon({"render.splash_drops=false"}, {120, 240});
    CHECK(on.errorFree);
    for (int k : {120, 240}) {
        const Image& img = imageAt(on, k);
        const int cx = int(on.hitScreen.x), cy = int(on.hitScreen.y);
        int dots = 0;
        for (int y = std::max(1, cy - 20); y < std::min(img.h - 1, cy + 20); ++y)
            for (int x = std::max(1, cx - 40); x < std::min(img.w - 1, cx + 40); ++x) {
                float around = 0.0f;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        if (dx || dy) around = std::max(around, luma(img, x + dx, y + dy));
                dots += luma(img, x, y) > around + 0.1f ? 1 : 0;
            }
        INFO(k << " frames after the hit: " << dots << " isolated bright pixels");
        CHECK(dots <= 2);
    }
}

TEST_CASE("the baked foam pattern draws the per-pixel one: 1 s after a cannonball's hit, full quality against shipped", "[gl][render][foam]") {
    // The shipped water shader reads the bubble pattern from its baked map (one RGBA8 lookup);
    // full quality computes it per pixel from three detail map lookups (common_detail.glsl).
    const CannonRun shipped = runCannon({"render.splash_drops=false"}, {60});
    const CannonRun full = runCannon({"render.splash_drops=false", "render.water_full_quality=true"}, {60});
    const CannonRun none = runCannon({"render.splash_drops=false", "foam.enabled=false"}, {60});
    REQUIRE(shipped.hitScreen == full.hitScreen);
    // Mean |luma difference| in a 40 × 20 px box round the hit (the foam patch, about 3 m across).
    const auto boxDifference = [&](const Image& a, const Image& b) {
        const int x = int(shipped.hitScreen.x), y = int(shipped.hitScreen.y);
        float sum = 0.0f;
        for (int j = y - 10; j < y + 10; ++j)
            for (int i = x - 20; i < x + 20; ++i) sum += std::abs(luma(a, i, j) - luma(b, i, j));
        return sum / 800.0f;
    };
    const float baked = boxDifference(imageAt(shipped, 60), imageAt(full, 60));
    const float foam = boxDifference(imageAt(none, 60), imageAt(full, 60));
    INFO("mean |luma shipped - full| in the box " << baked << "; the foam itself (full - no foam) " << foam);
    CHECK(foam > 0.05f);
    CHECK(baked < 0.1f * foam);
}

TEST_CASE("splash drops above flat water: drawn in the frame where they are, mirrored in the reflection target, none below the "
          "surface, and far drops keep a 1.5 px sprite",
          "[gl][render][splash]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform(SIZE);
    const int errorsBefore = gfx::glErrorCount();
    gfx::RenderDef def;
    def.rtt_scale = 0.5f;
    def.antialias = gfx::Antialias::Off;
    gfx::Renderer renderer(def);
    gfx::CameraView camera;
    camera.position = glm::vec3(0.0f, 6.0f, 0.0f);
    camera.view = glm::lookAtRH(camera.position, glm::vec3(0.0f, 0.0f, -30.0f), glm::vec3(0, 1, 0));
    camera.projection = glm::perspectiveRH_NO(glm::radians(60.0f), float(SIZE.x) / float(SIZE.y), 0.1f, 2000.0f);
    camera.nearM = 0.1f;
    camera.farM = 2000.0f;
    const glm::ivec2 target = SIZE / 2;
    const auto pixelOf = [&](glm::vec3 p, glm::ivec2 size) {
        const glm::vec4 clip = camera.projection * camera.view * glm::vec4(p, 1.0f);
        return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(size);
    };
    // A ball of 400 drops (r = 1 cm, sprites of 6 cm) 3 m above the water, 30 m ahead.
    const glm::vec3 centre(2.0f, 3.0f, -30.0f);
    std::vector<gfx::SplashDrop> drops;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 u(float(i % 7) / 6.0f - 0.5f, float((i / 7) % 7) / 6.0f - 0.5f, float(i / 49) / 8.0f - 0.5f);
        drops.emplace_back(centre + 0.8f * u, 0.01f);
    }
    renderer.render(camera, gfx::WaterView{}, {}, 0.0, SIZE, drops);
    const Image with = readFrame();
    const auto [reflection, reflected] = alphaCentroid(renderer.reflectionTarget().color, target);
    const auto [refraction, refracted] = alphaCentroid(renderer.refractionTarget().color, target);
    renderer.render(camera, gfx::WaterView{}, {}, 0.0, SIZE, {});
    const Image without = readFrame();

    const glm::vec2 mirrored = pixelOf(glm::vec3(centre.x, -centre.y, centre.z), target);
    INFO("reflection: alpha " << reflected << " at " << reflection.x << ", " << reflection.y << "; expected at " << mirrored.x << ", "
                              << mirrored.y);
    CHECK(reflected > 5.0f);
    CHECK(glm::distance(reflection, mirrored) < 1.5f);
    CHECK(refracted == 0.0f);  // above the water: nothing in the refraction target

    // In the frame, the changed pixels gather round the drops' own pixel, brighter.
    const glm::vec2 at = pixelOf(centre, SIZE);
    glm::vec2 sum(0.0f);
    int changed = 0;
    for (int y = 0; y < SIZE.y; ++y)
        for (int x = 0; x < SIZE.x; ++x)
            if (luma(with, x, y) > luma(without, x, y) + 0.05f && y < SIZE.y / 2 + 10) {
                sum += glm::vec2(float(x) + 0.5f, float(SIZE.y - y) - 0.5f);
                ++changed;
            }
    REQUIRE(changed > 10);
    INFO("frame: " << changed << " brighter pixels round " << sum.x / float(changed) << ", " << sum.y / float(changed) << "; the drops at "
                   << at.x << ", " << at.y);
    CHECK(glm::distance(sum / float(changed), at) < 2.0f);

    // One drop 13 m away: its 2.4 cm sprite is 0.29 px in radius, so it is drawn 0.75 px in
    // radius at (0.29/0.75)² = 15% of its opacity: it changes its pixels a little, never to white.
    const glm::vec3 far(0.0f, 1.0f, -12.0f);  // seen against the water
    renderer.render(camera, gfx::WaterView{}, {}, 0.0, SIZE, std::vector<gfx::SplashDrop>{gfx::SplashDrop(far, 0.004f)});
    const Image one = readFrame();
    const glm::vec2 p = pixelOf(far, SIZE);
    float most = 0.0f;
    for (int y = int(SIZE.y - p.y) - 2; y <= int(SIZE.y - p.y) + 2; ++y)
        for (int x = int(p.x) - 2; x <= int(p.x) + 2; ++x) most = std::max(most, std::abs(luma(one, x, y) - luma(without, x, y)));
    INFO("largest change near the far drop " << most);
    CHECK(most > 0.02f);
    CHECK(most < 0.25f);
    CHECK(one.maxDifference(without, 0, int(SIZE.y - p.y) - 3) == 0);  // nothing above it
    CHECK(gfx::glErrorCount() == errorsBefore);
}
