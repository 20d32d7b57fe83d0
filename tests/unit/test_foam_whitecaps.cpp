// The whitecap law from the wind (foam_whitecaps.h): the Jacobian's statistics against their
// closed forms on a sum of cosines, the threshold's tail share against the normal law, Monahan's
// W at its published points.
#include "foam/foam_whitecaps.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

using namespace ob::foam;

namespace {

// J = 1 + Σ a_m·cos(k_m·x + φ_m) on a periodic n×n tile of side L, M modes of distinct integer
// wave vectors spread over a disc of 23 × 29 (so the sample mean of each cos² is exactly ½, and
// the tile holds many independent patches for the tail).
struct Field {
    std::vector<float> j;
    double variance = 0.0, gradVariance = 0.0;
};
Field cosineField(int n, float tile, int modes) {
    Field f;
    f.j.assign(size_t(n) * size_t(n), 1.0f);
    uint64_t s = 12345;
    auto next = [&] { s = s * 6364136223846793005ull + 1442695040888963407ull; return double(s >> 11) / double(1ull << 53); };
    const double twoPi = 2.0 * std::numbers::pi;
    for (int m = 0; m < modes; ++m) {
        const int kx = 1 + (m * 7) % 23, kz = (m * 11) % 29 - 14;  // distinct for m < 667 (23·29), kx ≠ 0
        const double a = 0.02 * (0.5 + next()), phase = twoPi * next();
        f.variance += 0.5 * a * a;
        // central differences see sin(k_x·Δ)/Δ, not k_x
        const double d = double(tile) / n, gx = std::sin(twoPi * kx / n) / d, gz = std::sin(twoPi * kz / n) / d;
        f.gradVariance += 0.5 * a * a * (gx * gx + gz * gz);
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c)
                f.j[size_t(r) * size_t(n) + size_t(c)] += float(a * std::cos(twoPi * (kx * c + kz * r) / n + phase));
    }
    return f;
}

} // namespace

TEST_CASE("Monahan's whitecap fraction: about 1% at 10 m/s and 10% at 20 m/s", "[foam][whitecaps]") {
    CHECK(monahanFraction(10.0) == Approx(0.00987).epsilon(0.01));
    CHECK(monahanFraction(20.0) == Approx(0.1049).epsilon(0.01));
    CHECK(monahanFraction(0.0) == 0.0);
}

TEST_CASE("the Jacobian's statistics are the sum of cosines' closed forms", "[foam][whitecaps]") {
    const Field f = cosineField(128, 64.0f, 60);
    const JacobianStats s = jacobianStats(f.j, 128, 64.0f);
    CHECK(s.mean == Approx(1.0).margin(1e-5));
    CHECK(s.sigma == Approx(std::sqrt(f.variance)).epsilon(1e-4));
    CHECK(s.gradSigma == Approx(std::sqrt(f.gradVariance)).epsilon(1e-4));
}

TEST_CASE("the derived threshold leaves the normal law's tail below it, higher with more wind", "[foam][whitecaps]") {
    // 400 cosines of random phase: J is close to Gaussian, so the share of samples below
    // J_b = J̄ − a·σ is Φ(−a) (the time a point spends breaking, foam_whitecaps.h).
    const int n = 128;
    const Field f = cosineField(n, 64.0f, 400);
    const JacobianStats s = jacobianStats(f.j, n, 64.0f);
    double previousJ0 = -1e9;
    for (double wind : {8.0, 10.0, 14.0, 20.0}) {
        const WhitecapLaw law = deriveWhitecapLaw(s, wind, 9.81, 6.0);
        INFO("U10 = " << wind << ": a = " << law.a << ", J_b = " << law.j0);
        size_t below = 0;
        for (float v : f.j) below += v < law.j0 ? 1 : 0;
        const double tail = 0.5 * std::erfc(law.a / std::sqrt(2.0));
        // A finite sum of bounded cosines has lighter tails than the normal law beyond ~2.8σ;
        // up to there its share below J_b is within a factor 2 of Φ(−a).
        if (law.a < 2.8) {
            CHECK(double(below) / double(f.j.size()) > 0.5 * tail);
            CHECK(double(below) / double(f.j.size()) < 2.0 * tail);
        }
        CHECK(law.j0 > previousJ0);  // more wind, more of the sea breaks
        CHECK(law.rate > 0.0f);
        // the law's own coverage is Monahan's
        const double omega = std::sqrt(9.81 * s.gradSigma / s.sigma);
        CHECK(whitecapCoverage(law.a, omega, 6.0) == Approx(monahanFraction(wind)).epsilon(1e-6));
        previousJ0 = law.j0;
    }
    // A flat sea (J = 1 everywhere) or no wind: no whitecaps.
    CHECK(deriveWhitecapLaw(jacobianStats(std::vector<float>(size_t(n) * n, 1.0f), n, 64.0f), 20.0, 9.81, 6.0).rate == 0.0f);
    CHECK(deriveWhitecapLaw(s, 0.0, 9.81, 6.0).rate == 0.0f);
}
