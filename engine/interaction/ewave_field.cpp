// Dispersive ripple field: exact per-mode rotation of (ĥ, v̂) with FFTW real-to-complex
// transforms (SPEC §2.5b; Tessendorf, "eWave", 2014), then the boundary in real space.
#include "interaction/ewave_field.h"

#include "core/error.h"
#include "core/parallel.h"
#include "interaction/ripple_field.h"
#include "ocean/fftw_wisdom.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <fftw3.h>
#include <numbers>
#include <string>

namespace ob::interaction {

namespace {

// Spectrum rows per parallel chunk: a chunk of fewer modes costs more to hand out than it saves.
constexpr int MIN_MODES_PER_CHUNK = 16384;
// The two transforms of a stage run on two workers from this many cells on; below it, waking
// a worker costs more than half the transforms (the ocean measured the same for N < 256).
constexpr size_t PARALLEL_MIN_CELLS = 256 * 256;
// Cap of a source's stagnation-pressure term, in g (see ewaveSource).
constexpr float MAX_DYNAMIC_G = 15.0f;

double* allocReal(size_t n) {
    double* p = fftw_alloc_real(n);
    if (!p) throw RuntimeError("out of memory for the ewave ripple field");
    std::memset(p, 0, n * sizeof(double));
    return p;
}

} // namespace

double EWaveField::omega(double k) { return std::sqrt(GRAVITY * k + SURFACE_TENSION * k * k * k); }

EWaveField::EWaveField(int rows, int cols, float cellSize, EWaveBoundary boundary, int spongeWidth)
    : m_rows(rows), m_cols(cols), m_specCols(cols / 2 + 1), m_cells(size_t(rows) * size_t(cols)),
      m_modes(size_t(rows) * size_t(cols / 2 + 1)), m_cellSize(cellSize), m_boundary(boundary) {
    assert(rows >= 2 && cols >= 2 && cellSize > 0.0f);
    m_h = allocReal(m_cells);
    m_v = allocReal(m_cells);
    m_hSpec = allocReal(2 * m_modes);
    m_vSpec = allocReal(2 * m_modes);
    // Planning may overwrite the arrays (FFTW_MEASURE): they hold nothing yet.
    auto* spec = reinterpret_cast<fftw_complex*>(m_hSpec);
    m_forward = ocean::planWithWisdomDouble(
        [&](unsigned flags) { return fftw_plan_dft_r2c_2d(rows, cols, m_h, spec, flags); });
    m_backward = ocean::planWithWisdomDouble(
        [&](unsigned flags) { return fftw_plan_dft_c2r_2d(rows, cols, spec, m_h, flags); });
    if (!m_forward || !m_backward)
        throw RuntimeError("FFTW could not plan a " + std::to_string(rows) + "×" + std::to_string(cols) + " transform");
    std::memset(m_h, 0, m_cells * sizeof(double));
    std::memset(m_hSpec, 0, 2 * m_modes * sizeof(double));
    m_hFloat.assign(m_cells, 0.0f);
    if (boundary == EWaveBoundary::Absorbing) m_spongeWidth = std::clamp(spongeWidth, 1, std::min(rows, cols) / 2);
    m_coef.resize(3 * m_modes);
}

EWaveField::~EWaveField() {
    {
        std::lock_guard<std::mutex> lock(ocean::fftwPlannerMutex());
        if (m_forward) fftw_destroy_plan(m_forward);
        if (m_backward) fftw_destroy_plan(m_backward);
    }
    fftw_free(m_h);
    fftw_free(m_v);
    fftw_free(m_hSpec);
    fftw_free(m_vSpec);
}

void EWaveField::setDamping(float decayTime, float viscosity) {
    assert(decayTime >= 0.0f && viscosity >= 0.0f);
    if (decayTime == m_decayTime && viscosity == m_viscosity) return;
    m_decayTime = decayTime;
    m_viscosity = viscosity;
    m_preparedDt = -1.0f;
}

EWaveField::ModeStep EWaveField::modeStep(double k, float dt, float decayTime, float viscosity, double scale) {
    const double dtd = dt;
    const double rate = decayTime > 0.0f ? 1.0 / double(decayTime) : 0.0;
    const double d = std::exp(-(rate + 2.0 * double(viscosity) * k * k) * dtd) * scale;
    if (k == 0.0) return {d, d * dtd, 0.0};
    const double w = omega(k);
    const double cs = std::cos(w * dtd), sn = std::sin(w * dtd);
    return {d * cs, d * sn / w, -d * w * sn};
}

// Sponge: friction γ = SPONGE_MAX_RATE·(1 − s_row·s_col) with RippleField's sin² profile s
// (0 at the outer ring, 1 from the band's inner edge, zero slope there, so the band starts
// without a step in the medium); each step multiplies h and v by exp(−γΔt). A wave that
// crosses the band twice (out, and back in through the periodic wrap) keeps little: 32
// cells of 0.25 m damp a 2 m wave (group speed 0.9 m/s) by e^-50 or so.
std::vector<float> EWaveField::spongeFactors(int rows, int cols, int spongeWidth, float dt) {
    const double dtd = dt;
    std::vector<float> sponge(size_t(rows) * size_t(cols), 1.0f);
    for (int z = 0; z < rows; ++z) {
        const float sz = RippleField::spongeFactor(std::min(z, rows - 1 - z), spongeWidth);
        for (int x = 0; x < cols; ++x) {
            const float sx = RippleField::spongeFactor(std::min(x, cols - 1 - x), spongeWidth);
            const double gamma = SPONGE_MAX_RATE * (1.0 - double(sz) * double(sx));
            sponge[size_t(z) * size_t(cols) + size_t(x)] = float(std::exp(-gamma * dtd));
        }
    }
    return sponge;
}

// Per mode (row j, column i of the r2c spectrum) the rotation by ωΔt times the damping and
// FFTW's 1/(rows·cols) (a power of two for power-of-two sides: exact). The sponge factors
// depend on Δt too: both are rebuilt when Δt or the damping changes.
void EWaveField::prepare(float dt) {
    const double norm = 1.0 / (double(m_rows) * double(m_cols));
    const double twoPi = 2.0 * std::numbers::pi;
    const double lx = double(m_cols) * m_cellSize, lz = double(m_rows) * m_cellSize;
    for (int j = 0; j < m_rows; ++j) {
        const int jj = j <= m_rows / 2 ? j : j - m_rows;
        const double kz = twoPi * jj / lz;
        for (int i = 0; i < m_specCols; ++i) {
            const double kx = twoPi * i / lx;
            const ModeStep s = modeStep(std::sqrt(kx * kx + kz * kz), dt, m_decayTime, m_viscosity, norm);
            double* c = &m_coef[3 * (size_t(j) * size_t(m_specCols) + size_t(i))];
            c[0] = s.a;
            c[1] = s.b;
            c[2] = s.c;
        }
    }
    m_sponge.clear();
    if (m_boundary == EWaveBoundary::Absorbing) m_sponge = spongeFactors(m_rows, m_cols, m_spongeWidth, dt);
    m_preparedDt = dt;
}

void EWaveField::step(float dt) {
    assert(dt > 0.0f);
    if (dt != m_preparedDt) prepare(dt);
    double* const real[2] = {m_h, m_v};
    double* const spec[2] = {m_hSpec, m_vSpec};
    const int pairChunk = m_cells >= PARALLEL_MIN_CELLS ? 1 : 2;  // 2: both on the calling thread
    // --- forward transforms, h and v each whole on one worker
    parallelFor(0, 2, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) fftw_execute_dft_r2c(m_forward, real[t], reinterpret_cast<fftw_complex*>(spec[t]));
    });
    // --- every mode rotated by ωΔt and damped
    const int minRows = std::max(1, MIN_MODES_PER_CHUNK / m_specCols);
    parallelFor(0, m_rows, minRows, [&](int j0, int j1) {
        const size_t m0 = size_t(j0) * size_t(m_specCols), m1 = size_t(j1) * size_t(m_specCols);
        double* __restrict hs = m_hSpec;
        double* __restrict vs = m_vSpec;
        const double* __restrict c = m_coef.data();
        for (size_t m = m0; m < m1; ++m) {
            const double a = c[3 * m], b = c[3 * m + 1], g = c[3 * m + 2];
            const double hr = hs[2 * m], hi = hs[2 * m + 1], vr = vs[2 * m], vi = vs[2 * m + 1];
            hs[2 * m] = a * hr + b * vr;
            hs[2 * m + 1] = a * hi + b * vi;
            vs[2 * m] = g * hr + a * vr;
            vs[2 * m + 1] = g * hi + a * vi;
        }
    });
    // --- inverse transforms (normalised by the coefficients)
    parallelFor(0, 2, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) fftw_execute_dft_c2r(m_backward, reinterpret_cast<fftw_complex*>(spec[t]), real[t]);
    });
    applyBoundary();
    syncHeight();
}

void EWaveField::syncHeight() {
    for (size_t i = 0; i < m_cells; ++i) m_hFloat[i] = float(m_h[i]);
}

void EWaveField::applyBoundary() {
    const int rows = m_rows, cols = m_cols;
    switch (m_boundary) {
    case EWaveBoundary::Periodic:
        return;
    case EWaveBoundary::Fixed:
        for (double* f : {m_h, m_v}) {
            std::fill(f, f + cols, 0.0);
            std::fill(f + size_t(rows - 1) * size_t(cols), f + m_cells, 0.0);
            for (int z = 0; z < rows; ++z) {
                f[size_t(z) * size_t(cols)] = 0.0;
                f[size_t(z) * size_t(cols) + size_t(cols - 1)] = 0.0;
            }
        }
        return;
    case EWaveBoundary::Absorbing: {
        // Only the band: rows in it whole, the other rows at their two ends.
        const int w = m_spongeWidth;
        auto scale = [&](size_t a, size_t b) {
            for (size_t i = a; i < b; ++i) {
                m_h[i] *= m_sponge[i];
                m_v[i] *= m_sponge[i];
            }
        };
        for (int z = 0; z < rows; ++z) {
            const size_t row = size_t(z) * size_t(cols);
            if (z < w || z >= rows - w) {
                scale(row, row + size_t(cols));
            } else {
                scale(row, row + size_t(w));
                scale(row + size_t(cols - w), row + size_t(cols));
            }
        }
        return;
    }
    }
}

void EWaveField::addSource(float gx, float gz, float radiusCells, float accel, float dt) {
    const float r = std::max(radiusCells, 1.0f);
    const int x0 = std::max(0, int(std::ceil(gx - r))), x1 = std::min(m_cols - 1, int(std::floor(gx + r)));
    const int z0 = std::max(0, int(std::ceil(gz - r))), z1 = std::min(m_rows - 1, int(std::floor(gz + r)));
    const double amount = double(accel) * double(dt);
    const double invR2 = 1.0 / (double(r) * double(r));
    for (int z = z0; z <= z1; ++z) {
        const double dz = double(z) - gz;
        const double dz2 = dz * dz * invR2;
        double* __restrict v = m_v + size_t(z) * size_t(m_cols);
        for (int x = x0; x <= x1; ++x) {
            const double dx = double(x) - gx;
            const double q = std::max(0.0, 1.0 - (dx * dx * invR2 + dz2));  // 1 − r²/R², 0 outside
            v[x] += amount * q * q;
        }
    }
}

void EWaveField::scroll(int dx, int dz) {
    if (dx == 0 && dz == 0) return;
    const int rows = m_rows, cols = m_cols;
    if (std::abs(dx) >= cols || std::abs(dz) >= rows) {
        clear();
        return;
    }
    const int xa = std::max(0, -dx), xb = std::min(cols, cols - dx);
    for (double* level : {m_h, m_v}) {
        auto shiftRow = [&](int z) {
            double* dst = level + size_t(z) * size_t(cols);
            const int sz = z + dz;
            if (sz < 0 || sz >= rows) {
                std::fill(dst, dst + cols, 0.0);
                return;
            }
            const double* src = level + size_t(sz) * size_t(cols);
            std::memmove(dst + xa, src + xa + dx, size_t(xb - xa) * sizeof(double));
            std::fill(dst, dst + xa, 0.0);
            std::fill(dst + xb, dst + cols, 0.0);
        };
        if (dz >= 0)
            for (int z = 0; z < rows; ++z) shiftRow(z);
        else
            for (int z = rows - 1; z >= 0; --z) shiftRow(z);
    }
    syncHeight();
}

EWaveSource ewaveSource(const RippleStamp& stamp, float gx, float gz, float cellSize, float verticalVelocity) {
    EWaveSource s;
    s.gx = gx;
    s.gz = gz;
    s.radiusCells = stamp.radiusCells;
    // heightScale = SD·SHR·Δ, so g·D/R = g·heightScale·SR/(SR·Δ) = g·SD·SHR; the stagnation
    // pressure ρ·v²/2 over the same patch adds v²/(2R), pushing the way SD points.
    const float sd = stamp.heightScale < 0.0f ? -1.0f : 1.0f;
    const float radius = std::max(stamp.radiusCells, 1.0f) * cellSize;
    const float hydrostatic = float(EWaveField::GRAVITY) * (stamp.heightScale / cellSize);
    // Capped at MAX_DYNAMIC_G·g: over a crossing of 2R/|v| the stagnation term gives the water
    // an impulse of about |v|, which for a fast ball (16 m/s) is a jet, not a ring; linear
    // waves cannot carry it (the default scene's cannonballs made 1.1 m spikes uncapped).
    const float dynamic = sd * std::min(verticalVelocity * verticalVelocity / (2.0f * radius),
                                        MAX_DYNAMIC_G * float(EWaveField::GRAVITY));
    s.accel = (hydrostatic + dynamic) * std::max(0.0f, 1.0f + stamp.accelerationFactor);
    return s;
}

void EWaveField::clear() {
    std::fill(m_h, m_h + m_cells, 0.0);
    std::fill(m_v, m_v + m_cells, 0.0);
    syncHeight();
}

} // namespace ob::interaction
