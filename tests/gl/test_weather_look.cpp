// The sea's weather and the eye's adaptation (docs/look.md#weather, #exposure): an overcast
// ([sky] cloud_cover = 1) darker than a clear sky and hiding the sun's disc; auto exposure that
// brings a level view under water up to a lit blue-green within 3 s while the radiance itself
// keeps the level/zenith ratio field measurements give (2–20 %, Jerlov type I waters).
#include "gfx/auto_exposure.h"
#include "gfx/clouds.h"
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "support/test_image.h"
#include "support/test_support.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

using namespace ob;
using test::Image;

namespace {

gfx::CameraView cameraAt(glm::vec3 eye, glm::vec3 forward, glm::vec3 up, float fovDeg, float aspect) {
    gfx::CameraView camera;
    camera.position = eye;
    camera.view = glm::lookAtRH(eye, eye + forward, up);
    camera.projection = glm::perspectiveRH_NO(glm::radians(fovDeg), aspect, 0.1f, 2000.0f);
    camera.nearM = 0.1f;
    camera.farM = 2000.0f;
    return camera;
}

gfx::RenderDef plainDef() {
    gfx::RenderDef def;
    def.antialias = gfx::Antialias::Off;
    def.dither = false;
    return def;
}

// Renders `frames` frames 0.1 s apart (simulated) from `start` s and returns the last.
Image renderFrames(gfx::Renderer& renderer, const gfx::CameraView& camera, glm::ivec2 size, int frames = 1, double start = 0.0,
                   const gfx::WaterView& water = {}) {
    for (int f = 0; f < frames; ++f) renderer.render(camera, water, {}, start + 0.1 * f, size);
    const std::string path = test::tempPath("weather.png");
    gfx::writeScreenshot(path, size);
    Image img = test::loadPng(path);
    REQUIRE(img.w == size.x);
    return img;
}

// The display encoding undone, written here from its definition (sRGB-like 1/2.2 power over
// Narkowicz's ACES fit y = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14)): exposed linear radiance.
double linearOf(double display) {
    const double y = std::min(std::pow(display, 2.2), 0.98);
    const double a = 2.51 - 2.43 * y, b = 0.03 - 0.59 * y, c = -0.14 * y;
    return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

// Mean linear luminance (Rec. 709) of [x0, x1) × [y0, y1).
double linearLuminance(const Image& img, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
            sum += 0.2126 * linearOf(p[0] / 255.0) + 0.7152 * linearOf(p[1] / 255.0) + 0.0722 * linearOf(p[2] / 255.0);
        }
    return sum / double((x1 - x0) * (y1 - y0));
}

double luma(const unsigned char* p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; }

} // namespace

TEST_CASE("an overcast sky (cloud_cover 1) is at least 30% darker than a clear one and hides the sun's disc", "[gl][render][weather]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(240, 160);
    auto platform = platform::createHeadlessPlatform(size);
    gfx::RenderDef def = plainDef();
    const float elevation = glm::radians(25.0f);
    def.sun_direction = glm::vec3(0.0f, std::sin(elevation), -std::cos(elevation));
    const glm::vec3 sun = glm::normalize(def.sun_direction);
    // The whole sky above a camera 10 m up looking 30° up, away from the sun (its mean), and
    // the sun itself at the centre of a 10° view.
    const gfx::CameraView skyView = cameraAt({0, 10, 0}, glm::normalize(glm::vec3(0.0f, 0.5f, 0.87f)), {0, 1, 0}, 60.0f, 1.5f);
    const gfx::CameraView sunView = cameraAt({0, 10, 0}, sun, {0, 1, 0}, 10.0f, 1.5f);
    struct Look {
        double skyMean, disc, ring;
    };
    const auto look = [&](float cover) {
        gfx::Renderer renderer(def);
        renderer.sky().cloud_cover = cover;
        const Image sky = renderFrames(renderer, skyView, size);
        const Image toward = renderFrames(renderer, sunView, size);
        // The disc (0.53°) spans ~8 px in a 10° view 160 px high: its 3×3 centre, against a
        // ring 2° to 3° from it (32 to 48 px), both linear.
        double ring = 0.0;
        int count = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const double r = std::hypot(x + 0.5 - size.x / 2.0, y + 0.5 - size.y / 2.0);
                if (r >= 32.0 && r < 48.0) ring += linearLuminance(toward, x, y, x + 1, y + 1), ++count;
            }
        return Look{linearLuminance(sky, 0, 0, size.x, size.y / 2), linearLuminance(toward, size.x / 2 - 1, size.y / 2 - 1, size.x / 2 + 2, size.y / 2 + 2), ring / count};
    };
    const Look clear = look(0.0f), overcast = look(1.0f);
    INFO("sky mean (linear): clear " << clear.skyMean << ", overcast " << overcast.skyMean);
    INFO("sun disc / ring 2–3° off: clear " << clear.disc << " / " << clear.ring << ", overcast " << overcast.disc << " / " << overcast.ring);
    CHECK(overcast.skyMean <= 0.7 * clear.skyMean);
    CHECK(clear.disc > 2.0 * clear.ring);        // the test sees a disc where there is one
    CHECK(overcast.disc < 1.1 * overcast.ring);  // none under the overcast: only a soft patch
}

TEST_CASE("a broken sky's clouds shade the sun by their shape: the glitter dims while a cloud stands before the sun and comes back in a gap", "[gl][render][weather][clouds]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(96, 64);
    auto platform = platform::createHeadlessPlatform(size);
    gfx::RenderDef def = plainDef();
    const float elevation = glm::radians(30.0f);
    def.sun_direction = glm::vec3(0.0f, std::sin(elevation), -std::cos(elevation));
    const glm::vec3 sun = glm::normalize(def.sun_direction);
    gfx::SkyDef sky;
    sky.cloud_cover = 0.5f;
    sky.wind_aloft = 50.0f;  // along +x (the water's wind angle 0): the layer drifts 50 m a second
    // Moments with a cloud's core on the sun's ray and with a gap there, picked by the CPU's copy
    // of the layer; the sky drawn toward the sun then shows whether that copy is the sky's.
    double cloudy = -1.0, gap = -1.0;
    for (double t = 0.0; t < 2000.0 && (cloudy < 0.0 || gap < 0.0); t += 5.0) {
        const float loss = gfx::cloudBeamLoss(sky, glm::vec2(float(t) * sky.wind_aloft, 0.0f), sun);
        if (loss > 0.999f && cloudy < 0.0) cloudy = t;
        if (loss < 0.02f && gap < 0.0) gap = t;
    }
    REQUIRE(cloudy >= 0.0);
    REQUIRE(gap >= 0.0);
    // The sun's mirror point on a flat sea (its slopes' variance 0.02) at the centre of a 20° view
    // from 10 m up, and the sun at the centre of another.
    const gfx::CameraView seaView = cameraAt({0, 10, 0}, glm::vec3(sun.x, -sun.y, sun.z), {0, 1, 0}, 20.0f, 1.5f);
    const gfx::CameraView sunView = cameraAt({0, 10, 0}, sun, {0, 1, 0}, 10.0f, 1.5f);
    gfx::WaterView water;
    water.seaSlopeVariance = 0.02f;
    const int cx = size.x / 2, cy = size.y / 2;
    // The glitter alone (the frame with the sun's irradiance 1 less the one with 0), linear, the
    // centre 9×9; and the sun's 3×3 centre against its 11×11 surroundings' mean.
    const auto look = [&](float cover, double t) {
        gfx::RenderDef lit = def;
        lit.glitter = 1.0f;
        gfx::RenderDef dark = def;
        dark.glitter = 0.0f;
        gfx::Renderer a(lit), b(dark);
        a.sky() = sky, b.sky() = sky;
        a.sky().cloud_cover = b.sky().cloud_cover = cover;
        const Image on = renderFrames(a, seaView, size, 1, t, water);
        const Image off = renderFrames(b, seaView, size, 1, t, water);
        const Image toward = renderFrames(a, sunView, size, 1, t, water);
        const double glitter = linearLuminance(on, cx - 4, cy - 4, cx + 5, cy + 5) - linearLuminance(off, cx - 4, cy - 4, cx + 5, cy + 5);
        const double disc = linearLuminance(toward, cx - 1, cy - 1, cx + 2, cy + 2);
        const double around = linearLuminance(toward, cx - 5, cy - 5, cx + 6, cy + 6);
        return std::pair(glitter, disc / around);
    };
    const auto [clearGlitter, clearDisc] = look(0.0f, 0.0);
    const auto [cloudGlitter, cloudDisc] = look(sky.cloud_cover, cloudy);
    const auto [gapGlitter, gapDisc] = look(sky.cloud_cover, gap);
    INFO("glitter (linear, centre): clear sky " << clearGlitter << ", the sun behind a cloud (t = " << cloudy << " s) " << cloudGlitter
                                                  << ", in a gap (t = " << gap << " s) " << gapGlitter);
    INFO("the sun's centre over its surroundings: clear " << clearDisc << ", behind the cloud " << cloudDisc << ", in the gap " << gapDisc);
    CHECK(clearDisc > 2.0);  // the view sees the disc where there is one
    CHECK(gapDisc > 2.0);    // ... in the gap the sky drawn shows it too
    CHECK(cloudDisc < 1.1);  // ... and behind the cloud the sky drawn hides it
    // In the gap the glitter is the clear sky's less the thin veil the whole cover spreads (3 %
    // of it at 0.5: 1.5 %); behind a cloud's core (optical depth in the tens) none.
    CHECK(gapGlitter == Approx(clearGlitter).epsilon(0.05));
    CHECK(cloudGlitter < 0.02 * clearGlitter);
}

TEST_CASE("auto exposure's gain takes back 2/3 of a change in stops, relaxing with a time constant of 1 s, clamped to [1/4, 8]", "[gl][render][exposure]") {
    using Law = gfx::AutoExposureLaw;
    // In stops: after 1 s (four steps of 0.25 s) 1 − 1/e of the way.
    float gain = 1.0f;
    for (int s = 0; s < 4; ++s) gain = Law::adapt(gain, 4.0f, 0.25f);
    CHECK(std::log2(gain) == Approx(2.0 * (1.0 - std::exp(-1.0))).epsilon(1e-4));
    CHECK(Law::target(Law::KEY) == Approx(1.0f));
    CHECK(Law::target(Law::KEY / 8.0f) == Approx(4.0f));  // two thirds of 3 stops
    CHECK(Law::target(Law::KEY * 1000.0f) == Approx(0.25f));
    CHECK(Law::target(Law::KEY / 1000.0f) == Approx(8.0f));
    // The inverse of the display curve is the test's own.
    for (float d : {0.05f, 0.2f, 0.5f, 0.8f}) CHECK(gfx::displayToExposed(d) == Approx(linearOf(d)).epsilon(1e-4));
}

TEST_CASE("under water: a level view at 3 m adapts to a median luma of 60 within 3 s, the radiance keeps level/zenith within 2–20%", "[gl][render][exposure][underwater]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(192, 108);
    auto platform = platform::createHeadlessPlatform(size);
    gfx::RenderDef def = plainDef();
    def.auto_exposure = gfx::AutoExposureMode::Off;
    const auto level = [](float depth) { return cameraAt({0, -depth, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 16.0f / 9.0f); };
    const auto zenith = [](float depth) { return cameraAt({0, -depth, 0}, {0, 1, 0}, {0, 0, -1}, 60.0f, 16.0f / 9.0f); };
    // Off: the physical ratio, centre 32×32 of each view, at three depths.
    for (float depth : {3.0f, 8.0f, 15.0f}) {
        gfx::Renderer renderer(def);
        const Image lv = renderFrames(renderer, level(depth), size), up = renderFrames(renderer, zenith(depth), size);
        const int x0 = size.x / 2 - 16, y0 = size.y / 2 - 16;
        const double ratio = linearLuminance(lv, x0, y0, x0 + 32, y0 + 32) / linearLuminance(up, x0, y0, x0 + 32, y0 + 32);
        INFO("depth " << depth << " m: level / zenith " << ratio);
        CHECK(ratio > 0.02);
        CHECK(ratio < 0.20);
    }
    // On: 30 frames 0.1 s apart; the median luma of the whole last frame.
    def.auto_exposure = gfx::AutoExposureMode::On;
    gfx::Renderer adapting(def);
    const Image before = renderFrames(adapting, level(3.0f), size);
    const Image after = renderFrames(adapting, level(3.0f), size, 30);
    const auto median = [](const Image& img) {
        std::vector<double> l;
        for (size_t i = 0; i < img.rgb.size(); i += 3) l.push_back(luma(&img.rgb[i]));
        std::nth_element(l.begin(), l.begin() + long(l.size() / 2), l.end());
        return l[l.size() / 2];
    };
    INFO("median luma: first frame " << median(before) << ", after 3 s " << median(after) << " (gain " << adapting.exposureGain() << ")");
    CHECK(median(before) < 60.0);
    CHECK(median(after) >= 60.0);
}
