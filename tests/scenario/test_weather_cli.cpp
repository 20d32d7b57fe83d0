// The weather end to end: the wind tears spray off breaking crests in a gale and not in a
// moderate breeze, counted in --stats as splash.spray_emitted; [sky] keys are checked as any.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

using ob::test::runOceanbox;
using ob::test::tempPath;

TEST_CASE("the stats of a run count splash.spray_emitted: above 0 at 18 m/s on the open sea, 0 at 6 m/s", "[cli][weather][spray][long]") {
    const auto spray = [](int wind) {
        const std::string stats = tempPath("spray_" + std::to_string(wind) + ".json");
        auto r = runOceanbox("run config/scenes/default.toml --headless --size 64x36 --frames 90 --set ocean.resolution=64 "
                             "--set ripples.resolution=64 --set ocean.wind_speed=" + std::to_string(wind) + " --stats " + stats);
        REQUIRE(r.exitCode == 0);
        std::ifstream in(stats);
        const nlohmann::json j = nlohmann::json::parse(in);
        REQUIRE(j.contains("splash"));
        return j["splash"]["spray_emitted"].get<long>();
    };
    CHECK(spray(18) > 0);
    CHECK(spray(6) == 0);
}

TEST_CASE("[sky] cloud_cover out of [0, 1] or an unknown [sky] key exits 2 naming file, line and key", "[cli][weather]") {
    const std::string path = ob::test::writeFile(tempPath("bad_sky.toml"), "[sky]\ncloud_cover = 1.5\nfog = 1\n");
    auto r = runOceanbox("run " + path + " --headless --frames 1");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(path + ":2:") != std::string::npos);
    CHECK(r.output.find("sky.cloud_cover") != std::string::npos);
    CHECK(r.output.find(path + ":3:1: sky.fog: unknown key") != std::string::npos);
}
