// The velocity bands' fitted depth decay (ocean/velocity_bands.h) against linear theory's own
// e^{−k·depth} for every wavenumber of a cascade: the default scene's two cascades and its sea
// in one, 0.5, 1 and 3 m down (docs/velocity_bands.md's table).
#include "ocean/ocean_def.h"
#include "ocean/spectrum.h"
#include "ocean/velocity_bands.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

using namespace ob::ocean;

TEST_CASE("velocity bands: every wavenumber of a cascade decays as its own e^{-k·depth} within a few percent",
          "[ocean][water_motion]") {
    struct Case {
        int cascades;
        int cascade;
        double worstHalf, worstOne, worstThree;  // relative, where e^{−k·d} ≥ 5 %
    };
    // The default scene's sea (256², 250 m, 16 m/s): its long and short cascade, and all of it in one.
    for (const Case c : {Case{2, 0, 0.03, 0.03, 0.05}, Case{2, 1, 0.05, 0.03, 0.15}, Case{1, 0, 0.03, 0.04, 0.06}}) {
        OceanDef def;
        def.resolution = 256;
        def.patch_size = 250.0f;
        def.cascades = c.cascades;
        const WaveBand band = cascadeBand(def, c.cascade);
        const double dk = 2.0 * std::numbers::pi / cascadePatchSize(def, c.cascade);
        const VelocityBands bands = velocityBands(def.resolution, cascadePatchSize(def, c.cascade), band);
        const double lo = std::max(band.kMin, dk), hi = std::min(band.kMax, dk * (def.resolution / 2 - 1) * std::numbers::sqrt2);
        REQUIRE(bands.count >= 2);
        REQUIRE(bands.k[0] > lo);
        double worst[3] = {};
        const double depths[3] = {0.5, 1.0, 3.0};
        for (int i = 0; i <= 200; ++i) {
            const double k = lo * std::pow(hi / lo, i / 200.0);
            CHECK(bandDecay(bands, k, 0.0) == Approx(1.0).margin(1e-9));  // the surface is exact
            for (int d = 0; d < 3; ++d) {
                const double exact = std::exp(-k * depths[d]);
                if (exact >= 0.05) worst[d] = std::max(worst[d], std::abs(bandDecay(bands, k, depths[d]) / exact - 1.0));
            }
        }
        INFO(c.cascades << " cascade(s), cascade " << c.cascade << ": worst " << worst[0] << ", " << worst[1] << ", "
                        << worst[2] << " at 0.5, 1, 3 m");
        CHECK(worst[0] < c.worstHalf);
        CHECK(worst[1] < c.worstOne);
        CHECK(worst[2] < c.worstThree);
    }
    // The 5 m and 100 m waves 1 m down in the one-cascade sea (one factor: +191 % and −12 %).
    OceanDef def;
    def.resolution = 256;
    def.patch_size = 250.0f;
    const VelocityBands one = velocityBands(def.resolution, def.patch_size, cascadeBand(def, 0));
    for (const double wavelength : {5.0, 100.0}) {
        const double k = 2.0 * std::numbers::pi / wavelength;
        CHECK(bandDecay(one, k, 1.0) == Approx(std::exp(-k)).epsilon(0.02));
    }
}
