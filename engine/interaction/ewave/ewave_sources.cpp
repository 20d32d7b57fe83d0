// The ewave field's sources: the biweight bumps summed in float in row bands, and the Table 2
// stamp's pressure as an acceleration (ewave_sources.h).
#include "interaction/ewave/ewave_sources.h"

#include "core/parallel.h"
#include "core/simd.h"

#include <algorithm>
#include <cmath>

namespace ob::interaction {

namespace {

// Cap of a source's stagnation-pressure term, in g (see ewaveSource).
constexpr float MAX_DYNAMIC_G = 15.0f;

// One source over `rows` rows of n cells of the sources' sum (row stride `stride`): per row
// q = 1 − dz²/R² (dz = dz0 + row), then sum[x] += amount·max(0, q − dx2[x])², 0 outside the disc.
OB_VECTOR_KERNEL void sourceKernel(float* __restrict sum, size_t stride, int rows, float dz0, float invR2,
                                   const float* __restrict dx2, int n, float amount) {
    for (int r = 0; r < rows; ++r, sum += stride) {
        const float dz = dz0 + float(r);
        const float q = 1.0f - dz * dz * invR2;
        if (q <= 0.0f) continue;
        for (int x = 0; x < n; ++x) {
            const float w = std::max(0.0f, q - dx2[x]);  // 1 − r²/R²
            sum[x] += amount * w * w;
        }
    }
}

// v += the sources' sum, row by row, and the sum back to 0.
OB_VECTOR_KERNEL void applySumKernel(double* __restrict v, float* __restrict sum, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        v[i] += double(sum[i]);
        sum[i] = 0.0f;
    }
}

} // namespace

EWaveSources::EWaveSources(int rows, int cols) : m_rows(rows), m_cols(cols), m_sum(size_t(rows) * size_t(cols), 0.0f) {}

std::pair<int, int> EWaveSources::applyTo(double* v) {
    if (m_rows0 >= m_rows1) return {m_rows, 0};
    const std::pair<int, int> written{m_rows0, m_rows1};
    const size_t at = size_t(m_rows0) * size_t(m_cols);
    applySumKernel(v + at, m_sum.data() + at, size_t(m_rows1 - m_rows0) * size_t(m_cols));
    m_rows0 = m_rows;
    m_rows1 = 0;
    return written;
}

// Row bands [z0, z1) of the field on the workers, each applying every source's rows in it in
// list order: a cell receives its sources in the same order whatever the split, so the bits do
// not depend on it. Per source the column terms (x − gx)²/R² are computed once, then per row
// q = 1 − (z − gz)²/R² and v += amount·max(0, q − (x − gx)²/R²)² over the bounding square
// (the corners cost less as multiply-adds than finding the disc's ends per row).
void EWaveSources::add(std::span<const EWaveSource> sources, float dt) {
    size_t work = 0;  // cells in the sources' bounding squares
    for (const EWaveSource& s : sources) {
        const float r = std::max(s.radiusCells, 1.0f);
        work += size_t(2.0 * r + 1.0) * size_t(2.0 * r + 1.0);
        m_rows0 = std::min(m_rows0, std::max(0, int(std::ceil(s.gz - r))));
        m_rows1 = std::max(m_rows1, std::min(m_rows, int(std::floor(s.gz + r)) + 1));
    }
    const int minRows = m_threads > 1 && work >= PARALLEL_MIN_CELLS ? std::max(1, m_rows / 16) : m_rows;
    parallelFor(0, m_rows, minRows, [&](int band0, int band1) {
        thread_local std::vector<float> dx2;
        dx2.resize(size_t(m_cols));
        for (const EWaveSource& s : sources) {
            const float r = std::max(s.radiusCells, 1.0f);
            const int z0 = std::max(band0, int(std::ceil(s.gz - r))), z1 = std::min(band1 - 1, int(std::floor(s.gz + r)));
            const int x0 = std::max(0, int(std::ceil(s.gx - r))), x1 = std::min(m_cols - 1, int(std::floor(s.gx + r)));
            if (z0 > z1 || x0 > x1) continue;
            const float invR2 = 1.0f / (r * r);
            for (int x = x0; x <= x1; ++x) {
                const float dx = float(x) - s.gx;
                dx2[size_t(x - x0)] = dx * dx * invR2;
            }
            sourceKernel(m_sum.data() + size_t(z0) * size_t(m_cols) + size_t(x0), size_t(m_cols), z1 - z0 + 1,
                         float(z0) - s.gz, invR2, dx2.data(), x1 - x0 + 1, s.accel * dt);
        }
    });
}

EWaveSource ewaveSource(const RippleStamp& stamp, float gx, float gz, float cellSize, float gravity, float verticalVelocity) {
    EWaveSource s;
    s.gx = gx;
    s.gz = gz;
    s.radiusCells = stamp.radiusCells;
    // heightScale = SD·SHR·Δ, so g·D/R = g·heightScale·SR/(SR·Δ) = g·SD·SHR; the stagnation
    // pressure ρ·v²/2 over the same patch adds v²/(2R), pushing the way SD points.
    const float sd = stamp.heightScale < 0.0f ? -1.0f : 1.0f;
    const float radius = std::max(stamp.radiusCells, 1.0f) * cellSize;
    const float hydrostatic = gravity * (stamp.heightScale / cellSize);
    // Capped at MAX_DYNAMIC_G·g: over a crossing of 2R/|v| the stagnation term gives the water
    // an impulse of about |v|, which for a fast ball (16 m/s) is a jet, not a ring; linear
    // waves cannot carry it (the default scene's cannonballs made 1.1 m spikes uncapped).
    const float dynamic = sd * std::min(verticalVelocity * verticalVelocity / (2.0f * radius),
                                        MAX_DYNAMIC_G * gravity);
    s.accel = (hydrostatic + dynamic) * std::max(0.0f, 1.0f + stamp.accelerationFactor);
    return s;
}

} // namespace ob::interaction
