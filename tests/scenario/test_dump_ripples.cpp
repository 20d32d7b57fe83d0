// `dump ripples` end to end: a sphere dropped into calm water rings out a circular wave in
// the ripple field (physics → interaction → field), symmetric about the drop.
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

TEST_CASE("dump ripples: a dropped sphere makes a ring symmetric about the drop point", "[dump][ripple]") {
    std::string scene = test::writeFile(test::tempPath("drop.toml"),
                                        "[ocean]\namplitude = 0.0\n[ripples]\nresolution = 128\ncell_size = 0.1\ndamping = 0.99\n"
                                        "[[objects]]\ntype = \"sphere\"\nposition = [0.0, 1.5, 0.0]\nradius = 0.4\ndensity = 600.0\n");
    std::string out = test::tempPath("ripples.npy");
    auto r = test::runOceanbox("dump ripples " + scene + " --frames 60 --out " + out);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    NpyArray a = readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{128, 128});
    auto at = [&](int x, int z) { return a.data[size_t(z * 128 + x)]; };
    float peak = 0.0f;
    for (float v : a.data) peak = std::max(peak, std::abs(v));
    REQUIRE(peak > 1e-3f);  // the drop disturbed the water
    // The drop is at world (0, 0) = cell (64, 64): the field is the same a distance d away
    // along +x, −x, +z and −z.
    for (int d : {5, 10, 15, 20, 25}) {
        INFO("distance " << d << " cells");
        float ref = at(64 + d, 64);
        for (float v : {at(64 - d, 64), at(64, 64 + d), at(64, 64 - d)}) CHECK(v == Approx(ref).margin(0.02f * peak));
    }
    // Calm water without bodies stays flat.
    std::string calm = test::writeFile(test::tempPath("calm.toml"), "[ocean]\namplitude = 0.0\n[ripples]\nresolution = 64\n");
    REQUIRE(test::runOceanbox("dump ripples " + calm + " --frames 10 --out " + out).exitCode == 0);
    for (float v : readNpy(out).data) CHECK(v == 0.0f);
}
