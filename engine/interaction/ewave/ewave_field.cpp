// Dispersive ripple field: exact per-mode rotation of (ĥ, v̂) with FFTW real-to-complex
// transforms of the step's change (docs/references.md#dispersive-ripples; Tessendorf, "eWave", 2014), then the boundary
// in real space.
#include "interaction/ewave/ewave_field.h"

#include "core/scrolling_grid.h"

#include "core/error.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "core/thread_choice.h"
#include "interaction/sponge.h"
#include "core/fftw_wisdom.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <fftw3.h>
#include <numbers>
#include <string>

namespace ob::interaction {

namespace {

// The two transforms of a stage may run on two workers (measured: chooseThreads) from this
// many cells on; below it, waking a worker costs more than half the transforms.
constexpr size_t PARALLEL_MIN_CELLS = 128 * 128;
// Sources are split over the workers in row bands from this many cells of footprint on (a
// hundred SR-20 spheres; a band's hand-off costs about as much as a few thousand cells).
constexpr size_t PARALLEL_MIN_SOURCE_CELLS = 1 << 17;
// Cap of a source's stagnation-pressure term, in g (see ewaveSource).
constexpr float MAX_DYNAMIC_G = 15.0f;

double* allocReal(size_t n) {
    double* p = fftw_alloc_real(n);
    if (!p) throw RuntimeError("out of memory for the ewave ripple field");
    std::memset(p, 0, n * sizeof(double));
    return p;
}

// FFTW's allocation, so every array has the alignment the plans were made for.
float* allocFloat(size_t n) {
    float* p = fftwf_alloc_real(n);
    if (!p) throw RuntimeError("out of memory for the ewave ripple field");
    std::memset(p, 0, n * sizeof(float));
    return p;
}

// state → float for the forward transform.
OB_VECTOR_KERNEL void toFloatKernel(float* __restrict out, const double* __restrict f, size_t n) {
    for (size_t i = 0; i < n; ++i) out[i] = float(f[i]);
}

// Both fields' change over n modes, in place, in double: with (a − 1, b, c) = coef[3m..3m + 2],
// ĥ ← (a − 1)·ĥ + b·v̂ and v̂ ← c·ĥ + (a − 1)·v̂, for the real and imaginary parts alike.
OB_VECTOR_KERNEL void changeKernel(float* __restrict hs, float* __restrict vs, const double* __restrict coef, int n) {
    for (int m = 0; m < n; ++m) {
        const double am1 = coef[3 * m], b = coef[3 * m + 1], c = coef[3 * m + 2];
        for (int p = 0; p < 2; ++p) {
            const double h = hs[2 * m + p], v = vs[2 * m + p];
            hs[2 * m + p] = float(am1 * h + b * v);
            vs[2 * m + p] = float(c * h + am1 * v);
        }
    }
}

// One spectrum row of n modes (SPEC §2.5c): the new state's ĥ', v̂' = scale·(ĥ, v̂) + their change
// (coef's a − 1, b, c as changeKernel, which carry `scale`; coef null: no change, the state as it
// is), then û = i·K·r·v̂' into ux, uz and, when xx is not null, ξ̂ = i·K·r·ĥ' into xx, xz, with
// K = (kx[m], kz) and r = riesz[m] = 1/(|K|·tanh(|K|d)); power[m] = weight[m]·|v̂'|² (weight: the
// mode's count in the full spectrum; the caller zeroes K = 0's and sums: sumsKernel).
// Multiplying by i: (re, im) → (−im, re).
OB_VECTOR_KERNEL void horizontalKernel(const float* __restrict hs, const float* __restrict vs,
                                       const double* __restrict coef, double scale, const float* __restrict riesz,
                                       const float* __restrict kx, const float* __restrict weight, float kz,
                                       float* __restrict ux, float* __restrict uz, float* __restrict xx,
                                       float* __restrict xz, float* __restrict power, int n) {
    if (coef) {
        for (int m = 0; m < n; ++m) {
            const double am1 = coef[3 * m], c = coef[3 * m + 2];
            const float n0 = float(scale * vs[2 * m] + (c * hs[2 * m] + am1 * vs[2 * m]));
            const float n1 = float(scale * vs[2 * m + 1] + (c * hs[2 * m + 1] + am1 * vs[2 * m + 1]));
            const float mx = kx[m] * riesz[m], mz = kz * riesz[m];
            ux[2 * m] = -mx * n1;
            ux[2 * m + 1] = mx * n0;
            uz[2 * m] = -mz * n1;
            uz[2 * m + 1] = mz * n0;
            power[m] = weight[m] * (n0 * n0 + n1 * n1);
        }
    } else {
        const float sc = float(scale);
        for (int m = 0; m < n; ++m) {
            const float n0 = sc * vs[2 * m], n1 = sc * vs[2 * m + 1];
            const float mx = kx[m] * riesz[m], mz = kz * riesz[m];
            ux[2 * m] = -mx * n1;
            ux[2 * m + 1] = mx * n0;
            uz[2 * m] = -mz * n1;
            uz[2 * m + 1] = mz * n0;
            power[m] = weight[m] * (n0 * n0 + n1 * n1);
        }
    }
    if (!xx) return;
    for (int m = 0; m < n; ++m) {
        double h0 = scale * hs[2 * m], h1 = scale * hs[2 * m + 1];
        if (coef) {
            h0 += coef[3 * m] * hs[2 * m] + coef[3 * m + 1] * vs[2 * m];
            h1 += coef[3 * m] * hs[2 * m + 1] + coef[3 * m + 1] * vs[2 * m + 1];
        }
        const float mx = kx[m] * riesz[m], mz = kz * riesz[m];
        xx[2 * m] = float(-mx * h1);
        xx[2 * m + 1] = float(mx * h0);
        xz[2 * m] = float(-mz * h1);
        xz[2 * m + 1] = float(mz * h0);
    }
}

// changeKernel and the horizontal velocity's spectra in one pass over a spectrum row (the step
// without the displacement): with Δĥ, Δv̂ as changeKernel makes them, the new state's v̂' =
// scale·v̂ + Δv̂ (the coefficients carry `scale`, 1/(rows·cols)), û = i·K·r·v̂' into ux, uz as
// horizontalKernel, and power[m] = w·|v̂'|² (the caller zeroes K = 0's), the reduction left to
// sumsKernel: no branch and no reduction, so this loop vectorises.
OB_VECTOR_KERNEL void changeVelocityKernel(float* __restrict hs, float* __restrict vs, const double* __restrict coef,
                                           double scale, const float* __restrict riesz, const float* __restrict kx,
                                           const float* __restrict weight, float kz, float* __restrict ux,
                                           float* __restrict uz, float* __restrict power, int n) {
    for (int m = 0; m < n; ++m) {
        const double am1 = coef[3 * m], b = coef[3 * m + 1], c = coef[3 * m + 2];
        const double h0 = hs[2 * m], h1 = hs[2 * m + 1], v0 = vs[2 * m], v1 = vs[2 * m + 1];
        const double dv0 = c * h0 + am1 * v0, dv1 = c * h1 + am1 * v1;
        hs[2 * m] = float(am1 * h0 + b * v0);
        hs[2 * m + 1] = float(am1 * h1 + b * v1);
        vs[2 * m] = float(dv0);
        vs[2 * m + 1] = float(dv1);
        const float n0 = float(scale * v0 + dv0), n1 = float(scale * v1 + dv1);
        const float r = riesz[m];
        const float mx = kx[m] * r, mz = kz * r;
        ux[2 * m] = -mx * n1;
        ux[2 * m + 1] = mx * n0;
        uz[2 * m] = -mz * n1;
        uz[2 * m + 1] = mz * n0;
        power[m] = weight[m] * (n0 * n0 + n1 * n1);
    }
}

// sums[0] = Σ kabs[m]·power[m], sums[1] = Σ power[m] over a row, in float (a row's sum to ~1e-6
// of itself, ample for a mean wavenumber), reassociated into vector lanes: the order is fixed by
// the code the clone was built with, so the bits do not depend on the workers; only this
// reduction is relaxed, never the state's arithmetic.
#if defined(__GNUC__) && !defined(__clang__)
#define OB_RELAXED_SUM __attribute__((optimize("associative-math", "no-signed-zeros", "no-trapping-math")))
#else
#define OB_RELAXED_SUM
#endif
OB_RELAXED_SUM OB_VECTOR_KERNEL void sumsKernel(const float* __restrict power, const float* __restrict kabs, int n, double* __restrict sums) {
    float num = 0.0f, den = 0.0f;
    for (int m = 0; m < n; ++m) {
        num += kabs[m] * power[m];
        den += power[m];
    }
    sums[0] = num;
    sums[1] = den;
}

// f += change, then its float copy (before the boundary: the caller redoes the band's).
OB_VECTOR_KERNEL void addKernel(double* __restrict f, float* __restrict copy, const float* __restrict change, int n) {
    for (int i = 0; i < n; ++i) {
        f[i] += double(change[i]);
        copy[i] = float(f[i]);
    }
}

// f relaxed towards `level` by factor (the sponge: f − level scaled), and its float copy.
OB_VECTOR_KERNEL void scaleKernel(double* __restrict f, float* __restrict copy, const float* __restrict factor, int n,
                                  double level) {
    for (int i = 0; i < n; ++i) {
        f[i] = (f[i] - level) * double(factor[i]) + level;
        copy[i] = float(f[i]);
    }
}

// Σ f in double, in index order (the same bits whatever the workers did before).
double sumKernel(const double* f, size_t n) {
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i) sum += f[i];
    return sum;
}

// f += shift, and its float copy.
OB_VECTOR_KERNEL void shiftKernel(double* __restrict f, float* __restrict copy, double shift, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        f[i] += shift;
        copy[i] = float(f[i]);
    }
}

} // namespace

// Finite depth (Lamb §228): the gravity-capillary restoring force times tanh(k·d); deep water
// (d = 0, or k·d past 20 where tanh is 1 to 1e-17) skips it.
double EWaveMedium::omega(double k) const {
    const double deep = gravity * k + capillarity * k * k * k;
    return std::sqrt(depth > 0.0 && k * depth < 20.0 ? deep * std::tanh(k * depth) : deep);
}

EWaveField::EWaveField(int rows, int cols, float cellSize, RippleBoundary boundary, int spongeWidth)
    : m_rows(rows), m_cols(cols), m_specCols(cols / 2 + 1), m_cells(size_t(rows) * size_t(cols)),
      m_modes(size_t(rows) * size_t(cols / 2 + 1)), m_cellSize(cellSize), m_boundary(boundary) {
    assert(rows >= 2 && cols >= 2 && cellSize > 0.0f);
    m_h = allocReal(m_cells);
    m_v = allocReal(m_cells);
    for (int t = 0; t < 2; ++t) {
        m_float[t] = allocFloat(m_cells);
        m_spec[t] = allocFloat(2 * m_modes);
        m_change[t] = allocFloat(m_cells);
    }
    // Planning may overwrite the arrays (FFTW_MEASURE): they hold nothing yet. The forward
    // transform keeps its input (r2c's default): it reads the float copies of the state.
    m_forward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_r2c_2d(rows, cols, m_float[0], reinterpret_cast<fftwf_complex*>(m_spec[0]), flags);
    });
    m_backward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_c2r_2d(rows, cols, reinterpret_cast<fftwf_complex*>(m_spec[0]), m_change[0], flags);
    });
    if (!m_forward || !m_backward)
        throw RuntimeError("FFTW could not plan a " + std::to_string(rows) + "×" + std::to_string(cols) + " transform");
    std::memset(m_float[0], 0, m_cells * sizeof(float));  // planning wrote into them
    std::memset(m_float[1], 0, m_cells * sizeof(float));
    if (boundary == RippleBoundary::Absorbing) m_spongeWidth = std::clamp(spongeWidth, 1, std::min(rows, cols) / 2);
    m_coef.resize(3 * size_t(m_rows / 2 + 1) * size_t(m_specCols));
    for (int f = 0; f < 4; ++f) {
        m_horiz[f] = allocFloat(m_cells);
        m_horizSpec[f] = allocFloat(2 * m_modes);
    }
    m_rowSums.assign(2 * size_t(m_rows), 0.0);
    m_power.assign(m_modes, 0.0f);
    prepareHorizontal();
    m_sourceSum.assign(m_cells, 0.0f);
    chooseThreads();
}

// Both choices measured on this field while it is still 0 (a step of zeros costs what any step
// costs and leaves zeros; the sources' velocity is cleared after), kept per size.
void EWaveField::chooseThreads() {
    const std::string size = std::to_string(m_rows) + "x" + std::to_string(m_cols);
    if (m_cells >= PARALLEL_MIN_CELLS) {
        const float dt = 1.0f / 60.0f;
        m_stepThreads = measuredThreads("ewave step " + size, std::min(2, workerCount()), [&](int n) {
            m_stepThreads = n;
            step(dt);
        });
        m_preparedDt = -1.0f;
    }
    // Sources of 20 cells (or a quarter of the field) in a lattice, PARALLEL_MIN_SOURCE_CELLS of
    // footprint in all: the smallest batch the bands are split for.
    const float r = std::min(20.0f, float(std::min(m_rows, m_cols)) / 4.0f);
    const size_t count = PARALLEL_MIN_SOURCE_CELLS / size_t((2.0f * r + 1.0f) * (2.0f * r + 1.0f)) + 1;
    std::vector<EWaveSource> batch(count);
    for (size_t i = 0; i < count; ++i)
        batch[i] = {float((i * 37) % size_t(m_cols)), float((i * 61) % size_t(m_rows)), r, 1.0f};
    m_sourceThreads = measuredThreads("ewave sources " + size, workerCount(), [&](int n) {
        m_sourceThreads = n;
        addSources(batch, 1.0f / 60.0f);
    });
    clear();
}

EWaveField::~EWaveField() {
    {
        std::lock_guard<std::mutex> lock(ocean::fftwPlannerMutex());
        if (m_forward) fftwf_destroy_plan(m_forward);
        if (m_backward) fftwf_destroy_plan(m_backward);
    }
    fftw_free(m_h);
    fftw_free(m_v);
    for (int t = 0; t < 2; ++t) {
        fftwf_free(m_float[t]);
        fftwf_free(m_spec[t]);
        fftwf_free(m_change[t]);
    }
    for (int f = 0; f < 4; ++f) {
        fftwf_free(m_horiz[f]);
        fftwf_free(m_horizSpec[f]);
    }
}

void EWaveField::setMedium(const EWaveMedium& medium) {
    assert(medium.gravity > 0.0 && medium.capillarity >= 0.0);
    m_medium = medium;
    m_preparedDt = -1.0f;
    prepareHorizontal();
}

// Per mode of rows 0..rows/2 (row rows − j has row j's |K|) r = 1/(|K|·tanh(|K|d)) (deep water, or
// |K|·d past 20: 1/|K|), 0 at K = 0; per column kx, 0 at the Nyquist column (its ±kx are one mode
// of a real field, whose derivative there is taken as 0; kz likewise in horizontalRow); per
// column the count of the full spectrum's modes it stands for (the half spectrum's inner columns
// stand for K and −K).
void EWaveField::prepareHorizontal() {
    const double twoPi = 2.0 * std::numbers::pi;
    const double lx = double(m_cols) * m_cellSize, lz = double(m_rows) * m_cellSize;
    m_kx.assign(size_t(m_specCols), 0.0f);
    m_weight.assign(size_t(m_specCols), 2.0f);
    for (int i = 0; i < m_specCols; ++i) m_kx[size_t(i)] = 2 * i == m_cols ? 0.0f : float(twoPi * i / lx);
    m_weight[0] = 1.0f;
    if (m_cols % 2 == 0) m_weight[size_t(m_cols / 2)] = 1.0f;
    const size_t modes = size_t(m_rows / 2 + 1) * size_t(m_specCols);
    m_riesz.assign(modes, 0.0f);
    m_kabs.assign(modes, 0.0f);
    const double d = m_medium.depth;
    for (int j = 0; j <= m_rows / 2; ++j) {
        const double kz = twoPi * j / lz;
        for (int i = 0; i < m_specCols; ++i) {
            const double kx = twoPi * i / lx;
            const double k = std::sqrt(kx * kx + kz * kz);
            const size_t m = size_t(j) * size_t(m_specCols) + size_t(i);
            m_kabs[m] = float(k);
            if (k > 0.0) m_riesz[m] = float(1.0 / (d > 0.0 && k * d < 20.0 ? k * std::tanh(k * d) : k));
        }
    }
}

void EWaveField::keepHorizontalDisplacement(bool on) {
    m_displacement = on;
    if (!on)
        for (int f = 2; f < 4; ++f) std::memset(m_horiz[f], 0, m_cells * sizeof(float));
}

// Spectrum row j (the step's: before changeRows turns it into the change; `change` false: the
// state as transformed) into the horizontal fields' spectra and its sums of velocityWavenumber.
// kz = 2π·(j or j − rows)/(rows·Δ), 0 at the Nyquist row.
void EWaveField::horizontalRow(int j, bool change) {
    const size_t row = size_t(j) * size_t(m_specCols);
    const size_t coefRow = size_t(std::min(j, m_rows - j)) * size_t(m_specCols);
    float* power = m_power.data() + row;
    horizontalKernel(m_spec[0] + 2 * row, m_spec[1] + 2 * row, change ? m_coef.data() + 3 * coefRow : nullptr,
                     1.0 / (double(m_rows) * double(m_cols)), m_riesz.data() + coefRow, m_kx.data(), m_weight.data(),
                     rowKz(j), m_horizSpec[0] + 2 * row, m_horizSpec[1] + 2 * row,
                     m_displacement ? m_horizSpec[2] + 2 * row : nullptr, m_displacement ? m_horizSpec[3] + 2 * row : nullptr,
                     power, m_specCols);
    if (j == 0) power[0] = 0.0f;  // K = 0: the mean, no wave (its û is 0: r = 0)
    sumsKernel(power, m_kabs.data() + coefRow, m_specCols, m_rowSums.data() + 2 * size_t(j));
}

// kz of spectrum row j: 2π·(j, or j − rows past the middle)/(rows·Δ), rad/m; 0 at the Nyquist
// row (its ±kz are one mode of a real field).
float EWaveField::rowKz(int j) const {
    const int signedJ = j <= m_rows / 2 ? j : j - m_rows;
    return 2 * j == m_rows ? 0.0f : float(2.0 * std::numbers::pi * signedJ / (double(m_rows) * m_cellSize));
}

void EWaveField::setDamping(float decayTime, float viscosity) {
    assert(decayTime >= 0.0f && viscosity >= 0.0f);
    if (decayTime == m_decayTime && viscosity == m_viscosity) return;
    m_decayTime = decayTime;
    m_viscosity = viscosity;
    m_preparedDt = -1.0f;
}

// Amplitude damping over dt: exp(−(1/τ + 2·ν·k²)·dt), ν the medium's viscosity plus the extra one.
static double dampingExponent(const EWaveMedium& medium, double k, float dt, float decayTime, float viscosity) {
    const double rate = decayTime > 0.0f ? 1.0 / double(decayTime) : 0.0;
    return -(rate + 2.0 * (medium.viscosity + double(viscosity)) * k * k) * double(dt);
}

EWaveField::ModeStep EWaveField::modeStep(const EWaveMedium& medium, double k, float dt, float decayTime, float viscosity, double scale) {
    if (k == 0.0) return {scale, 0.0, 0.0};  // the volume: kept, not damped (v̂(0) is dropped by the step)
    const double dtd = dt;
    const double d = std::exp(dampingExponent(medium, k, dt, decayTime, viscosity)) * scale;
    const double w = medium.omega(k);
    const double cs = std::cos(w * dtd), sn = std::sin(w * dtd);
    return {d * cs, d * sn / w, -d * w * sn};
}

// d·cos θ − 1 = (d − 1)·cos θ − 2·sin²(θ/2): no cancellation for the small θ and 1 − d of
// long waves, whose change is the whole point.
double EWaveField::modeStepMinusOne(const EWaveMedium& medium, double k, float dt, float decayTime, float viscosity,
                                    double scale) {
    if (k == 0.0) return 0.0;
    const double dtd = dt;
    const double dm1 = std::expm1(dampingExponent(medium, k, dt, decayTime, viscosity));
    const double half = std::sin(0.5 * medium.omega(k) * dtd);
    return (dm1 * std::cos(medium.omega(k) * dtd) - 2.0 * half * half) * scale;
}

// Sponge: friction γ = SPONGE_MAX_RATE·(1 − s_row·s_col) with the sin² profile s (spongeProfile)
// (0 at the outer ring, 1 from the band's inner edge, zero slope there, so the band starts
// without a step in the medium); each step scales h − its mean level and v by exp(−γΔt). A wave that
// crosses the band twice (out, and back in through the periodic wrap) keeps little: 32
// cells of 0.25 m damp a 2 m wave (group speed 0.9 m/s) by e^-50 or so.
std::vector<float> EWaveField::spongeFactors(int rows, int cols, int spongeWidth, float dt) {
    const double dtd = dt;
    std::vector<float> sponge(size_t(rows) * size_t(cols), 1.0f);
    for (int z = 0; z < rows; ++z) {
        const float sz = spongeProfile(std::min(z, rows - 1 - z), spongeWidth);
        for (int x = 0; x < cols; ++x) {
            const float sx = spongeProfile(std::min(x, cols - 1 - x), spongeWidth);
            const double gamma = SPONGE_MAX_RATE * (1.0 - double(sz) * double(sx));
            sponge[size_t(z) * size_t(cols) + size_t(x)] = float(std::exp(-gamma * dtd));
        }
    }
    return sponge;
}

// Per mode (row j ≤ rows/2, column i of the r2c spectrum; row rows − j has the same |k| and
// reads row j's) the change's coefficients a − 1, b, c (the rotation by ωΔt times the damping,
// less the identity) times FFTW's 1/(rows·cols) (a power of two for power-of-two sides: exact).
// The sponge factors depend on Δt too: both are rebuilt when Δt or the damping changes.
void EWaveField::prepare(float dt) {
    const double norm = 1.0 / (double(m_rows) * double(m_cols));
    const double twoPi = 2.0 * std::numbers::pi;
    const double lx = double(m_cols) * m_cellSize, lz = double(m_rows) * m_cellSize;
    for (int j = 0; j <= m_rows / 2; ++j) {
        const double kz = twoPi * j / lz;
        for (int i = 0; i < m_specCols; ++i) {
            const double kx = twoPi * i / lx;
            const double k = std::sqrt(kx * kx + kz * kz);
            double* c = m_coef.data() + 3 * (size_t(j) * size_t(m_specCols) + size_t(i));
            c[0] = modeStepMinusOne(m_medium, k, dt, m_decayTime, m_viscosity, norm);
            const ModeStep s = modeStep(m_medium, k, dt, m_decayTime, m_viscosity, norm);
            c[1] = s.b;
            c[2] = s.c;
        }
    }
    m_sponge.clear();
    if (m_boundary == RippleBoundary::Absorbing) m_sponge = spongeFactors(m_rows, m_cols, m_spongeWidth, dt);
    m_preparedDt = dt;
}

// The float copies the forward transforms read, current: the sources in v, an edit's state, the
// rows the sources wrote.
void EWaveField::syncFloatCopies() {
    applySources();
    if (m_stale) syncHeight();
    if (m_vRows0 < m_vRows1) {  // rows the sources wrote
        const size_t at = size_t(m_vRows0) * size_t(m_cols);
        toFloatKernel(m_float[1] + at, m_v + at, size_t(m_vRows1 - m_vRows0) * size_t(m_cols));
        m_vRows0 = m_rows;
        m_vRows1 = 0;
    }
}

void EWaveField::step(float dt) {
    assert(dt > 0.0f);
    if (dt != m_preparedDt) prepare(dt);
    syncFloatCopies();
    const int pairChunk = m_stepThreads > 1 ? 1 : 2;             // 2: both on the calling thread
    const int rowChunk = m_stepThreads > 1 ? m_rows / 2 : m_rows;  // two row bands, or one
    // --- 1. forward transforms of h and v, each whole on one worker
    parallelFor(0, 2, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t)
            fftwf_execute_dft_r2c(m_forward, m_float[t], reinterpret_cast<fftwf_complex*>(m_spec[t]));
    });
    // --- 2. the horizontal fields' spectra of the new state, then both spectra become their
    //        changes, in row bands
    parallelFor(0, m_rows, rowChunk, [&](int j0, int j1) { changeRows(j0, j1); });
    sumVelocityWavenumber();
    // --- 3. per field: the inverse transform of its change, added to it, the boundary, its float
    //        copy; the horizontal fields' inverse transforms and their boundary
    inverseTransforms(true);
    // --- 4. the volume the rounding and the sponge moved, put back
    if (m_boundary != RippleBoundary::Fixed) conserveVolume();
}

// The inverse transforms over the workers, in an order that gives each of two workers one state
// field (its transform and its finishRows, the larger tasks) and half the horizontal ones.
void EWaveField::inverseTransforms(bool state) {
    // Tasks: 0, 1 the state's h and v; 2.. the horizontal fields ux, uz, ξx, ξz.
    static constexpr int STEP[] = {0, 2, 1, 3}, STEP_DISPLACEMENT[] = {0, 2, 4, 1, 3, 5}, DERIVED[] = {2, 3, 4, 5};
    const int* tasks = state ? (m_displacement ? STEP_DISPLACEMENT : STEP) : DERIVED;
    const int count = (state ? 2 : 0) + (m_displacement ? 4 : 2);
    const int chunk = m_stepThreads > 1 ? 1 : count;
    parallelFor(0, count, chunk, [&](int b, int e) {
        for (int k = b; k < e; ++k) {
            const int t = tasks[k];
            if (t < 2) {
                fftwf_execute_dft_c2r(m_backward, reinterpret_cast<fftwf_complex*>(m_spec[t]), m_change[t]);
                finishRows(t, 0, m_rows);
            } else {
                fftwf_execute_dft_c2r(m_backward, reinterpret_cast<fftwf_complex*>(m_horizSpec[t - 2]), m_horiz[t - 2]);
                if (state) finishHorizontal(t - 2);  // derived from a state that had its boundary: none again
            }
        }
    });
}

// Field f of the horizontal ones after its transform: the boundary as finishRows applies it to v
// (Fixed: the outer ring 0; Absorbing: the band scaled by the sponge factors, towards 0).
void EWaveField::finishHorizontal(int f) {
    float* const u = m_horiz[f];
    const int rows = m_rows, cols = m_cols, w = m_spongeWidth;
    switch (m_boundary) {
    case RippleBoundary::Periodic:
        break;
    case RippleBoundary::Fixed:
        std::fill(u, u + cols, 0.0f);
        std::fill(u + size_t(rows - 1) * size_t(cols), u + m_cells, 0.0f);
        for (int z = 1; z < rows - 1; ++z) u[size_t(z) * size_t(cols)] = u[size_t(z) * size_t(cols) + size_t(cols - 1)] = 0.0f;
        break;
    case RippleBoundary::Absorbing:
        for (int z = 0; z < rows; ++z) {
            float* r = u + size_t(z) * size_t(cols);
            const float* s = m_sponge.data() + size_t(z) * size_t(cols);
            if (z < w || z >= rows - w) {
                for (int x = 0; x < cols; ++x) r[x] *= s[x];
            } else {
                for (int x = 0; x < w; ++x) r[x] *= s[x];
                for (int x = cols - w; x < cols; ++x) r[x] *= s[x];
            }
        }
        break;
    }
}

// As the step's passes 1–3 with no change: the state as it is, its boundary already applied.
void EWaveField::deriveHorizontal() {
    syncFloatCopies();
    const int pairChunk = m_stepThreads > 1 ? 1 : 2;
    parallelFor(0, m_displacement ? 2 : 1, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) {
            const int field = 1 - t;  // v first
            fftwf_execute_dft_r2c(m_forward, m_float[field], reinterpret_cast<fftwf_complex*>(m_spec[field]));
        }
    });
    const int rowChunk = m_stepThreads > 1 ? m_rows / 2 : m_rows;
    parallelFor(0, m_rows, rowChunk, [&](int j0, int j1) {
        for (int j = j0; j < j1; ++j) horizontalRow(j, false);
    });
    sumVelocityWavenumber();
    inverseTransforms(false);
}

void EWaveField::sumVelocityWavenumber() {
    double num = 0.0, den = 0.0;  // in row order: the same bits whatever the workers' split
    for (int j = 0; j < m_rows; ++j) {
        num += m_rowSums[2 * size_t(j)];
        den += m_rowSums[2 * size_t(j) + 1];
    }
    m_velocityWavenumber = den > 0.0 ? num / den : 0.0;
}

// The step changes no mode but k = 0 of h by more than rounding, so the shift is that rounding
// (~1e-8 of the change's RMS over the field) plus, with the sponge, the water it moved:
// spread over the whole field it is the k = 0 mode alone, as a volume's rise would be.
void EWaveField::conserveVolume() {
    const double shift = (m_volume - sumKernel(m_h, m_cells)) / double(m_cells);
    shiftKernel(m_h, m_float[0], shift, m_cells);
}

// Spectrum rows [j0, j1) of both fields: Δĥ = (a − 1)·ĥ + b·v̂, Δv̂ = c·ĥ + (a − 1)·v̂ in place.
// Mode 0 (in the band of row 0): its coefficients are 0, so ĥ(0) is kept, and v̂(0) is dropped
// (Δv̂(0) = −v̂(0)): a source's uniform part lifts no water.
void EWaveField::changeRows(int j0, int j1) {
    const float v0[2] = {j0 == 0 ? m_spec[1][0] : 0.0f, j0 == 0 ? m_spec[1][1] : 0.0f};
    for (int j = j0; j < j1; ++j) {
        const size_t row = size_t(j) * size_t(m_specCols);
        const size_t coefRow = size_t(std::min(j, m_rows - j)) * size_t(m_specCols);
        if (m_displacement) {  // ξ too (the coarse levels, which step rarely): the two passes
            horizontalRow(j, true);
            changeKernel(m_spec[0] + 2 * row, m_spec[1] + 2 * row, m_coef.data() + 3 * coefRow, m_specCols);
            continue;
        }
        float* power = m_power.data() + row;
        changeVelocityKernel(m_spec[0] + 2 * row, m_spec[1] + 2 * row, m_coef.data() + 3 * coefRow,
                             1.0 / (double(m_rows) * double(m_cols)), m_riesz.data() + coefRow, m_kx.data(),
                             m_weight.data(), rowKz(j), m_horizSpec[0] + 2 * row, m_horizSpec[1] + 2 * row, power,
                             m_specCols);
        if (j == 0) power[0] = 0.0f;  // K = 0: the mean, no wave (its û is 0: r = 0)
        sumsKernel(power, m_kabs.data() + coefRow, m_specCols, m_rowSums.data() + 2 * size_t(j));
    }
    if (j0 == 0) {  // the change's spectrum carries the inverse transform's 1/(rows·cols), as the coefficients do
        const float norm = float(1.0 / (double(m_rows) * double(m_cols)));
        m_spec[1][0] = -v0[0] * norm;
        m_spec[1][1] = -v0[1] * norm;
    }
}

// Rows [z0, z1) of field t (0: h, 1: v): the change added, then the boundary (Fixed: the outer
// ring 0; Absorbing: the band scaled by the sponge factors), the float copy following.
void EWaveField::finishRows(int t, int z0, int z1) {
    const int rows = m_rows, cols = m_cols, w = m_spongeWidth;
    double* const f = t == 0 ? m_h : m_v;
    const double level = t == 0 ? m_volume / double(m_cells) : 0.0;  // the sponge's far field: the mean level, v = 0
    for (int z = z0; z < z1; ++z) {
        const size_t row = size_t(z) * size_t(cols);
        double* fr = f + row;
        float* copy = m_float[t] + row;
        addKernel(fr, copy, m_change[t] + row, cols);
        switch (m_boundary) {
        case RippleBoundary::Periodic:
            break;
        case RippleBoundary::Fixed:
            if (z == 0 || z == rows - 1) {
                std::fill(fr, fr + cols, 0.0);
                std::fill(copy, copy + cols, 0.0f);
            } else {
                fr[0] = fr[cols - 1] = 0.0;
                copy[0] = copy[cols - 1] = 0.0f;
            }
            break;
        case RippleBoundary::Absorbing:
            // Only the band: rows in it whole, the other rows at their two ends.
            if (z < w || z >= rows - w) {
                scaleKernel(fr, copy, m_sponge.data() + row, cols, level);
            } else {
                scaleKernel(fr, copy, m_sponge.data() + row, w, level);
                scaleKernel(fr + (cols - w), copy + (cols - w), m_sponge.data() + row + size_t(cols - w), w, level);
            }
            break;
        }
    }
}

void EWaveField::addLevel(double dh) {
    shiftKernel(m_h, m_float[0], dh, m_cells);
    m_volume += dh * double(m_cells);
}

void EWaveField::syncHeight() {
    applySources();
    toFloatKernel(m_float[0], m_h, m_cells);
    toFloatKernel(m_float[1], m_v, m_cells);
    m_volume = sumKernel(m_h, m_cells);
    m_stale = false;
    m_vRows0 = m_rows;
    m_vRows1 = 0;
}

// One source over `rows` rows of n cells of the sources' sum (row stride `stride`): per row
// q = 1 − dz²/R² (dz = dz0 + row), then sum[x] += amount·max(0, q − dx2[x])², 0 outside the disc.
OB_VECTOR_KERNEL static void sourceKernel(float* __restrict sum, size_t stride, int rows, float dz0, float invR2,
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
OB_VECTOR_KERNEL static void applySumKernel(double* __restrict v, float* __restrict sum, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        v[i] += double(sum[i]);
        sum[i] = 0.0f;
    }
}

void EWaveField::applySources() const {
    if (m_sourceRows0 >= m_sourceRows1) return;
    const size_t at = size_t(m_sourceRows0) * size_t(m_cols);
    applySumKernel(m_v + at, m_sourceSum.data() + at, size_t(m_sourceRows1 - m_sourceRows0) * size_t(m_cols));
    m_vRows0 = std::min(m_vRows0, m_sourceRows0);  // v's float copy is stale there
    m_vRows1 = std::max(m_vRows1, m_sourceRows1);
    m_sourceRows0 = m_rows;
    m_sourceRows1 = 0;
}

void EWaveField::addSource(float gx, float gz, float radiusCells, float accel, float dt) {
    const EWaveSource s{gx, gz, radiusCells, accel};
    addSources({&s, 1}, dt);
}

// Row bands [z0, z1) of the field on the workers, each applying every source's rows in it in
// list order: a cell receives its sources in the same order whatever the split, so the bits do
// not depend on it. Per source the column terms (x − gx)²/R² are computed once, then per row
// q = 1 − (z − gz)²/R² and v += amount·max(0, q − (x − gx)²/R²)² over the bounding square
// (the corners cost less as multiply-adds than finding the disc's ends per row).
void EWaveField::addSources(std::span<const EWaveSource> sources, float dt) {
    size_t work = 0;  // cells in the sources' bounding squares
    for (const EWaveSource& s : sources) {
        const float r = std::max(s.radiusCells, 1.0f);
        work += size_t(2.0 * r + 1.0) * size_t(2.0 * r + 1.0);
        m_sourceRows0 = std::min(m_sourceRows0, std::max(0, int(std::ceil(s.gz - r))));
        m_sourceRows1 = std::max(m_sourceRows1, std::min(m_rows, int(std::floor(s.gz + r)) + 1));
    }
    const int minRows = m_sourceThreads > 1 && work >= PARALLEL_MIN_SOURCE_CELLS ? std::max(1, m_rows / 16) : m_rows;
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
            sourceKernel(m_sourceSum.data() + size_t(z0) * size_t(m_cols) + size_t(x0), size_t(m_cols), z1 - z0 + 1,
                         float(z0) - s.gz, invR2, dx2.data(), x1 - x0 + 1, s.accel * dt);
        }
    });
}

// Fixed: the new cells at 0 and the volume recounted (its ring drains anyway). Periodic and
// Absorbing keep the volume, the k = 0 mode, exactly: the new cells come in at the mean level
// (the far field the sponge relaxes to), v = 0, and the water the strips that left held above
// or below that level is put back as a uniform shift (as conserveVolume puts back what the
// sponge moved). Filling with 0 and recounting lowered a patch that follows a ship by the
// raised far field it scrolled out, a different amount on each level (docs/ewave.md#levels).
void EWaveField::scroll(int dx, int dz) {
    if (dx == 0 && dz == 0) return;
    applySources();
    if (m_stale) syncHeight();  // the volume of an edit
    const bool keep = m_boundary != RippleBoundary::Fixed;
    const double volume = m_volume;
    scrollCells(m_h, m_rows, m_cols, glm::ivec2(dx, dz), keep ? volume / double(m_cells) : 0.0);
    scrollCells(m_v, m_rows, m_cols, glm::ivec2(dx, dz), 0.0);
    for (float* f : m_horiz) scrollCells(f, m_rows, m_cols, glm::ivec2(dx, dz), 0.0f);
    syncHeight();
    if (!keep) return;
    m_volume = volume;
    conserveVolume();
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

void EWaveField::clear() {
    applySources();
    std::fill(m_h, m_h + m_cells, 0.0);
    std::fill(m_v, m_v + m_cells, 0.0);
    for (float* f : m_horiz) std::fill(f, f + m_cells, 0.0f);
    m_velocityWavenumber = 0.0;
    syncHeight();
}

} // namespace ob::interaction
