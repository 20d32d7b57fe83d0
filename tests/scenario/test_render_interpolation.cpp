// Render interpolation reaches what is drawn and nothing else: `play` with render.interpolate on
// and off ends in the same state hash (docs/frame.md#render-interpolation-renderinterpolate),
// while the camera its last frame drew differs (on, one step behind the latest).
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>

using namespace ob;
using ob::test::runOceanbox;
using ob::test::tempPath;

namespace {

struct Played {
    std::string hash;
    glm::vec3 eye;  // the camera the last frame drew
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
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
    const nlohmann::json& eye = j["camera"]["position"];
    return {j["state_hash"].get<std::string>(), {eye[0].get<float>(), eye[1].get<float>(), eye[2].get<float>()}};
}

} // namespace

TEST_CASE("play with render.interpolate on and off: the same state hash, the camera drawn one step apart", "[interpolation][play]") {
    const Played on = play(true), off = play(false);
    CHECK(on.hash == off.hash);
    // Negative control: the setting reaches the drawing. A fixed clock of one step a frame
    // leaves no remainder, so interpolated the last frame draws the camera where the step
    // before the last left it: behind the one that follows the player's ship (at most a few
    // m/s: well under a metre a step).
    const float apart = glm::length(on.eye - off.eye);
    INFO("the camera drawn " << apart << " m from the latest step's");
    CHECK(apart > 0.0f);
    CHECK(apart < 1.0f);
}
