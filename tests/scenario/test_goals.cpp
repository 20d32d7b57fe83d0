// The goal scenes end to end (`oceanbox run SCENE --input FILE --stats S.json`): a scripted
// winning input (tests/data/goals/*_win.toml) wins and no input loses, with the result in
// --stats; a gate skipped is reported missed; the run ends on the step the goal is decided,
// at 1 and 8 steps a frame alike; [sim] end_time ends any run; R restarts; bad [game] input
// exits 2 naming file, line and key. The sea is each scene's own (its ocean grid at 64², as
// the scene tests do); a losing run's limit is cut short with --set to keep the test quick.
// herd.toml's inputs run in the unit suite (tests/unit/test_goals.cpp), without the picture.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

using ob::test::runOceanbox;
using ob::test::tempPath;
using ob::test::writeFile;

namespace {

const std::string DATA = std::string(OCEANBOX_TEST_DATA) + "/goals/";

// Runs a scene headless for at most `frames` frames; returns the stats.
nlohmann::json play(const std::string& scene, const std::string& input, long frames, const std::string& extra = "") {
    const std::string stats = tempPath("goal_stats.json");
    std::string args = "run " + scene + " --headless --size 64x36 --set ocean.resolution=64 --frames " + std::to_string(frames) +
                       " --stats " + stats + " " + extra;
    if (!input.empty()) args += " --input " + input;
    auto r = runOceanbox(args);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return nlohmann::json::parse(std::ifstream(stats));
}

} // namespace

TEST_CASE("targets.toml: the scripted aim hits all five targets and wins, no input loses at the time limit", "[goals][scenes][long]") {
    const nlohmann::json won = play("config/scenes/targets.toml", DATA + "targets_win.toml", 3000);
    const nlohmann::json& game = won["game"];
    INFO(game.dump());
    CHECK(game["mode"] == "targets");
    CHECK(game["result"] == "won");
    CHECK(game["score"] == 5);
    CHECK(game["hits"] == 5);
    CHECK(game["hit"].size() == 5);
    CHECK(won["cannons"][0]["shots"] == 5);  // one ball per target: every shot hit
    CHECK(game["time_s"].get<double>() < 20.0);
    // The run ends on the step the last target was hit.
    CHECK(won["steps"].get<double>() == Approx(game["time_s"].get<double>() * 60.0));

    const nlohmann::json lost = play("config/scenes/targets.toml", "", 3000, "--set game.time_limit=5");
    CHECK(lost["game"]["result"] == "lost");
    CHECK(lost["game"]["reason"] == "time is up");
    CHECK(lost["game"]["score"] == 0);
    CHECK(lost["game"]["time_s"].get<double>() == Approx(5.0));
    CHECK(lost["steps"] == 300);
}

TEST_CASE("race.toml: the scripted slalom passes the four gates in order and wins, no input loses", "[goals][scenes][long]") {
    const nlohmann::json won = play("config/scenes/race.toml", DATA + "race_win.toml", 3000);
    const nlohmann::json& game = won["game"];
    INFO(game.dump());
    CHECK(game["mode"] == "race");
    CHECK(game["result"] == "won");
    CHECK(game["passed"] == 4);
    CHECK(game["missed_gates"].empty());
    CHECK(game["race_time_s"].get<double>() == Approx(game["time_s"].get<double>()));
    CHECK(game["time_s"].get<double>() < 45.0);

    const nlohmann::json lost = play("config/scenes/race.toml", "", 3000, "--set game.time_limit=5");
    CHECK(lost["game"]["result"] == "lost");
    CHECK(lost["game"]["passed"] == 0);
    CHECK(lost["game"]["next_gate"] == 1);
}

TEST_CASE("race.toml: full throttle on a straight course skips gate 2 (it lies to starboard): missed and penalised, or lost", "[goals][scenes][long]") {
    // Full throttle, the heading held by one short touch of the rudder against the drift: the
    // ship passes gates 1, 3 and 4 and wide of gate 2. Crossing gate 3 marks gate 2 missed; its
    // 10 s penalty is added to the race time (still inside the 45 s limit), or with
    // missed_gate = "lose" the race is lost there.
    const std::string straight = writeFile(tempPath("race_straight.toml"),
                                           "[[press]]\nat = 0.2\nkey = \"w\"\nhold = 3.0\n\n"
                                           "[[press]]\nat = 10.0\nkey = \"a\"\nhold = 0.3\n");
    const nlohmann::json run = play("config/scenes/race.toml", straight, 3000);
    const nlohmann::json& game = run["game"];
    INFO(game.dump());
    CHECK(game["missed_gates"] == nlohmann::json::array({2}));
    CHECK(game["passed"] == 3);
    CHECK(game["race_time_s"].get<double>() == Approx(game["time_s"].get<double>() + 10.0));
    CHECK(game["result"] == "won");
    const nlohmann::json strict = play("config/scenes/race.toml", straight, 3000, "--set game.missed_gate=lose");
    INFO(strict["game"].dump());
    CHECK(strict["game"]["result"] == "lost");
}

TEST_CASE("a goal ends on the same step with the same state hash at 1 and 8 steps a frame", "[goals][determinism]") {
    const nlohmann::json one = play("config/scenes/targets.toml", DATA + "targets_win.toml", 3000);
    const nlohmann::json eight = play("config/scenes/targets.toml", DATA + "targets_win.toml", 400, "--steps-per-frame 8");
    CHECK(eight["game"]["result"] == "won");
    CHECK(eight["steps"] == one["steps"]);
    CHECK(eight["state_hash"] == one["state_hash"]);
}

TEST_CASE("[sim] end_time ends any run: play headless stops there, a scene without a goal ends, a goal undecided is lost",
          "[goals][scenes][long]") {
    const std::string calm = "[ocean]\nresolution = 32\namplitude = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n";
    const std::string scene = writeFile(tempPath("end_scene.toml"), calm + "[sim]\nend_time = 0.5\n");
    const std::string stats = tempPath("end_stats.json");
    auto r = runOceanbox("play " + scene + " --headless --size 64x36 --frames 600 --stats " + stats + " --screenshot " +
                         tempPath("end.png"));
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
    CHECK(j["steps"] == 30);
    CHECK(j["game"]["mode"] == "none");
    CHECK(j["game"]["result"] == "ended");
    // The targets scene with an end_time before the aim could win: lost at end_time.
    j = play("config/scenes/targets.toml", DATA + "targets_win.toml", 3000, "--set sim.end_time=4");
    CHECK(j["game"]["result"] == "lost");
    CHECK(j["game"]["time_s"].get<double>() == Approx(4.0));
    CHECK(j["game"]["score"].get<int>() < 5);
}

TEST_CASE("R restarts the scene: a new world from the scene file, the script goes on", "[goals][input]") {
    // Fire at 0.5 s, R at 1.0 s, fire at 1.5 s: the new world (from 1.0 s on) has one shot
    // and has run the frames after the restart only.
    const std::string input = writeFile(tempPath("restart_input.toml"),
                                        "[[press]]\nat = 0.5\nkey = \"space\"\n[[press]]\nat = 1.0\nkey = \"r\"\n"
                                        "[[press]]\nat = 1.5\nkey = \"space\"\n");
    const nlohmann::json j = play("config/scenes/targets.toml", input, 120);
    CHECK(j["cannons"][0]["shots"] == 1);
    CHECK(j["steps"].get<int>() == 60);
    CHECK(j["game"]["time_s"].get<double>() == Approx(1.0));
    const nlohmann::json without = play("config/scenes/targets.toml",
                                        writeFile(tempPath("no_restart.toml"), "[[press]]\nat = 0.5\nkey = \"space\"\n[[press]]\nat = 1.5\nkey = \"space\"\n"), 120);
    CHECK(without["cannons"][0]["shots"] == 2);
    CHECK(without["steps"] == 120);
}

TEST_CASE("a bad [game] key or value exits 2 naming file, line and key, before the run starts", "[goals][cli]") {
    const std::string calm = "[ocean]\nresolution = 32\n";
    auto run = [](const std::string& path, const std::string& extra = "") {
        return runOceanbox("run " + path + " --headless --size 64x36 --frames 1 " + extra);
    };
    std::string bad = writeFile(tempPath("bad_game.toml"), calm + "[game]\nmode = \"targets\"\ntarget_prefx = \"t\"\n");
    auto r = run(bad);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("bad_game.toml:5") != std::string::npos);
    CHECK(r.output.find("target_prefx") != std::string::npos);
    bad = writeFile(tempPath("bad_game.toml"), calm + "[game]\nmode = \"golf\"\n");
    r = run(bad);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("bad_game.toml:4") != std::string::npos);
    CHECK(r.output.find("game.mode") != std::string::npos);
    bad = writeFile(tempPath("bad_game.toml"), calm + "[game]\nmode = \"herd\"\nzone_radius = 0.1\n");
    r = run(bad);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("bad_game.toml:5") != std::string::npos);
    CHECK(r.output.find("zone_radius") != std::string::npos);
    // A gate naming an object the scene lacks; --set names its own assignment.
    r = run("config/scenes/race.toml", "--set game.gates[1].port=gate9_port");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("game.gates[1].port") != std::string::npos);
    CHECK(r.output.find("gate9_port") != std::string::npos);
    r = run("config/scenes/race.toml", "--set game.miss_penalty=-3");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("game.miss_penalty") != std::string::npos);
}
