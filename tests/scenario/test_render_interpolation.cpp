// Render interpolation reaches the pictures and nothing else: `play` with render.interpolate on
// and off ends in the same state hash (docs/frame.md#render-interpolation), while what it draws
// differs (on, a frame draws the bodies and the camera one step behind the latest).
#include "support/test_image.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

using namespace ob;
using ob::test::runOceanbox;
using ob::test::tempPath;

namespace {

struct Played {
    std::string hash;
    test::Image picture;
};

// The default scene (the ships under way, the follow camera) played headless for 40 frames.
Played play(bool interpolate) {
    const std::string tag = interpolate ? "on" : "off";
    const std::string stats = tempPath("interpolate_" + tag + ".json"), png = tempPath("interpolate_" + tag + ".png");
    auto r = runOceanbox("play config/scenes/default.toml --headless --size 160x90 --frames 40 --set ocean.resolution=32"
                         " --set render.interpolate=" + std::string(interpolate ? "true" : "false") + " --stats " + stats +
                         " --screenshot " + png);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return {nlohmann::json::parse(std::ifstream(stats))["state_hash"].get<std::string>(), test::loadPng(png)};
}

} // namespace

TEST_CASE("play with render.interpolate on and off: the same state hash, different pictures", "[interpolation][play]") {
    const Played on = play(true), off = play(false);
    CHECK(on.hash == off.hash);
    // Negative control: the setting reaches the renderer (the camera drawn one step back moves
    // every pixel of the sea).
    REQUIRE(on.picture.rgb.size() == off.picture.rgb.size());
    CHECK(on.picture.rgb != off.picture.rgb);
}
