// `oceanbox ripple --model ewave` and the ewave scenes end to end (docs/references.md#dispersive-ripples, docs/references.md#contracts): one Fourier
// mode through the tool follows cos(K·X)·cos(ωt) with a standing velocity field too; bad
// flags exit 2; `dump ripples` writes the ewave height; the new scenes run and hash the same
// twice.
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

double omegaOf(double k) { return std::sqrt(9.81 * k + 7.4e-5 * k * k * k); }

} // namespace

TEST_CASE("ripple CLI, ewave: h = cos(kx), v = ω·sin(kx) step as the exact travelling wave cos(kx − ωt)", "[scenario][ripple][ewave]") {
    // h0 = cos(k·x), v0 = ω·sin(k·x): the wave cos(k·x − ωt) travelling towards +x.
    const int n = 16, m = 32, mode = 3;
    const double cell = 0.5, dt = 1.0 / 30.0;
    const int steps = 25;
    const double k = 2 * std::numbers::pi * mode / (m * cell), w = omegaOf(k);
    std::vector<float> h(n * m), v(n * m);
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < m; ++x) {
            h[size_t(z * m + x)] = float(std::cos(k * x * cell));
            v[size_t(z * m + x)] = float(w * std::sin(k * x * cell));
        }
    const std::string in = ob::test::tempPath("ew_in.npy"), vel = ob::test::tempPath("ew_vel.npy"),
                      out = ob::test::tempPath("ew_out.npy");
    ob::writeNpy(in, {size_t(n), size_t(m)}, h.data());
    ob::writeNpy(vel, {size_t(n), size_t(m)}, v.data());
    auto r = ob::test::runOceanbox("ripple --model ewave --in " + quoted(in) + " --vel " + quoted(vel) +
                                   " --steps 25 --dt 0.0333333333 --cell-size 0.5 --damping 0 --boundary periodic --out " +
                                   quoted(out));
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const ob::NpyArray a = ob::readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{size_t(n), size_t(m)});
    const double t = steps * double(float(dt));
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < m; ++x) REQUIRE(a.data[size_t(z * m + x)] == Approx(std::cos(k * x * cell - w * t)).margin(1e-4));
}

TEST_CASE("ripple CLI, ewave: bad flags exit 2 naming the flag", "[scenario][ripple][ewave]") {
    const std::string in = ob::test::tempPath("ew_in2.npy"), out = ob::test::tempPath("ew_out2.npy");
    const std::vector<float> h(16, 1.0f);
    ob::writeNpy(in, {4, 4}, h.data());
    for (auto [flags, word] : {std::pair{"--model ewave --dt 0", "--dt"}, std::pair{"--model ewave --boundary round", "--boundary"},
                               std::pair{"--model ewave --damping -1", "--damping"}, std::pair{"--model ewave --prev x.npy", "--prev"},
                               std::pair{"--model swe", "--model"}, std::pair{"--vel x.npy", "--vel"}}) {
        std::string damping = std::string(flags).find("--damping") == std::string::npos ? " --damping 1" : "";
        auto r = ob::test::runOceanbox("ripple " + std::string(flags) + " --in " + quoted(in) + " --steps 2" + damping +
                                       " --out " + quoted(out));
        INFO(flags << ": " << r.output);
        CHECK(r.exitCode == 2);
        CHECK(r.output.find(word) != std::string::npos);
    }
}

TEST_CASE("dump ripples writes the ewave height", "[scenario][ewave]") {
    // (The drop and wake scenes' same hash twice: test_scenes.cpp.)
    const std::string out = ob::test::tempPath("ew_dump.npy");
    auto r = ob::test::runOceanbox("dump ripples config/scenes/drop.toml --frames 150 --out " + quoted(out));
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    const ob::NpyArray a = ob::readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{512, 512});
    double peak = 0.0;
    for (float v : a.data) peak = std::max(peak, double(std::abs(v)));
    CHECK(peak > 1e-3);  // the ball (spawned at 1 s, falling 3 m) has hit the water by 150 steps (about 1.8 s)
}
