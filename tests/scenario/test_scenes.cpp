// Every scene in config/scenes: 300 headless frames (rendering included) end without an
// error (GL debug output on) and two runs end in the same state hash. The spectrum grid is
// shrunk to 64² and the frame to 32×32 so the suite stays quick; the simulation is otherwise
// the scene's own.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <set>

using namespace ob;

namespace {

// The scenes with a test below; the last test checks the folder holds no other.
const std::set<std::string> SCENES{"default", "spectrum_only", "cannon", "fish", "ship", "all", "fish_swarm", "drop", "wake",
                                 "sandbox", "targets", "race", "herd", "harbour", "tide"};

struct Run {
    int exitCode = -1;
    std::string output;
    std::string hash;
    nlohmann::json stats;
};

Run runScene(const std::string& name, int tag) {
    const std::string json = test::tempPath(name + std::to_string(tag) + ".json");
    // drop.toml ends at 6 s (360 steps): its run goes past the end (below).
    const int frames = name == "drop" ? 400 : 300;
    auto r = test::runOceanbox("run config/scenes/" + name + ".toml --headless --frames " + std::to_string(frames) + " --size 32x32 "
                               "--set render.grid_resolution=16 --set ocean.resolution=64 --stats " + json);
    Run run{r.exitCode, r.output, "", {}};
    if (r.exitCode == 0) {
        run.stats = nlohmann::json::parse(std::ifstream(json));
        run.hash = run.stats["state_hash"].get<std::string>();
    }
    return run;
}

void checkScene(const std::string& name) {
    REQUIRE(SCENES.count(name));
    setenv("OCEANBOX_GL_DEBUG", "1", 1);  // GL errors fail the run (exit 1)
    // The two runs go side by side: each is one process on one core.
    auto first = std::async(std::launch::async, runScene, name, 0);
    Run b = runScene(name, 1);
    Run a = first.get();
    INFO(a.output);
    REQUIRE(a.exitCode == 0);
    REQUIRE(b.exitCode == 0);
    // [sim] end_time ends the simulation of every run (drop.toml's 6 s: 360 steps; the frames
    // after it draw the ended world).
    CHECK(a.stats["steps"] == (name == "drop" ? 360 : 300));
    CHECK(a.hash == b.hash);
    // Every body ends as a number (no NaN escaped into a pose).
    for (const auto& body : a.stats["bodies"]) CHECK(body["position"][1].is_number_float());
}

} // namespace

TEST_CASE("scene default.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("default"); }
TEST_CASE("scene spectrum_only.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("spectrum_only"); }
TEST_CASE("scene cannon.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("cannon"); }
TEST_CASE("scene fish.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("fish"); }
TEST_CASE("scene ship.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("ship"); }
TEST_CASE("scene all.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("all"); }
TEST_CASE("scene fish_swarm.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("fish_swarm"); }
TEST_CASE("scene drop.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("drop"); }
TEST_CASE("scene wake.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("wake"); }
TEST_CASE("scene sandbox.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("sandbox"); }
TEST_CASE("scene targets.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("targets"); }
TEST_CASE("scene race.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("race"); }
TEST_CASE("scene herd.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("herd"); }
TEST_CASE("scene tide.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("tide"); }
TEST_CASE("scene harbour.toml: 300 headless frames without error, the same state hash twice", "[scenes][long]") { checkScene("harbour"); }

TEST_CASE("every scene in config/scenes has a determinism test", "[scenes]") {
    std::set<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes"))
        if (entry.path().extension() == ".toml") found.insert(entry.path().stem().string());
    CHECK(found == SCENES);
}

TEST_CASE("run without --frames stops at [sim] end_time, screenshot events write their PNG", "[scenes]") {
    const std::string json = test::tempPath("end.json"), png = test::tempPath("event.png");
    auto r = test::runOceanbox("run config/scenes/ship.toml --headless --size 48x32 --set render.grid_resolution=16 "
                               "--set sim.end_time=0.5 --set 'events=[{at = 0.25, action = \"screenshot\", file = \"" + png +
                               "\"}]' --stats " + json);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    auto stats = nlohmann::json::parse(std::ifstream(json));
    CHECK(stats["steps"] == 30);
    CHECK(stats["events_run"] == 1);
    // Every body at the end: the ship at rest floats level at its density ratio (450/1025).
    REQUIRE(stats["bodies"].size() == 1);
    const auto& ship = stats["bodies"][0];
    CHECK(ship["type"] == "ship");
    CHECK(ship["position"].size() == 3);
    CHECK(std::abs(ship["roll_deg"].get<double>()) < 2.0);
    CHECK(std::abs(ship["pitch_deg"].get<double>()) < 2.0);
    CHECK(ship["submerged_fraction"].get<double>() == Approx(450.0 / 1025.0).margin(0.08));
    CHECK(std::filesystem::file_size(png) > 100);
    // --frames wins over the end time.
    r = test::runOceanbox("run config/scenes/ship.toml --headless --size 48x32 --set render.grid_resolution=16 --frames 12 --stats " + json);
    REQUIRE(r.exitCode == 0);
    CHECK(nlohmann::json::parse(std::ifstream(json))["steps"] == 12);
    // An unwritable event screenshot is bad input, caught before the run.
    r = test::runOceanbox("run config/scenes/ship.toml --headless --frames 1 --set 'events=[{action = \"screenshot\", file = \"/no/such/dir/x.png\"}]'");
    CHECK(r.exitCode == 2);
}
