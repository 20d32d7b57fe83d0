// The composite ocean hides the FFT tile's repetition ([Lee2007] §2.3): with the spectrum
// alone, the surface one tile (L) away is the same surface; with Gerstner swell and a
// second, non-commensurate cascade it is not.
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

namespace {

// RMS of h(x + L, z) − h(x, z) relative to the RMS of h, along a line of points.
double repetition(const std::string& scene) {
    const float L = 250.0f;  // ocean.patch_size of both scenes
    std::vector<float> pts;
    for (int i = 0; i < 200; ++i) pts.insert(pts.end(), {0.37f * float(i), 3.0f + 0.11f * float(i)});
    for (int i = 0; i < 200; ++i) pts.insert(pts.end(), {0.37f * float(i) + L, 3.0f + 0.11f * float(i)});
    std::string in = test::tempPath("line.npy"), out = test::tempPath("heights.npy");
    writeNpy(in, {400, 2}, pts.data());
    auto r = test::runOceanbox("dump surface " + scene + " --time 5 --points " + in + " --out " + out);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    NpyArray h = readNpy(out);
    double diff = 0.0, power = 0.0;
    for (size_t i = 0; i < 200; ++i) {
        double a = h.data[i * 5], b = h.data[(i + 200) * 5];
        diff += (a - b) * (a - b);
        power += a * a;
    }
    return std::sqrt(diff / power);
}

} // namespace

TEST_CASE("the spectrum alone repeats every tile, the composite sea does not", "[tiling]") {
    CHECK(repetition("config/scenes/spectrum_only.toml") < 1e-3);
    // Why 0.1: for a periodic part of power Pp plus a part uncorrelated with it that does not
    // repeat at L (the Gerstner swell, the second cascade) of power Pq, E[(h(x+L) − h(x))²] =
    // 2·Pq, so the ratio is √(2·Pq / (Pp + Pq)). 0.1 asks that at least 0.5 % of the surface's
    // power not repeat; a tiled sea gives 0 (above). No closed form gives Pq itself: it is the
    // spectrum's random draw. The default scene measures 0.19 (≈ 2 % of the power).
    CHECK(repetition("config/scenes/default.toml") > 0.1);
}
