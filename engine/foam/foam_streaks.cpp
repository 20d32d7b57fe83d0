// The autocorrelation length of a coverage map along a direction (foam_streaks.h).
#include "foam/foam_streaks.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace ob::foam {

namespace {

// The correlation at lag (dx, dz) samples: ⟨g(p)·g(p + lag)⟩ over the pairs inside, g = f − f̄.
double lagCovariance(std::span<const float> f, int n, double mean, glm::dvec2 lag) {
    const double fx = std::floor(lag.x), fz = std::floor(lag.y);
    const int ox = int(fx), oz = int(fz);
    const double tx = lag.x - fx, tz = lag.y - fz;
    // p + lag's four samples (i + ox .. i + ox + 1, j + oz .. j + oz + 1) inside [0, n).
    const int iLo = std::max(0, -ox), iHi = std::min(n, n - 1 - ox);
    const int jLo = std::max(0, -oz), jHi = std::min(n, n - 1 - oz);
    double sum = 0.0;
    size_t count = 0;
    for (int j = jLo; j < jHi; ++j) {
        const float* row = f.data() + size_t(j) * size_t(n);
        const float* r0 = f.data() + size_t(j + oz) * size_t(n) + ox;
        const float* r1 = r0 + n;
        double rowSum = 0.0;
        for (int i = iLo; i < iHi; ++i) {
            const double partner = (1 - tz) * ((1 - tx) * r0[i] + tx * r0[i + 1]) + tz * ((1 - tx) * r1[i] + tx * r1[i + 1]);
            rowSum += (double(row[i]) - mean) * (partner - mean);
        }
        sum += rowSum;
        count += size_t(std::max(0, iHi - iLo));
    }
    return count > 0 ? sum / double(count) : 0.0;
}

// The map's mean and variance.
glm::dvec2 streakMeanVariance(std::span<const float> f) {
    double mean = 0.0;
    for (float v : f) mean += v;
    mean /= double(f.size());
    double variance = 0.0;
    for (float v : f) variance += (double(v) - mean) * (double(v) - mean);
    return {mean, variance / double(f.size())};
}

} // namespace

float autocorrelation(std::span<const float> f, int n, float cell, glm::vec2 direction, float lag) {
    const glm::dvec2 mv = streakMeanVariance(f);
    if (mv.y <= 0.0) return 0.0f;
    return float(lagCovariance(f, n, mv.x, glm::normalize(glm::dvec2(direction)) * double(lag / cell)) / mv.y);
}

float autocorrelationLength(std::span<const float> f, int n, float cell, glm::vec2 direction, float maxLag) {
    const glm::dvec2 mv = streakMeanVariance(f);
    const double mean = mv.x, variance = mv.y;
    if (variance <= 0.0) return 0.0f;
    const glm::dvec2 d = glm::normalize(glm::dvec2(direction));
    const double target = std::exp(-1.0);
    double before = 1.0;
    const int lags = int(std::ceil(maxLag / cell));
    for (int s = 1; s <= lags; ++s) {
        const double c = lagCovariance(f, n, mean, d * double(s)) / variance;
        if (c <= target) return float(cell * ((s - 1) + (before - target) / (before - c)));
        before = c;
    }
    return maxLag;
}

} // namespace ob::foam
