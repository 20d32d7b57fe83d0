// Velocity bands: knots evenly in √k, per-mode weights by a constrained least-squares fit of
// e^{−k·depth} over the probes' depths (docs/velocity_bands.md).
#include "ocean/velocity_bands.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace ob::ocean {

namespace {

// Depths the fit samples, evenly over [0, VELOCITY_FIT_DEPTH].
constexpr int FIT_SAMPLES = 31;
// The fit weighs a depth's residual by 1/(e^{−k·depth} + FIT_FLOOR)²: relative where the mode
// still moves, absolute (in units of 5 % of its surface velocity) where it has died away.
constexpr double FIT_FLOOR = 0.05;
// Weights are tabulated at this many points in √k and read linearly (they vary smoothly).
constexpr int TABLE_POINTS = 1024;

// Solves the n × n system a·x = b in place (partial pivoting); n ≤ MAX_BANDS + 1.
void solve(double a[][VelocityBands::MAX_BANDS + 1], double* b, int n) {
    for (int c = 0; c < n; ++c) {
        int p = c;
        for (int r = c + 1; r < n; ++r)
            if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
        for (int j = 0; j < n; ++j) std::swap(a[c][j], a[p][j]);
        std::swap(b[c], b[p]);
        for (int r = 0; r < n; ++r) {
            if (r == c) continue;
            const double f = a[r][c] / a[c][c];
            for (int j = c; j < n; ++j) a[r][j] -= f * a[c][j];
            b[r] -= f * b[c];
        }
    }
    for (int c = 0; c < n; ++c) b[c] /= a[c][c];
}

// Knots for the modes from kLow to kHigh, rad/m.
void placeKnots(VelocityBands& bands, double kLow, double kHigh) {
    const double a = std::sqrt(kLow), b = std::sqrt(std::min(kHigh, VELOCITY_FIT_CAP));
    if (b <= a) {  // every mode at or above the cap: one band at the longest
        bands.count = 1;
        bands.k[0] = float(kLow);
        return;
    }
    bands.count = std::clamp(int(std::ceil((b - a) / VELOCITY_KNOT_SPACING + 0.5)), 1, VelocityBands::MAX_BANDS);
    if (bands.count == 1) {
        bands.k[0] = float(0.25 * (a + b) * (a + b));
        return;
    }
    // The first knot half a gap above the longest wave, the last at the cap (or the shortest).
    const double gap = (b - a) / (bands.count - 0.5);
    for (int j = 0; j < bands.count; ++j) {
        const double s = a + (j + 0.5) * gap;
        bands.k[size_t(j)] = float(s * s);
    }
}

} // namespace

void bandWeights(const VelocityBands& bands, double k, std::span<double> out) {
    const int n = bands.count;
    assert(int(out.size()) >= n);
    if (n == 1) {
        out[0] = 1.0;
        return;
    }
    // Normal equations of the weighted fit with Σ g_b = 1 as a Lagrange row.
    double a[VelocityBands::MAX_BANDS + 1][VelocityBands::MAX_BANDS + 1] = {};
    double r[VelocityBands::MAX_BANDS + 1] = {};
    for (int s = 0; s < FIT_SAMPLES; ++s) {
        const double d = VELOCITY_FIT_DEPTH * s / (FIT_SAMPLES - 1);
        const double exact = std::exp(-k * d);
        const double w = 1.0 / ((exact + FIT_FLOOR) * (exact + FIT_FLOOR));
        double f[VelocityBands::MAX_BANDS];
        for (int b = 0; b < n; ++b) f[b] = std::exp(-double(bands.k[size_t(b)]) * d);
        for (int i = 0; i < n; ++i) {
            r[i] += w * f[i] * exact;
            for (int j = 0; j < n; ++j) a[i][j] += w * f[i] * f[j];
        }
    }
    for (int i = 0; i < n; ++i) a[i][n] = a[n][i] = 1.0;
    r[n] = 1.0;
    solve(a, r, n + 1);
    for (int b = 0; b < n; ++b) out[size_t(b)] = r[b];
}

double bandDecay(const VelocityBands& bands, double k, double depth) {
    double g[VelocityBands::MAX_BANDS];
    bandWeights(bands, k, g);
    double sum = 0.0;
    for (int b = 0; b < bands.count; ++b) sum += g[b] * std::exp(-double(bands.k[size_t(b)]) * depth);
    return sum;
}

VelocityBands velocityBands(int resolution, double patchSize, WaveBand band) {
    VelocityBands bands;
    const double dk = 2.0 * std::numbers::pi / patchSize;
    const int half = resolution / 2;
    const double shortest = dk * (half - 1) * std::numbers::sqrt2;  // the corner mode (no Nyquist wave)
    placeKnots(bands, std::max(band.kMin, dk), std::min(band.kMax, shortest));
    bands.quarter = half + 1;
    const int mapped = bands.mappedBands();
    if (mapped == 0) return bands;

    // The fit at TABLE_POINTS points in √k up to the Nyquist corner, then per mode.
    const double top = std::sqrt(dk * half * std::numbers::sqrt2), step = top / (TABLE_POINTS - 1);
    std::vector<double> table(size_t(TABLE_POINTS) * size_t(mapped));
    double g[VelocityBands::MAX_BANDS];
    for (int t = 0; t < TABLE_POINTS; ++t) {
        const double s = t * step;
        bandWeights(bands, s * s, g);
        std::copy_n(g, mapped, table.begin() + ptrdiff_t(t) * mapped);
    }
    const size_t plane = size_t(bands.quarter) * size_t(bands.quarter);
    bands.weights.resize(plane * size_t(mapped));
    for (int m = 0; m <= half; ++m)
        for (int n = 0; n <= half; ++n) {
            const double u = std::sqrt(dk * std::hypot(double(n), double(m))) / step;
            const int t = std::min(int(u), TABLE_POINTS - 2);
            const double f = u - t;
            const size_t at = size_t(m) * size_t(bands.quarter) + size_t(n);
            for (int b = 0; b < mapped; ++b)
                bands.weights[size_t(b) * plane + at] =
                    float((1.0 - f) * table[size_t(t) * mapped + size_t(b)] + f * table[size_t(t + 1) * mapped + size_t(b)]);
        }
    return bands;
}

} // namespace ob::ocean
