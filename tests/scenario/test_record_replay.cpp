// Record and replay: a `play` session in a window (a virtual display where there is one),
// driven by scripted input on the wall clock, writes what its steps consumed; `run --input`
// of that recording reaches the state hash the session reported, at 1 and 8 steps a frame.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

using ob::test::runOceanbox;
using ob::test::runShell;
using ob::test::tempPath;
using ob::test::withoutLeakCheck;
using ob::test::writeFile;

namespace {

// A rough sea, ripples under the followed ship, a cannon: what the tools and the camera touch.
const std::string SCENE = R"(# record and replay
[window]
width = 320
height = 180
[camera]
mode = "follow"
[ocean]
resolution = 64
wind_speed = 10.0
[gerstner]
count = 4
[ripples]
model = "ewave"
resolution = 128
follow = "target"
[[objects]]
type = "ship"
name = "boat"
player = true
position = [0, 0.2, 0]
[[objects]]
type = "cannon"
player = true
position = [6, 3, 0]
[[objects]]
type = "box"
name = "crate"
position = [2, 0.3, 12]
)";

// Throttle, a right drag of the camera, a drop, a stir stroke, a shot of the cannon tool.
const std::string INPUT = R"(
[[press]]
at = 0.2
key = "w"
hold = 2.0
[[mouse]]
at = 0.4
button = "right"
hold = 0.3
pos = [160, 90]
drag = [40, -10]
[[press]]
at = 1.0
key = "3"
hold = 0.05
[[mouse]]
at = 1.3
button = "left"
pos = [200, 120]
hold = 0.05
[[press]]
at = 1.8
key = "2"
hold = 0.05
[[mouse]]
at = 2.1
button = "left"
pos = [100, 130]
hold = 0.6
drag = [60, 5]
[[press]]
at = 3.0
key = "5"
hold = 0.05
[[mouse]]
at = 3.3
button = "left"
pos = [230, 110]
hold = 0.05
[[press]]
at = 4.0
key = "escape"
)";

std::string hashOf(const std::string& statsPath) {
    return nlohmann::json::parse(std::ifstream(statsPath))["state_hash"].get<std::string>();
}

} // namespace

TEST_CASE("a recorded play session replays by run to the same state hash at 1 and 8 steps a frame", "[record]") {
    const std::string scene = writeFile(tempPath("record_scene.toml"), SCENE);
    const std::string input = writeFile(tempPath("record_input.toml"), INPUT);
    const std::string recording = tempPath("record_session.toml");
    const std::string playStats = tempPath("record_play.json");
    // A window on a virtual display when xvfb-run is there (the wall clock, frames of any
    // length), else play's headless fallback (its fixed clock).
    // Under the sanitizers the headless fallback: LeakSanitizer would report the X client
    // libraries' per-display allocations, which no code of ours makes; and without the leak
    // check, whose tracer crashes at this child's exit (withoutLeakCheck).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    const bool xvfb = false;
#else
    const bool xvfb = runShell("command -v xvfb-run").exitCode == 0;
#endif
    // The player quits with Esc at 4 s of the wall clock (the input's last click is at 3.3 s),
    // however fast the frames come; headless, play's fixed clock reaches it too.
    const std::string play = "play " + scene + " --input " + input + " --record " + recording + " --stats " + playStats;
    auto played = xvfb ? runShell("timeout 300 xvfb-run -a -s '-screen 0 640x480x24' $OCEANBOX " + play) : runShell(withoutLeakCheck() + "\"$OCEANBOX\" " + play + " --headless --frames 300");
    INFO(played.output);
    REQUIRE(played.exitCode == 0);
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(playStats));
    // The session did what the input asked: a dropped ball, a cannon shot.
    bool dropped = false;
    for (const auto& b : stats["bodies"]) dropped = dropped || b["name"] == "ball_1";
    CHECK(dropped);
    CHECK(stats["cannons"][0]["shots"] == 1);
    for (int k : {1, 8}) {
        INFO("steps per frame " << k);
        const std::string runStats = tempPath("record_run.json");
        auto replayed = runOceanbox("run " + scene + " --headless --input " + recording + " --steps-per-frame " + std::to_string(k) +
                                    " --stats " + runStats);
        INFO(replayed.output);
        REQUIRE(replayed.exitCode == 0);
        const nlohmann::json again = nlohmann::json::parse(std::ifstream(runStats));
        CHECK(again["steps"] == stats["steps"]);
        CHECK(hashOf(runStats) == hashOf(playStats));
    }
}

TEST_CASE("bad input scripts and record paths are exit 2 naming the file, line and key, before the run", "[record]") {
    const std::string scene = writeFile(tempPath("record_bad_scene.toml"), "[ocean]\nresolution = 32\n");
    const auto run = [&](const std::string& input, const std::string& extra = "") {
        return runOceanbox("run " + scene + " --headless --frames 3 --input " + writeFile(tempPath("record_bad.toml"), input) + extra);
    };
    auto unknownKey = run("[[mouse]]\nat = 1.0\nposition = [3, 4]\n");
    CHECK(unknownKey.exitCode == 2);
    CHECK(unknownKey.output.find("record_bad.toml:3") != std::string::npos);
    CHECK(unknownKey.output.find("position") != std::string::npos);
    auto unknownTool = run("[[press]]\nat = 1.0\nkey = \"7x\"\n");
    CHECK(unknownTool.exitCode == 2);
    CHECK(unknownTool.output.find("key") != std::string::npos);
    auto badGame = runOceanbox("run " + writeFile(tempPath("record_bad_tools.toml"), "[tools]\ntool = \"hammer\"\n") + " --headless --frames 3");
    CHECK(badGame.exitCode == 2);
    CHECK(badGame.output.find("tools.tool") != std::string::npos);
    CHECK(badGame.output.find(":2") != std::string::npos);
    auto unwritable = runOceanbox("play " + scene + " --headless --frames 3 --record /nonexistent/folder/rec.toml");
    CHECK(unwritable.exitCode == 2);
    CHECK(unwritable.output.find("recording") != std::string::npos);
}

TEST_CASE("a recording's [[set]] entries (the overlay's live changes) replay as the timeline's set events", "[record]") {
    const std::string base = "[ocean]\nresolution = 32\nwind_speed = 6.0\n[gerstner]\ncount = 2\n";
    const std::string change = "at = 0.5\nkey = \"ocean.wind_speed\"\nvalue = 14.0\n";
    const std::string timeline = writeFile(tempPath("record_set_timeline.toml"), base + "[[events]]\naction = \"set\"\n" + change);
    const std::string plain = writeFile(tempPath("record_set_plain.toml"), base);
    const std::string input = writeFile(tempPath("record_set_input.toml"), "[[set]]\n" + change);
    const std::string a = tempPath("record_set_a.json"), b = tempPath("record_set_b.json"), c = tempPath("record_set_c.json");
    REQUIRE(runOceanbox("run " + timeline + " --headless --size 32x32 --frames 90 --stats " + a).exitCode == 0);
    REQUIRE(runOceanbox("run " + plain + " --headless --size 32x32 --frames 90 --input " + input + " --stats " + b).exitCode == 0);
    REQUIRE(runOceanbox("run " + plain + " --headless --size 32x32 --frames 90 --stats " + c).exitCode == 0);
    CHECK(hashOf(a) == hashOf(b));
    CHECK(hashOf(b) != hashOf(c));  // the change did something
    auto bad = runOceanbox("run " + plain + " --headless --frames 3 --input " +
                           writeFile(tempPath("record_set_bad.toml"), "[[set]]\nat = 0.5\nkey = \"ocean.resolution\"\nvalue = 64\n"));
    CHECK(bad.exitCode == 2);
    CHECK(bad.output.find("set[0].key") != std::string::npos);
}
