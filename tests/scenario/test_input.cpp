// The input path end to end: scripted presses (`run --input`) through the same queue as a
// window's events, at 1, 3 and 8 simulation steps a frame (what a slow machine does in
// play): one press is one action, a tap shorter than a frame counts, held keys act per step.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

using ob::test::runOceanbox;
using ob::test::tempPath;
using ob::test::writeFile;

namespace {

// Calm water, no ripples: what the input does is all that changes.
const std::string CALM = "[ocean]\nresolution = 32\namplitude = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n";
const std::string CANNON = "[[objects]]\ntype = \"cannon\"\nname = \"gun\"\nplayer = true\nposition = [0, 4, 0]\n";
const std::string SHIP = "[[objects]]\ntype = \"ship\"\nname = \"hull\"\nplayer = true\nposition = [0, 0.1, 0]\nspeed = 6.0\n";

nlohmann::json run(const std::string& scene, const std::string& input, int stepsPerFrame, int steps,
                   const std::string& extra = "") {
    const std::string scenePath = writeFile(tempPath("input_scene.toml"), scene);
    const std::string stats = tempPath("input_stats.json");
    std::string args = "run " + scenePath + " --headless --size 64x36 --frames " + std::to_string(steps / stepsPerFrame) +
                       " --steps-per-frame " + std::to_string(stepsPerFrame) + " --stats " + stats + extra;
    if (!input.empty()) args += " --input " + writeFile(tempPath("input.toml"), input);
    auto r = runOceanbox(args);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return nlohmann::json::parse(std::ifstream(stats));
}

int shots(const nlohmann::json& stats) { return stats["cannons"][0]["shots"].get<int>(); }

} // namespace

TEST_CASE("one scripted Space press fires one ball at 1, 3 and 8 steps a frame, a 5 ms tap fires, and a click of the cannon tool", "[input]") {
    const std::string press = "[[press]]\nat = 1.0\nkey = \"space\"\nhold = 0.3\n";
    const std::string tap = "[[press]]\nat = 1.01\nkey = \"space\"\nhold = 0.005\n";
    // The cannon tool (5): a left click on the water aims there and fires.
    const std::string click = "[[press]]\nat = 1.4\nkey = \"5\"\nhold = 0.02\n"
                              "[[mouse]]\nat = 1.5\nbutton = \"left\"\nhold = 0.2\npos = [32, 30]\n";
    for (int k : {1, 3, 8}) {
        INFO("steps per frame " << k);
        const nlohmann::json quiet = run(CALM + CANNON, "", k, 120);
        CHECK(quiet["steps"] == 120);
        CHECK(shots(quiet) == 0);
        CHECK(shots(run(CALM + CANNON, press, k, 120)) == 1);
        CHECK(shots(run(CALM + CANNON, tap, k, 120)) == 1);
        CHECK(shots(run(CALM + CANNON, press + click, k, 120)) == 2);
    }
}

TEST_CASE("F spawns one school of fish per press", "[input]") {
    const std::string f = "[[press]]\nat = 0.5\nkey = \"f\"\nhold = 0.4\n";
    for (int k : {1, 8}) {
        INFO("steps per frame " << k);
        CHECK(run(CALM, "", k, 96)["fish_schools"].size() == 0);
        CHECK(run(CALM, f, k, 96)["fish_schools"].size() == 1);
        CHECK(run(CALM, f + "[[press]]\nat = 1.0\nkey = \"f\"\nhold = 0.01\n", k, 96)["fish_schools"].size() == 2);
    }
    // The school is the scene's [controls] (12 fish by default).
    CHECK(run(CALM, f, 1, 96)["fish_schools"][0]["fish"] == 12);
    CHECK(run(CALM + "[controls]\nfish_count = 5\n", f, 1, 96)["fish_schools"][0]["fish"] == 5);
}

TEST_CASE("P pauses the simulation and N then advances exactly one step", "[input]") {
    const std::string p = "[[press]]\nat = 0.51\nkey = \"p\"\nhold = 0.1\n";
    const std::string n = "[[press]]\nat = 1.01\nkey = \"n\"\nhold = 0.1\n";
    const nlohmann::json paused = run(CALM, p, 1, 120);
    const nlohmann::json stepped = run(CALM, p + n, 1, 120);
    CHECK(paused["frames"] == 120);
    CHECK(paused["steps"].get<int>() < 40);  // paused near 0.5 s: about 31 of the 120 steps ran
    CHECK(stepped["steps"].get<int>() == paused["steps"].get<int>() + 1);
}

TEST_CASE("holding W gives the ship the same course at any number of steps a frame", "[input]") {
    const std::string w = "[[press]]\nat = 0.5\nkey = \"w\"\nhold = 2.0\n";
    auto ship = [](const nlohmann::json& stats) {
        for (const auto& b : stats["bodies"])
            if (b["name"] == "hull") return b["position"];
        return nlohmann::json();
    };
    const nlohmann::json still = ship(run(CALM + SHIP, "", 1, 360));
    const nlohmann::json one = ship(run(CALM + SHIP, w, 1, 360));
    // 2 s of W opens the lever to full: the ship is well under way after 6 s.
    CHECK(one[2].get<double>() - still[2].get<double>() > 5.0);
    for (int k : {3, 8}) {
        INFO("steps per frame " << k);
        const nlohmann::json other = ship(run(CALM + SHIP, w, k, 360));
        for (int i = 0; i < 3; ++i) CHECK(other[i].get<double>() == one[i].get<double>());
    }
}

TEST_CASE("in fly mode W/S/A/D move the camera and never the ship", "[input]") {
    const std::string fly = "[camera]\nmode = \"fly\"\nposition = [0, 10, -30]\n";
    const std::string w = "[[press]]\nat = 0.2\nkey = \"w\"\nhold = 2.0\n";
    auto shipZ = [](const nlohmann::json& stats) {
        for (const auto& b : stats["bodies"])
            if (b["name"] == "hull") return b["position"][2].get<double>();
        return 1e9;
    };
    CHECK(shipZ(run(CALM + fly + SHIP, w, 1, 180)) == shipZ(run(CALM + fly + SHIP, "", 1, 180)));
    CHECK(shipZ(run(CALM + SHIP, w, 1, 180)) > shipZ(run(CALM + SHIP, "", 1, 180)) + 0.5);
}

TEST_CASE("bad input scripts exit 2 naming file, line and key", "[input]") {
    const std::string scene = writeFile(tempPath("input_scene.toml"), CALM);
    auto r = runOceanbox("run " + scene + " --headless --frames 1 --input " +
                         writeFile(tempPath("bad_input.toml"), "[[press]]\nat = 1.0\nkey = \"spacebar\"\n"));
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("bad_input.toml:3") != std::string::npos);
    CHECK(r.output.find("press[0].key") != std::string::npos);
    r = runOceanbox("run " + scene + " --headless --frames 1 --input " +
                    writeFile(tempPath("bad_input.toml"), "[[press]]\nat = 1.0\nkey = \"w\"\nduration = 2\n"));
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("duration") != std::string::npos);
    r = runOceanbox("run " + scene + " --headless --frames 1 --steps-per-frame 0");
    CHECK(r.exitCode == 2);
    r = runOceanbox("run " + scene + " --headless --frames 1 --input /no/such/input.toml");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("/no/such/input.toml") != std::string::npos);
}

TEST_CASE("a folder, a device or an empty file given as a scene exits 2 with its reason", "[cli]") {
    auto r = runOceanbox("run config/scenes --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("is a folder") != std::string::npos);
    r = runOceanbox("run /dev/null --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("not a regular file") != std::string::npos);
    r = runOceanbox("run " + writeFile(tempPath("empty.toml"), "") + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("is empty") != std::string::npos);
}

TEST_CASE("play --help lists every key and mouse action", "[cli]") {
    auto r = runOceanbox("play --help");
    CHECK(r.exitCode == 0);
    for (const char* key : {"right drag", "wheel", "Space", "click", "W/S", "A/D", "arrows", "F12", "Esc", " C ", " H ", " N", " F "})
        CHECK(r.output.find(key) != std::string::npos);
}

TEST_CASE("tools through --input with pos: a drop lands under the click, an erase takes the body clicked", "[input][tools]") {
    // The camera looks straight down on the origin from 20 m: the framebuffer's centre is the
    // water point (0, 0, 0) by construction.
    const std::string down = CALM + "[window]\nwidth = 64\nheight = 36\n[camera]\nmode = \"fixed\"\nposition = [0, 20, -0.01]\n"
                                    "target = [0, 0, 0]\n";
    const std::string drop = "[[press]]\nat = 0.1\nkey = \"3\"\n[[mouse]]\nat = 0.3\nbutton = \"left\"\npos = [32, 18]\n";
    const nlohmann::json dropped = run(down, drop, 1, 150);
    REQUIRE(dropped["bodies"].size() == 1);
    const auto& p = dropped["bodies"][0]["position"];
    CHECK(std::hypot(p[0].get<double>(), p[2].get<double>()) < 0.5);
    const std::string erase = "[[press]]\nat = 0.1\nkey = \"4\"\n[[mouse]]\nat = 0.3\nbutton = \"left\"\npos = [32, 18]\n";
    const std::string ball = "[[objects]]\ntype = \"sphere\"\nname = \"ball\"\nposition = [0, 0, 0]\n"
                             "[[objects]]\ntype = \"sphere\"\nname = \"other\"\nposition = [6, 0, 0]\n";
    const nlohmann::json erased = run(down + ball, erase, 1, 60);
    REQUIRE(erased["bodies"].size() == 1);
    CHECK(erased["bodies"][0]["name"] == "other");
}
