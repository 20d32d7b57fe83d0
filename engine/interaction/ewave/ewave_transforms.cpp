// The ewave field's spectral half: FFTW real-to-complex transforms of the state's float copies,
// the exact per-mode change in double, and the horizontal surface velocity and displacement of
// the new state's spectrum (ewave_transforms.h; docs/references.md#dispersive-ripples).
#include "interaction/ewave/ewave_transforms.h"

#include "interaction/ewave/ewave_field.h"

#include "core/error.h"
#include "core/fftw_wisdom.h"
#include "core/simd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fftw3.h>
#include <mutex>
#include <numbers>
#include <string>

namespace ob::interaction {

namespace {

// FFTW's allocation, so every array has the alignment the plans were made for.
float* allocTransformArray(size_t n) {
    float* p = fftwf_alloc_real(n);
    if (!p) throw RuntimeError("out of memory for the ewave ripple field");
    std::memset(p, 0, n * sizeof(float));
    return p;
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

} // namespace

EWaveTransforms::EWaveTransforms(int rows, int cols, float cellSize)
    : m_rows(rows), m_cols(cols), m_specCols(cols / 2 + 1), m_cells(size_t(rows) * size_t(cols)),
      m_modes(size_t(rows) * size_t(cols / 2 + 1)), m_cellSize(cellSize) {
    for (int t = 0; t < 2; ++t) {
        m_spec[t] = allocTransformArray(2 * m_modes);
        m_change[t] = allocTransformArray(m_cells);
    }
    // Planning may overwrite the arrays (FFTW_MEASURE): they hold nothing yet. The forward
    // transform keeps its input (r2c's default): it reads the field's float copies of the state,
    // as new arrays of the same alignment (planned here on a change array).
    m_forward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_r2c_2d(rows, cols, m_change[1], reinterpret_cast<fftwf_complex*>(m_spec[0]), flags);
    });
    m_backward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_c2r_2d(rows, cols, reinterpret_cast<fftwf_complex*>(m_spec[0]), m_change[0], flags);
    });
    if (!m_forward || !m_backward)
        throw RuntimeError("FFTW could not plan a " + std::to_string(rows) + "×" + std::to_string(cols) + " transform");
    m_coef.resize(3 * size_t(m_rows / 2 + 1) * size_t(m_specCols));
    for (int f = 0; f < 4; ++f) {
        m_horiz[f] = allocTransformArray(m_cells);
        m_horizSpec[f] = allocTransformArray(2 * m_modes);
    }
    m_rowSums.assign(2 * size_t(m_rows), 0.0);
    m_power.assign(m_modes, 0.0f);
}

EWaveTransforms::~EWaveTransforms() {
    {
        std::lock_guard<std::mutex> lock(ocean::fftwPlannerMutex());
        if (m_forward) fftwf_destroy_plan(m_forward);
        if (m_backward) fftwf_destroy_plan(m_backward);
    }
    for (int t = 0; t < 2; ++t) {
        fftwf_free(m_spec[t]);
        fftwf_free(m_change[t]);
    }
    for (int f = 0; f < 4; ++f) {
        fftwf_free(m_horiz[f]);
        fftwf_free(m_horizSpec[f]);
    }
}

void EWaveTransforms::keepVelocity(bool on) {
    m_velocity = on;
    if (!on) clearHorizontal();
}

void EWaveTransforms::keepDisplacement(bool on) {
    m_displacement = on;
    if (!on)
        for (int f = 2; f < 4; ++f) std::memset(m_horiz[f], 0, m_cells * sizeof(float));
}

void EWaveTransforms::forward(int t, const float* copy) {
    fftwf_execute_dft_r2c(m_forward, const_cast<float*>(copy), reinterpret_cast<fftwf_complex*>(m_spec[t]));
}

void EWaveTransforms::inverseChange(int t) {
    fftwf_execute_dft_c2r(m_backward, reinterpret_cast<fftwf_complex*>(m_spec[t]), m_change[t]);
}

void EWaveTransforms::inverseHorizontal(int f) {
    fftwf_execute_dft_c2r(m_backward, reinterpret_cast<fftwf_complex*>(m_horizSpec[f]), m_horiz[f]);
}

void EWaveTransforms::horizontalRows(int j0, int j1) {
    for (int j = j0; j < j1; ++j) horizontalRow(j, false);
}

void EWaveTransforms::clearHorizontal() {
    for (float* f : m_horiz) std::fill(f, f + m_cells, 0.0f);
    m_velocityWavenumber = 0.0;
}

// Per mode of rows 0..rows/2 (row rows − j has row j's |K|) r = 1/(|K|·tanh(|K|d)) (deep water, or
// |K|·d past 20: 1/|K|), 0 at K = 0; per column kx, 0 at the Nyquist column (its ±kx are one mode
// of a real field, whose derivative there is taken as 0; kz likewise in horizontalRow); per
// column the count of the full spectrum's modes it stands for (the half spectrum's inner columns
// stand for K and −K).
void EWaveTransforms::prepareHorizontal(const EWaveMedium& medium) {
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
    const double d = medium.depth;
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

// Spectrum row j (the step's: before changeRows turns it into the change; `change` false: the
// state as transformed) into the horizontal fields' spectra and its sums of velocityWavenumber.
// kz = 2π·(j or j − rows)/(rows·Δ), 0 at the Nyquist row.
void EWaveTransforms::horizontalRow(int j, bool change) {
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
float EWaveTransforms::rowKz(int j) const {
    const int signedJ = j <= m_rows / 2 ? j : j - m_rows;
    return 2 * j == m_rows ? 0.0f : float(2.0 * std::numbers::pi * signedJ / (double(m_rows) * m_cellSize));
}

void EWaveTransforms::sumVelocityWavenumber() {
    double num = 0.0, den = 0.0;  // in row order: the same bits whatever the workers' split
    for (int j = 0; j < m_rows; ++j) {
        num += m_rowSums[2 * size_t(j)];
        den += m_rowSums[2 * size_t(j) + 1];
    }
    m_velocityWavenumber = den > 0.0 ? num / den : 0.0;
}

// Spectrum rows [j0, j1) of both fields: Δĥ = (a − 1)·ĥ + b·v̂, Δv̂ = c·ĥ + (a − 1)·v̂ in place.
// Mode 0 (in the band of row 0): its coefficients are 0, so ĥ(0) is kept, and v̂(0) is dropped
// (Δv̂(0) = −v̂(0)): a source's uniform part lifts no water.
void EWaveTransforms::changeRows(int j0, int j1) {
    const float v0[2] = {j0 == 0 ? m_spec[1][0] : 0.0f, j0 == 0 ? m_spec[1][1] : 0.0f};
    for (int j = j0; j < j1; ++j) {
        const size_t row = size_t(j) * size_t(m_specCols);
        const size_t coefRow = size_t(std::min(j, m_rows - j)) * size_t(m_specCols);
        if (!m_velocity) {  // the state alone (no reader of the horizontal fields)
            changeKernel(m_spec[0] + 2 * row, m_spec[1] + 2 * row, m_coef.data() + 3 * coefRow, m_specCols);
            m_rowSums[2 * size_t(j)] = m_rowSums[2 * size_t(j) + 1] = 0.0;
            continue;
        }
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

// Per mode (row j ≤ rows/2, column i of the r2c spectrum; row rows − j has the same |k| and
// reads row j's) the change's coefficients a − 1, b, c (the rotation by ωΔt times the damping,
// less the identity) times FFTW's 1/(rows·cols) (a power of two for power-of-two sides: exact).
void EWaveTransforms::prepare(const EWaveMedium& medium, float dt, float decayTime, float viscosity) {
    const double norm = 1.0 / (double(m_rows) * double(m_cols));
    const double twoPi = 2.0 * std::numbers::pi;
    const double lx = double(m_cols) * m_cellSize, lz = double(m_rows) * m_cellSize;
    for (int j = 0; j <= m_rows / 2; ++j) {
        const double kz = twoPi * j / lz;
        for (int i = 0; i < m_specCols; ++i) {
            const double kx = twoPi * i / lx;
            const double k = std::sqrt(kx * kx + kz * kz);
            double* c = m_coef.data() + 3 * (size_t(j) * size_t(m_specCols) + size_t(i));
            c[0] = EWaveField::modeStepMinusOne(medium, k, dt, decayTime, viscosity, norm);
            const EWaveField::ModeStep s = EWaveField::modeStep(medium, k, dt, decayTime, viscosity, norm);
            c[1] = s.b;
            c[2] = s.c;
        }
    }
}


} // namespace ob::interaction
