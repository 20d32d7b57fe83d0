// Whitecaps from the wind (foam_whitecaps.h): Monahan's coverage through the Jacobian's statistics.
#include "foam/foam_whitecaps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ob::foam {

namespace {

double normalTail(double a) { return 0.5 * std::erfc(a / std::numbers::sqrt2); }   // Φ(−a)
double normalDensity(double a) { return std::exp(-0.5 * a * a) / std::sqrt(2.0 * std::numbers::pi); }
double riceRate(double a, double omega) { return omega / (2.0 * std::numbers::pi) * std::exp(-0.5 * a * a); }

// The gain fills an average episode this many times over, f → 1 − e^(−fill) (the source covers the
// share still open, 1 − f): a typical episode's core reaches 0.86, a deeper one nearer 1, and the
// coverage falls to 0 with the depth below J_b toward the rim (8 saturated every breaking
// sample at 1 a cell or two inside the rim: flat white patches with a step for an edge).
constexpr double EPISODE_FILL = 2.0;
// The share of t½ a fresh patch's samples stay over ½ on the map: its linear resampling spreads
// each patch by a variance α(1 − α)·Δ² a step and axis while the orbital velocity swings to and
// fro, so a patch a few cells across loses its peak before its decay would (measured on the
// default sea from 8 to 20 m/s: the samples over ½ were 0.45–0.6 of the unspread model while the
// mean coverage, which the resampling keeps, matched it; docs/splash_foam.md §2.1).
constexpr double PATCH_SPREAD = 0.5;

// How long, in decay times, an episode's foam stays over ½ on average: an episode of x times the
// mean's depth × duration leaves c = 1 − e^(−fill·x) and stays over ½ for τ·ln(2c) after (none
// for c ≤ ½); x taken as exponential of mean 1 (a Gaussian process's excursions over a high
// level: most are short and shallow, a few long and deep), averaged over 4096 of its quantiles.
// (fill 8: 0.58; the fill's 1 − e^(−fill) → 1 alone: ln 2 = 0.69.)
double whitecapOverHalf() {
    static const double mean = [] {
        constexpr int COUNT = 4096;
        double sum = 0.0;
        for (int q = 0; q < COUNT; ++q) {
            const double x = -std::log((q + 0.5) / COUNT);
            sum += std::max(0.0, std::log(2.0 * (1.0 - std::exp(-EPISODE_FILL * x))));
        }
        return sum / COUNT;
    }();
    return mean;
}

} // namespace

double monahanFraction(double windSpeed) { return 3.84e-6 * std::pow(std::max(windSpeed, 0.0), 3.41); }

JacobianStats jacobianStats(std::span<const float> j, int n, float tile) {
    JacobianStats s;
    if (n <= 0 || j.size() < size_t(n) * size_t(n)) return s;
    // Per row: the interior columns without wrapping (vectorisable), the two edge columns apart.
    double sum = 0.0, sum2 = 0.0, grad2 = 0.0;
    const double inv2d = double(n) / (2.0 * double(tile));
    for (int r = 0; r < n; ++r) {
        const float* row = &j[size_t(r) * size_t(n)];
        const float* up = &j[size_t((r + n - 1) % n) * size_t(n)];
        const float* down = &j[size_t((r + 1) % n) * size_t(n)];
        float rowSum = 0.0f, rowSum2 = 0.0f, rowGrad2 = 0.0f;
        for (int c = 0; c < n; ++c) {
            const float left = row[c == 0 ? n - 1 : c - 1], right = row[c == n - 1 ? 0 : c + 1];
            const float gx = right - left, gz = down[c] - up[c];
            rowSum += row[c], rowSum2 += row[c] * row[c], rowGrad2 += gx * gx + gz * gz;
        }
        sum += rowSum, sum2 += rowSum2, grad2 += double(rowGrad2) * inv2d * inv2d;
    }
    const double count = double(n) * double(n);
    s.mean = sum / count;
    s.sigma = std::sqrt(std::max(0.0, sum2 / count - s.mean * s.mean));
    s.gradSigma = std::sqrt(grad2 / count);
    return s;
}

double whitecapCoverage(double a, double omega, double decayS) {
    const double overHalf = decayS * whitecapOverHalf();
    return 1.0 - std::exp(-(normalTail(a) + riceRate(a, omega) * overHalf * PATCH_SPREAD));
}

double instantWhitecapJacobian(const JacobianStats& stats, double windSpeed) {
    const double target = std::min(monahanFraction(windSpeed), MAX_WHITECAP_FRACTION);
    if (stats.sigma < 1e-6 || target <= 0.0) return -std::numeric_limits<double>::infinity();
    double lo = 0.0, hi = 10.0;
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (normalTail(mid) > target ? lo : hi) = mid;
    }
    return stats.mean - 0.5 * (lo + hi) * stats.sigma;
}

WhitecapLaw deriveWhitecapLaw(const JacobianStats& stats, double windSpeed, double gravity, double decayS) {
    WhitecapLaw law;
    const double target = std::min(monahanFraction(windSpeed), MAX_WHITECAP_FRACTION);
    if (stats.sigma < 1e-6 || target <= 0.0) return law;
    const double omega = std::sqrt(gravity * stats.gradSigma / stats.sigma);
    // W(a) falls from W(0) ≥ 1 − e^(−½) to 0: bisection on [0, 10].
    double lo = 0.0, hi = 10.0;
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (whitecapCoverage(mid, omega, decayS) > target ? lo : hi) = mid;
    }
    const double a = 0.5 * (lo + hi);

    const double p = normalTail(a), nu = riceRate(a, omega);
    const double depth = stats.sigma * std::max(normalDensity(a) / std::max(p, 1e-300) - a, 1e-6);
    const double duration = p / std::max(nu, 1e-300);
    law.a = a;
    law.j0 = float(stats.mean - a * stats.sigma);
    law.rate = float(std::min(EPISODE_FILL / (depth * duration), 1e4));
    return law;
}

} // namespace ob::foam
