// [environment] end to end: the keys that moved there are bad input (exit 2, file, line and the
// new key), on the command line too; the new keys run.
#include "support/test_support.h"

#include <catch2/catch.hpp>

using ob::test::runOceanbox;
using ob::test::tempPath;
using ob::test::writeFile;

TEST_CASE("physics.gravity, physics.water_density and ocean.gravity exit 2 naming the key they moved to", "[cli][environment]") {
    const std::string path = writeFile(tempPath("moved_keys.toml"), "[physics]\nlinear_drag = 900.0\ngravity = 3.7\n"
                                                                     "water_density = 1000.0\n[ocean]\ngravity = 3.7\n");
    auto r = runOceanbox("run " + path + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(path + ":3:11: physics.gravity: moved to environment.gravity") != std::string::npos);
    CHECK(r.output.find(path + ":4:17: physics.water_density: moved to environment.water_density") != std::string::npos);
    CHECK(r.output.find(path + ":6:11: ocean.gravity: moved to environment.gravity") != std::string::npos);
    auto set = runOceanbox("run config/scenes/default.toml --headless --frames 1 --set physics.gravity=3.7");
    CHECK(set.exitCode == 2);
    CHECK(set.output.find("physics.gravity: moved to environment.gravity") != std::string::npos);
    const std::string moon = writeFile(tempPath("low_gravity.toml"), "[environment]\ngravity = 1.62\nwater_density = 1000.0\n"
                                                                      "[ocean]\nresolution = 16\n[ripples]\nresolution = 32\n");
    CHECK(runOceanbox("run " + moon + " --headless --size 32x32 --frames 2").exitCode == 0);
}
