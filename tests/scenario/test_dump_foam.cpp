// `dump foam` end to end: whitecaps cover the share of the sea the wind gives (Monahan &
// O'Muircheartaigh 1980, W = 3.84e-6·U10^3.41) within a factor of 2 from 8 to 20 m/s.
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

namespace {

// The share of the map's samples over ½ after `frames` steps of a sea with wind `wind`.
double whitecapShare(const std::string& scene, float wind, int frames) {
    const std::string out = test::tempPath("foam.npy");
    auto r = test::runOceanbox("dump foam " + scene + " --frames " + std::to_string(frames) + " --out " + out +
                               " --set ocean.wind_speed=" + std::to_string(wind));
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const NpyArray a = readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{256, 256});
    size_t over = 0;
    for (float v : a.data) over += v > 0.5f ? 1 : 0;
    return double(over) / double(a.data.size());
}

} // namespace

TEST_CASE("dump foam: whitecap coverage follows Monahan's W(U10) within a factor of 2", "[dump][foam][whitecaps][long]") {
    // [long]: nine whole-scene dumps (2.5 minutes under ASan); the plain run has it.
    // The default scene's sea (Phillips, a 250 m tile, two cascades, choppiness 1.2) at half its
    // resolution; no bodies, so every sample's foam is a whitecap's. The map spans the tile (its
    // whitecaps come in wave groups tens of metres apart), and the share is averaged over two
    // moments after the map has filled (τ = 6 s: stationary after ~10 s).
    const std::string scene = test::writeFile(test::tempPath("storm.toml"),
                                              "[ocean]\nresolution = 128\npatch_size = 250.0\nwind_direction = [1.0, 0.6]\n"
                                              "choppiness = 1.2\ncascades = 2\n[ripples]\nresolution = 64\ncell_size = 2.0\n"
                                              "[foam]\nresolution = 256\nextent_m = 250.0\n");
    for (float wind : {8.0f, 10.0f, 14.0f, 20.0f}) {
        const double monahan = 3.84e-6 * std::pow(double(wind), 3.41);
        const double w = 0.5 * (whitecapShare(scene, wind, 900) + whitecapShare(scene, wind, 1200));
        INFO("U10 = " << wind << " m/s: whitecap share " << w << ", Monahan " << monahan);
        CHECK(w > 0.5 * monahan);
        CHECK(w < 2.0 * monahan);
    }
    // No wind, no whitecaps (the sea of a calm: amplitude 0).
    CHECK(whitecapShare(scene + " --set ocean.amplitude=0", 10.0f, 60) == 0.0);
}
