// The whitecap law from the wind (foam_whitecaps.h): the Jacobian's statistics against their
// closed forms on a sum of cosines, the threshold's tail share against the normal law, Monahan's
// W at its published points.
#include "foam/foam_whitecaps.h"
#include "foam/foam_map.h"

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

TEST_CASE("a whitecap's foam follows the depth of breaking: soft edges, no flat plateau", "[foam][whitecaps]") {
    // A sea of one crest direction, J = 1 − A·cos(k·x) (two waves over a 64 m tile, A = 0.6),
    // under 28 m/s (a cosine dips at most √2·σ below its mean: a storm to break), held still for the law's mean episode (duration P/ν, §2.1 of
    // docs/splash_foam.md) on a 0.25 m map without transport: the strips where J < J_b break.
    // Whitecap foam is a density of bubbles, not a cut-out: across a strip it should rise from
    // its rim with the depth of breaking (J_b − J) and keep varying inside, as a real whitecap
    // thins toward its edges. So: (1) it rises from 10% to 90% of the strip's peak over at least
    // a quarter of the strip's half-width w (the depth J_b − J itself does so over 0.64·w; a
    // step does it within a cell or two), and (2) halfway to the rim, where the depth is 0.73 of
    // the crest's, the coverage is below 0.95 of the peak (no flat white plateau; a clamp at 1
    // holds it at the peak).
    const int n = 64;
    const float tile = 64.0f, amplitude = 0.6f;
    const double k = 2.0 * std::numbers::pi * 2.0 / tile;
    std::vector<float> jac(size_t(n) * size_t(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) jac[size_t(j) * size_t(n) + size_t(i)] = float(1.0 - amplitude * std::cos(k * i * tile / n));
    const JacobianStats stats = jacobianStats(jac, n, tile);
    const WhitecapLaw law = deriveWhitecapLaw(stats, 28.0, 9.81, 6.0);
    const double omega = std::sqrt(9.81 * stats.gradSigma / stats.sigma);
    const double p = 0.5 * std::erfc(law.a / std::numbers::sqrt2), nu = omega / (2.0 * std::numbers::pi) * std::exp(-0.5 * law.a * law.a);
    const double duration = p / nu;

    FoamDef def;
    def.resolution = 256;
    def.wind_drift = 0.0f, def.streak_speed = 0.0f, def.ripple_weight = 0.0f;
    FoamMap map(def, tile, {tile / 2, tile / 2});  // x from 0 to 64 m
    FoamInputs in;
    in.jacobian = jac, in.jacobianN = n, in.jacobianTile = tile, in.windSpeed = 28.0f;
    const float dt = 1.0f / 60.0f;
    for (int s = 0; s < int(std::lround(duration / dt)); ++s) map.update(in, dt);

    // The strip around x = 0 (the crest at cos k·x = 1), on the map's middle row, x ≥ 0 (by
    // symmetry): its half-width w where J = J_b.
    const double w = std::acos((1.0 - double(law.j0)) / amplitude) / k;
    const ob::ScrollingGrid& g = map.grid();
    std::vector<std::pair<double, double>> profile;  // (x, coverage) for 0 ≤ x ≤ w
    double peak = 0.0;
    for (int i = 0; i < g.n; ++i) {
        const double x = g.origin().x + i * g.cell;
        if (x < 0.0 || x > w) continue;
        const double c = map.coverage()[size_t(g.n / 2) * size_t(g.n) + size_t(i)];
        profile.emplace_back(x, c);
        peak = std::max(peak, c);
    }
    double x10 = w, x90 = 0.0, half = 0.0;
    for (auto [x, c] : profile) {
        if (c >= 0.9 * peak) x90 = std::max(x90, x);
        if (c >= 0.1 * peak) x10 = x;  // the outermost sample over 10%
        if (x <= 0.5 * w) half = c;    // the last sample up to w/2
    }
    const double rim = x10 - x90;
    INFO("episode " << duration << " s, J_b " << law.j0 << ", strip half-width " << w << " m, peak " << peak << ", 10→90% over "
                    << rim << " m, halfway " << half);
    CHECK(peak > 0.5);
    CHECK(rim >= 0.25 * w);
    CHECK(half < 0.95 * peak);
}
