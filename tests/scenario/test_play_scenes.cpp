// Every scene opened as `play` opens it where there is no display (headless, 150 frames):
// no GL error, and the picture is water where water should be — the first frame's lower
// half is the sea's colour, not the sky's (a hole in the projected grid shows the sky).
#include "support/test_image.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>

using namespace ob;

namespace {

// The lower half of a frame looks like water: darker than the sky at the horizon (which is
// near white, luminance > 0.8) and blue over red, pixel by pixel for nearly all pixels.
void checkLowerHalfIsWater(const test::Image& img, const std::string& what) {
    INFO(what);
    REQUIRE(img.w > 0);
    int sky = 0, total = 0;
    for (int y = img.h / 2; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) {
            const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
            const float luminance = (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f;
            // Sky: bright and grey-blue. Glitter and foam are bright too but rare.
            sky += luminance > 0.8f && p[2] >= p[0] ? 1 : 0;
            ++total;
        }
    const glm::vec3 mean = img.mean(0, img.h / 2, img.w, img.h);
    CHECK(double(sky) / total < 0.08);
    CHECK(mean.z > mean.x);
    CHECK(0.2126f * mean.x + 0.7152f * mean.y + 0.0722f * mean.z < 0.65f);
}

} // namespace

TEST_CASE("every scene opened as play opens it headless: 150 frames without a GL error, water below the horizon",
          "[scenes][play][long]") {
    setenv("OCEANBOX_GL_DEBUG", "1", 1);  // GL errors fail the run (exit 1)
    for (const auto& entry : std::filesystem::directory_iterator(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes")) {
        if (entry.path().extension() != ".toml") continue;
        const std::string scene = entry.path().string();
        const std::string first = test::tempPath("play_first.png"), last = test::tempPath("play_last.png");
        auto r = test::runOceanbox("play " + scene + " --headless --size 160x90 --frames 1 --screenshot " + first);
        INFO(r.output);
        REQUIRE(r.exitCode == 0);
        checkLowerHalfIsWater(test::loadPng(first), scene + ", first frame");
        // Without the sun's glitter and the foam here: the check looks for sky through a hole in
        // the sea, and both whiten water itself (the glitter's Cox–Munk path toward a low sun;
        // the foam on fish_swarm's piled-up walls of water, a tenth of the lower half by frame 300).
        r = test::runOceanbox("play " + scene + " --headless --size 96x54 --frames 150 --set ocean.resolution=64 --set render.glitter=0 --set render.foam=false --screenshot " + last);
        REQUIRE(r.exitCode == 0);
        checkLowerHalfIsWater(test::loadPng(last), scene + ", frame 150");
    }
}

TEST_CASE("play says a benchmark scene is one", "[scenes][play]") {
    auto r = test::runShell(test::withoutLeakCheck() + "\"$OCEANBOX\" play config/scenes/fish_swarm.toml --headless --size 32x32 --frames 1 --screenshot " +
                               test::tempPath("swarm.png"));
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(r.output.find("is a benchmark scene") != std::string::npos);
    r = test::runOceanbox("play config/scenes/default.toml --headless --size 32x32 --frames 1 --screenshot " +
                          test::tempPath("default.png"));
    REQUIRE(r.exitCode == 0);
    CHECK(r.output.find("benchmark") == std::string::npos);
}
