// Live keys end to end: a run-time `set` of a key read once at start, and a grid resolution out
// of its range, are bad input (exit 2, file, line and key), not a silent change.
#include "support/test_support.h"

#include <catch2/catch.hpp>

using ob::test::runOceanbox;
using ob::test::tempPath;
using ob::test::writeFile;

TEST_CASE("a set event of a key read once at start exits 2 naming file, line and key", "[cli][live_keys]") {
    const std::string path = writeFile(tempPath("set_gravity.toml"),
                                       "[[events]]\nat = 1\naction = \"set\"\nkey = \"environment.gravity\"\nvalue = 3\n");
    auto r = runOceanbox("run " + path + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(path + ":4:7: events[0].key: 'environment.gravity' is read once at start; live keys: ") != std::string::npos);
    const std::string live = writeFile(tempPath("set_drag.toml"),
                                       "[ocean]\nresolution = 16\n[[events]]\nat = 0\naction = \"set\"\nkey = \"physics.linear_drag\"\nvalue = 3\n");
    CHECK(runOceanbox("run " + live + " --headless --size 32x32 --frames 2").exitCode == 0);
}

TEST_CASE("render.grid_resolution below 16 on the command line (--set) exits 2 with the key's range", "[cli][live_keys]") {
    auto r = runOceanbox("run config/scenes/default.toml --headless --frames 1 --set render.grid_resolution=8");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("render.grid_resolution: must be 0 (auto) or in [16, 2048], got 8") != std::string::npos);
}
