// The ewave field's spectral half: FFTW real-to-complex transforms of the state's float copies,
// the exact per-mode change in double, and the horizontal surface velocity and displacement of
// the new state's spectrum (ewave_transforms.h; docs/references.md#dispersive-ripples).
#include "interaction/ewave/ewave_transforms.h"

#include "interaction/ewave/ewave_field.h"

#include "core/error.h"
#include "core/fftw_wisdom.h"
#include "core/simd.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <fftw3.h>
#include <mutex>
#include <numbers>
#include <string>
#include <type_traits>

namespace ob::interaction {

namespace {

// FFTW's allocation, so every array has the alignment the plans were made for.
float* allocTransformArray(size_t n) {
    float* p = fftwf_alloc_real(n);
    if (!p) throw RuntimeError("out of memory for the ewave ripple field");
    std::memset(p, 0, n * sizeof(float));
    return p;
}

// Packing (ewave_transforms.h): real fields a, b with Hermitian spectra into one complex field
// a + i·b. From â(K) = (ar, ai) and b̂(K) = (br, bi) its spectrum at K is (ar − bi, ai + br), at −K
// (ar + bi, br − ai). The kernels below write, per mode i of a half-spectrum row, K's value into
// `own` (the row's columns 0..cols/2) and −K's into `staged` at i, in the same order;
// mirrorKernel then copies the staged values of the columns 1..mirrorEnd, whose −K lies in the
// other half, to column cols − i of the row (rows − j) mod rows (columns 0 and cols/2 are their
// own mirrors). Two forward loops and a reversed copy: GCC vectorises each (a reversed store
// beside more than one input stream it does not).

// One mode's change (double, as the state's step has always made it), rounded to float:
// Δĥ = (a − 1)·ĥ + b·v̂, Δv̂ = c·ĥ + (a − 1)·v̂ with a − 1, b, c = coef[m], coef[n + m], coef[2n + m]
// (the row's three planes, n modes each); and the new v̂' = scale·v̂ + Δv̂ (the coefficients carry
// `scale`, 1/(rows·cols)).
struct ModeChange {
    float dh0, dh1, dv0, dv1, n0, n1;
};
inline ModeChange modeChange(const float* hs, const float* vs, const double* coef, int n, double scale, int m) {
    const double am1 = coef[m], b = coef[n + m], c = coef[2 * n + m];
    const double h0 = hs[2 * m], h1 = hs[2 * m + 1], v0 = vs[2 * m], v1 = vs[2 * m + 1];
    const double dv0 = c * h0 + am1 * v0, dv1 = c * h1 + am1 * v1;
    return {float(am1 * h0 + b * v0), float(am1 * h1 + b * v1), float(dv0), float(dv1), float(scale * v0 + dv0),
            float(scale * v1 + dv1)};
}

// The packed change Δh + i·s·Δv at mode m, own and staged.
inline void packChange(const ModeChange& d, float s, float* own, float* staged, int m) {
    const float sv0 = s * d.dv0, sv1 = s * d.dv1;  // a power of two: exact
    own[2 * m] = d.dh0 - sv1;
    own[2 * m + 1] = d.dh1 + sv0;
    staged[2 * m] = d.dh0 + sv1;
    staged[2 * m + 1] = sv0 - d.dh1;
}

// The packed horizontal pair ûx + i·ûz = i·K·r·(n0, n1) at mode m, own and staged: with
// (mx, mz) = (kx, kz)·r, ûx = (−mx·n1, mx·n0), ûz = (−mz·n1, mz·n0).
inline void packRiesz(float n0, float n1, float mx, float mz, float* own, float* staged, int m) {
    const float xr = -mx * n1, xi = mx * n0, zr = -mz * n1, zi = mz * n0;
    own[2 * m] = xr - zi;
    own[2 * m + 1] = xi + zr;
    staged[2 * m] = xr + zi;
    staged[2 * m + 1] = zr - xi;
}

// The staged −K values of columns 1..mirrorEnd to their places, columns cols − i of `mirror`.
OB_VECTOR_KERNEL void mirrorKernel(const float* __restrict staged, float* __restrict mirror, int mirrorEnd, int cols) {
    for (int m = 1; m <= mirrorEnd; ++m) {
        mirror[2 * (cols - m)] = staged[2 * m];
        mirror[2 * (cols - m) + 1] = staged[2 * m + 1];
    }
}

// One spectrum row of the state's step without the horizontal fields: the packed change.
OB_VECTOR_KERNEL void changeKernel(const float* __restrict hs, const float* __restrict vs, const double* __restrict coef,
                                   float s, float* __restrict own, float* __restrict staged, int n) {
    for (int m = 0; m < n; ++m) packChange(modeChange(hs, vs, coef, n, 1.0, m), s, own, staged, m);
}

// One spectrum row of the step (SPEC §2.5c): the packed change, the packed velocity û = i·K·r·v̂'
// (K = (kx[m], kz), r = riesz[m] = 1/(|K|·tanh(|K|d))) and power[m] = weight[m]·|v̂'|² (weight:
// the mode's count in the full spectrum; the caller zeroes K = 0's and sums: sumsKernel).
OB_VECTOR_KERNEL void changeVelocityKernel(const float* __restrict hs, const float* __restrict vs,
                                           const double* __restrict coef, double scale, float s,
                                           const float* __restrict riesz, const float* __restrict kx,
                                           const float* __restrict weight, float kz, float* __restrict ownC,
                                           float* __restrict stagedC, float* __restrict ownU, float* __restrict stagedU,
                                           float* __restrict power, int n) {
    for (int m = 0; m < n; ++m) {
        const ModeChange d = modeChange(hs, vs, coef, n, scale, m);
        packChange(d, s, ownC, stagedC, m);
        const float r = riesz[m];
        packRiesz(d.n0, d.n1, kx[m] * r, kz * r, ownU, stagedU, m);
        power[m] = weight[m] * (d.n0 * d.n0 + d.n1 * d.n1);
    }
}

// The packed horizontal pair i·K·r·(scale·f) of a spectrum row f and its power: deriveHorizontal's
// velocity from v̂, and the displacement from ĥ' (the coarse levels).
OB_VECTOR_KERNEL void rieszKernel(const float* __restrict f, float scale, const float* __restrict riesz,
                                  const float* __restrict kx, const float* __restrict weight, float kz,
                                  float* __restrict own, float* __restrict staged, float* __restrict power, int n) {
    for (int m = 0; m < n; ++m) {
        const float n0 = scale * f[2 * m], n1 = scale * f[2 * m + 1];
        const float r = riesz[m];
        packRiesz(n0, n1, kx[m] * r, kz * r, own, staged, m);
        power[m] = weight[m] * (n0 * n0 + n1 * n1);
    }
}

// The new ĥ' = scale·ĥ + Δĥ of a spectrum row as floats into `out` (the displacement's input).
OB_VECTOR_KERNEL void newHeightKernel(const float* __restrict hs, const float* __restrict vs, const double* __restrict coef,
                                      double scale, float* __restrict out, int n) {
    for (int m = 0; m < n; ++m) {
        const double am1 = coef[m], b = coef[n + m];
        for (int p = 0; p < 2; ++p) out[2 * m + p] = float(scale * hs[2 * m + p] + (am1 * hs[2 * m + p] + b * vs[2 * m + p]));
    }
}

// sums[0] = Σ kabs[m]·power[m], sums[1] = Σ power[m] over a row, in float (a row's sum to ~1e-6
// of itself, ample for a mean wavenumber), reassociated into vector lanes: the order is fixed by
// the code the clone was built with, so the bits do not depend on the workers; only this
// reduction is relaxed, never the state's arithmetic.
OB_RELAXED_SUM OB_VECTOR_KERNEL void sumsKernel(const float* __restrict power, const float* __restrict kabs, int n, double* __restrict sums) {
    float num = 0.0f, den = 0.0f;
    for (int m = 0; m < n; ++m) {
        num += kabs[m] * power[m];
        den += power[m];
    }
    sums[0] = num;
    sums[1] = den;
}

// The change's scale s is kept within [2^-SCALE_RANGE, 2^SCALE_RANGE] (balance).
constexpr int SCALE_RANGE = 30;

} // namespace

EWaveTransforms::EWaveTransforms(int rows, int cols, float cellSize)
    : m_rows(rows), m_cols(cols), m_specCols(cols / 2 + 1), m_cells(size_t(rows) * size_t(cols)),
      m_modes(size_t(rows) * size_t(cols / 2 + 1)), m_cellSize(cellSize) {
    for (int t = 0; t < 2; ++t) m_spec[t] = allocTransformArray(2 * m_modes);
    for (float*& f : m_full) f = allocTransformArray(2 * m_cells);
    // Planning may overwrite the arrays (FFTW_MEASURE): they hold nothing yet. The forward
    // transform keeps its input (r2c's default): it reads the field's float copies of the state,
    // as new arrays of the same alignment (planned here on the displacement's array). The inverse
    // one is in place, run on each packed array.
    m_forward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_r2c_2d(rows, cols, m_full[2], reinterpret_cast<fftwf_complex*>(m_spec[0]), flags);
    });
    m_backward = ocean::planWithWisdom([&](unsigned flags) {
        fftwf_complex* f = reinterpret_cast<fftwf_complex*>(m_full[0]);
        return fftwf_plan_dft_2d(rows, cols, f, f, FFTW_BACKWARD, flags);
    });
    if (!m_forward || !m_backward)
        throw RuntimeError("FFTW could not plan a " + std::to_string(rows) + "×" + std::to_string(cols) + " transform");
    for (float* f : m_full) std::memset(f, 0, 2 * m_cells * sizeof(float));
    m_coef.resize(3 * size_t(m_rows / 2 + 1) * size_t(m_specCols));
    m_rowSums.assign(2 * size_t(m_rows), 0.0);
    m_power.assign(m_modes, 0.0f);
    m_staged.assign(8 * size_t(m_specCols), 0.0f);
}

EWaveTransforms::~EWaveTransforms() {
    {
        std::lock_guard<std::mutex> lock(ocean::fftwPlannerMutex());
        if (m_forward) fftwf_destroy_plan(m_forward);
        if (m_backward) fftwf_destroy_plan(m_backward);
    }
    for (float* f : m_spec) fftwf_free(f);
    for (float* f : m_full) fftwf_free(f);
}

void EWaveTransforms::keepVelocity(bool on) {
    m_velocity = on;
    if (!on) clearHorizontal();
}

void EWaveTransforms::keepDisplacement(bool on) {
    m_displacement = on;
    if (!on) std::memset(m_full[2], 0, 2 * m_cells * sizeof(float));
}

void EWaveTransforms::forward(int t, const float* copy) {
    fftwf_execute_dft_r2c(m_forward, const_cast<float*>(copy), reinterpret_cast<fftwf_complex*>(m_spec[t]));
}

void EWaveTransforms::inverseChange() {
    fftwf_complex* f = reinterpret_cast<fftwf_complex*>(m_full[0]);
    fftwf_execute_dft(m_backward, f, f);
}

void EWaveTransforms::inverseHorizontal(int f) {
    fftwf_complex* a = reinterpret_cast<fftwf_complex*>(m_full[1 + f]);
    fftwf_execute_dft(m_backward, a, a);
}

void EWaveTransforms::horizontalRows(int p0, int p1) {
    float* const staged = stagedRows(p0);
    for (int p = p0; p < p1; ++p)
        for (int j : pair(p))
            if (j >= 0) horizontalRow(j, false, staged);
}

// The scratch of the band of pairs starting at p0: at most two bands, [0, pairs/2) and the rest.
float* EWaveTransforms::stagedRows(int p0) {
    assert(p0 == 0 || p0 >= pairs() / 2);
    return m_staged.data() + (p0 == 0 ? 0 : 4 * size_t(m_specCols));
}

// Pair p's rows: p and rows − p (−1 where it has one row: p = 0, and rows/2 for even rows).
std::array<int, 2> EWaveTransforms::pair(int p) const {
    const int other = m_rows - p;
    return {p, p > 0 && other != p ? other : -1};
}

void EWaveTransforms::clearHorizontal() {
    for (int f = 1; f < 3; ++f) std::memset(m_full[f], 0, 2 * m_cells * sizeof(float));
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

// Spectrum row j's horizontal fields, packed, and its sums of velocityWavenumber: of the new state
// (`change`: the rotation's ĥ', v̂'; the velocity is changeRows' own, so this makes the displacement
// alone) or of the state as transformed (deriveHorizontal). kz = 2π·(j or j − rows)/(rows·Δ), 0 at
// the Nyquist row. `staged`: the band's scratch (stagedRows).
void EWaveTransforms::horizontalRow(int j, bool change, float* staged) {
    const size_t row = size_t(j) * size_t(m_specCols);
    const size_t coefRow = size_t(std::min(j, m_rows - j)) * size_t(m_specCols);
    const float norm = float(1.0 / (double(m_rows) * double(m_cols)));
    const int mirrorEnd = (m_cols - 1) / 2;
    float* power = m_power.data() + row;
    if (!change) {
        rieszKernel(m_spec[1] + 2 * row, norm, m_riesz.data() + coefRow, m_kx.data(), m_weight.data(), rowKz(j), fullRow(1, j),
                    staged, power, m_specCols);
        mirrorKernel(staged, mirrorRow(1, j), mirrorEnd, m_cols);
        if (j == 0) power[0] = 0.0f;  // K = 0: the mean, no wave (its û is 0: r = 0)
        sumsKernel(power, m_kabs.data() + coefRow, m_specCols, m_rowSums.data() + 2 * size_t(j));
    }
    if (!m_displacement) return;
    const float* h = m_spec[0] + 2 * row;
    float scale = norm;
    if (change) {  // ĥ' into the band's scratch for the velocity (still unused): the displacement's input
        float* hNew = staged + 2 * size_t(m_specCols);
        newHeightKernel(m_spec[0] + 2 * row, m_spec[1] + 2 * row, m_coef.data() + 3 * coefRow, double(norm), hNew, m_specCols);
        h = hNew;
        scale = 1.0f;
    }
    // Its power is scratch: the velocity's is summed before (derive) or made after (the step).
    rieszKernel(h, scale, m_riesz.data() + coefRow, m_kx.data(), m_weight.data(), rowKz(j), fullRow(2, j), staged, power,
                m_specCols);
    mirrorKernel(staged, mirrorRow(2, j), mirrorEnd, m_cols);
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

void EWaveTransforms::finishChange() {
    m_usedScale = m_scale;
    if (m_velocity) sumVelocityWavenumber();
}

// s' = s·√(Σ(Δh)²/Σ(s·Δv)²) to the nearest power of two; as it was where either sum is 0 (nothing
// to balance).
void EWaveTransforms::balance(double sumH2, double sumV2) {
    if (!(sumH2 > 0.0) || !(sumV2 > 0.0)) return;
    const int e = std::ilogb(m_usedScale) + int(std::lround(0.5 * std::log2(sumH2 / sumV2)));
    m_scale = std::ldexp(1.0f, std::clamp(e, -SCALE_RANGE, SCALE_RANGE));
}

// Row pairs [p0, p1) (pair(p): rows p and rows − p, which share their coefficients, so the second
// reads them from the cache, and which write each other's mirrored halves).
void EWaveTransforms::changeRows(int p0, int p1) {
    float* const staged = stagedRows(p0);
    for (int p = p0; p < p1; ++p)
        for (int j : pair(p))
            if (j >= 0) changeRow(j, staged);
}

// Spectrum row j: the packed change (and the horizontal fields) of each mode, and the row's sums.
// Mode 0 (row 0): its coefficients are 0, so ĥ(0) is kept, and v̂(0) is dropped (Δv̂(0) = −v̂(0)): a
// source's uniform part lifts no water.
void EWaveTransforms::changeRow(int j, float* staged) {
    const double norm = 1.0 / (double(m_rows) * double(m_cols));
    const int mirrorEnd = (m_cols - 1) / 2;
    float* const stagedC = staged;
    float* const stagedU = staged + 2 * size_t(m_specCols);
    const size_t row = size_t(j) * size_t(m_specCols);
    const size_t coefRow = size_t(std::min(j, m_rows - j)) * size_t(m_specCols);
    const float* hs = m_spec[0] + 2 * row;
    const float* vs = m_spec[1] + 2 * row;
    const double* coef = m_coef.data() + 3 * coefRow;
    double* sums = m_rowSums.data() + 2 * size_t(j);
    if (m_displacement) horizontalRow(j, true, stagedC);  // ξ (the coarse levels, which step rarely): its own pass, reading ĥ' first
    if (!m_velocity) {  // the state alone (no reader of the horizontal fields)
        changeKernel(hs, vs, coef, m_scale, fullRow(0, j), stagedC, m_specCols);
        sums[0] = sums[1] = 0.0;
    } else {
        float* power = m_power.data() + row;
        changeVelocityKernel(hs, vs, coef, norm, m_scale, m_riesz.data() + coefRow, m_kx.data(), m_weight.data(), rowKz(j),
                             fullRow(0, j), stagedC, fullRow(1, j), stagedU, power, m_specCols);
        mirrorKernel(stagedU, mirrorRow(1, j), mirrorEnd, m_cols);
        if (j == 0) power[0] = 0.0f;  // K = 0: the mean, no wave (its û is 0: r = 0)
        sumsKernel(power, m_kabs.data() + coefRow, m_specCols, sums);
    }
    mirrorKernel(stagedC, mirrorRow(0, j), mirrorEnd, m_cols);
    if (j == 0) {  // Δv̂(0) = −v̂(0), carrying the inverse transform's 1/(rows·cols) as the coefficients do; Δĥ(0) = 0
        const float dv0 = -vs[0] * float(norm), dv1 = -vs[1] * float(norm);
        float* c = fullRow(0, 0);
        c[0] = -m_scale * dv1;
        c[1] = m_scale * dv0;
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
            double* c = m_coef.data() + 3 * size_t(j) * size_t(m_specCols) + size_t(i);  // the row's planes a − 1, b, c
            c[0] = EWaveField::modeStepMinusOne(medium, k, dt, decayTime, viscosity, norm);
            const EWaveField::ModeStep s = EWaveField::modeStep(medium, k, dt, decayTime, viscosity, norm);
            c[m_specCols] = s.b;
            c[2 * m_specCols] = s.c;
        }
    }
}


} // namespace ob::interaction
