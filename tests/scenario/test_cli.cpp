// The oceanbox executable end to end: exit codes and messages of docs/references.md#contracts, and a headless
// run that writes a screenshot and stats.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using ob::test::runOceanbox;
using ob::test::tempPath;
using ob::test::writeFile;

TEST_CASE("help (--help) on the program and on each subcommand exits 0", "[cli]") {
    CHECK(runOceanbox("--help").exitCode == 0);
    for (const char* cmd : {"play", "run", "bench", "dump"}) {
        auto r = runOceanbox(std::string(cmd) + " --help");
        INFO(cmd << ": " << r.output);
        CHECK(r.exitCode == 0);
        CHECK(r.output.find("--") != std::string::npos);
    }
}

TEST_CASE("a headless run writes a PNG screenshot and JSON stats", "[cli]") {
    std::string png = tempPath("shot.png"), json = tempPath("stats.json");
    auto r = runOceanbox("run config/scenes/default.toml --headless --frames 12 --size 96x64 --screenshot " + png +
                         " --stats " + json);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(std::filesystem::file_size(png) > 100);
    nlohmann::json stats = nlohmann::json::parse(std::ifstream(json));
    CHECK(stats["frames"] == 12);
    CHECK(stats["steps"] == 12);
    CHECK(stats["simulated_seconds"].get<double>() == Approx(12.0 / 60.0));
    for (const char* phase : {"input", "script", "physics", "interaction", "ocean", "render"}) {
        CHECK(stats["phases"][phase].contains("mean_ms"));
        CHECK(stats["phases"][phase].contains("median_ms"));
    }
    CHECK(stats["entities"]["total"].get<int>() >= 1);
    CHECK(stats["state_hash"].get<std::string>().size() == 16);
}

TEST_CASE("bad flags exit 2 with a message", "[cli]") {
    auto r = runOceanbox("run config/scenes/default.toml --frobnicate");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--frobnicate") != std::string::npos);
    r = runOceanbox("run config/scenes/default.toml --headless --size 12by7");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--size '12by7'") != std::string::npos);
    r = runOceanbox("run config/scenes/default.toml --frames -3");
    CHECK(r.exitCode == 2);
    CHECK(runOceanbox("").exitCode == 2);
    CHECK(runOceanbox("launch").exitCode == 2);
    CHECK(runOceanbox("ripple --in x.npy").exitCode == 2);
}

TEST_CASE("bad scene files exit 2 naming file, line and key", "[cli]") {
    std::string path = writeFile(tempPath("bad.toml"), "[camera]\nfov_deg = 500\n[render]\ncolour = 1\n");
    auto r = runOceanbox("run " + path + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(path + ":2:11: camera.fov_deg: must be in [10, 120], got 500") != std::string::npos);
    CHECK(r.output.find(path + ":4:1: render.colour: unknown key") != std::string::npos);

    r = runOceanbox("run /no/such/scene.toml --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("/no/such/scene.toml: cannot open file (no such file)") != std::string::npos);

    std::string syntax = writeFile(tempPath("syntax.toml"), "[window\nwidth = 3\n");
    r = runOceanbox("run " + syntax + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(syntax + ":1:") != std::string::npos);

    r = runOceanbox("run config/scenes/default.toml --headless --frames 1 --set render.fresnel=3");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--set render.fresnel=3: render.fresnel: expected a string, got an integer") != std::string::npos);

    std::string aa = writeFile(tempPath("antialias.toml"), "[render]\nantialias = \"msaa8\"\n");
    r = runOceanbox("run " + aa + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(aa + ":2:13: render.antialias: must be one of \"auto\", \"off\", \"fxaa\", \"msaa4\", got \"msaa8\"") !=
          std::string::npos);
    r = runOceanbox("run config/scenes/default.toml --headless --frames 1 --set render.antialias=smaa");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--set render.antialias=smaa: render.antialias: must be one of") != std::string::npos);
}

TEST_CASE("an unwritable output path exits 2 before anything runs, and writes nothing", "[cli]") {
    auto r = runOceanbox("run config/scenes/default.toml --headless --frames 1 --screenshot /no/such/dir/x.png");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("cannot write screenshot '/no/such/dir/x.png'") != std::string::npos);
    r = runOceanbox("run config/scenes/default.toml --headless --frames 1 --stats /no/such/dir/x.json");
    CHECK(r.exitCode == 2);
}

TEST_CASE("play without a display falls back to headless, says so in one line, and keeps a screenshot", "[cli]") {
    std::string png = tempPath("play.png");
    auto r = runOceanbox("play --frames 3 --size 64x48 --screenshot " + png + " < /dev/null");
    // The test environment may or may not have a display; without one the fallback is taken.
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr) {
        INFO(r.output);
        CHECK(r.exitCode == 0);
        CHECK(r.output.find("no display found: running headless") != std::string::npos);
        CHECK(std::filesystem::exists(png));
    }
}
