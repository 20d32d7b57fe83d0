// Dispersive ripple field: exact per-mode rotation of (ĥ, v̂) with FFTW real-to-complex
// transforms of the step's change (docs/references.md#dispersive-ripples; Tessendorf, "eWave", 2014), then the boundary
// in real space. The state, its boundary and the step's order here; the transforms in
// ewave_transforms.cpp, the sources in ewave_sources.cpp.
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

// Both fields' change added, and their float copies: change holds (Δh, s·Δv) pairs, invS = 1/s
// (a power of two: exact). Before the boundary's band (finishRows' addScaleKernel there).
OB_VECTOR_KERNEL void addKernel(double* __restrict h, double* __restrict v, float* __restrict hc, float* __restrict vc,
                                const float* __restrict change, float invS, int n) {
    for (int i = 0; i < n; ++i) {
        h[i] += double(change[2 * i]);
        hc[i] = float(h[i]);
        v[i] += double(change[2 * i + 1] * invS);
        vc[i] = float(v[i]);
    }
}

// addKernel, then the sponge on both: h − level and v scaled by factor (level: h's mean level; v's is 0).
OB_VECTOR_KERNEL void addScaleKernel(double* __restrict h, double* __restrict v, float* __restrict hc, float* __restrict vc,
                                     const float* __restrict change, float invS, const float* __restrict factor, int n,
                                     double level) {
    for (int i = 0; i < n; ++i) {
        const double f = double(factor[i]);
        h[i] = ((h[i] + double(change[2 * i])) - level) * f + level;
        hc[i] = float(h[i]);
        v[i] = ((v[i] + double(change[2 * i + 1] * invS)) - 0.0) * f + 0.0;
        vc[i] = float(v[i]);
    }
}

// Σ change[2i]², Σ change[2i + 1]² over a row's n cells (Δh², (s·Δv)²: EWaveTransforms::balance), in
// float, reassociated into vector lanes: the order is fixed by the code the clone was built with
// (as the transforms' sums of velocityWavenumber), and only this reduction is relaxed.
OB_RELAXED_SUM OB_VECTOR_KERNEL void squaresKernel(const float* __restrict change, int n, double* __restrict sums) {
    float h = 0.0f, v = 0.0f;
    for (int i = 0; i < n; ++i) {
        h += change[2 * i] * change[2 * i];
        v += change[2 * i + 1] * change[2 * i + 1];
    }
    sums[0] = h;
    sums[1] = v;
}

// Σ f over a row in eight interleaved partial sums (a fixed order: the same bits from either clone),
// so the adds' latency does not bound it; the rows are then summed in order (conserveVolume).
OB_VECTOR_KERNEL double rowSumKernel(const double* __restrict f, int n) {
    constexpr int LANES = 8;
    double lane[LANES] = {};
    int i = 0;
    for (; i + LANES <= n; i += LANES)
        for (int l = 0; l < LANES; ++l) lane[l] += f[i + l];
    for (; i < n; ++i) lane[0] += f[i];
    double sum = 0.0;
    for (int l = 0; l < LANES; ++l) sum += lane[l];
    return sum;
}

// Σ f over rows × cols: each row's rowSumKernel, the rows in order. The one sum of the volume: the
// step's pass 3 makes the same rows' sums (finishRows), so what it keeps is what this counts.
double volumeSum(const double* f, int rows, int cols) {
    double sum = 0.0;
    for (int z = 0; z < rows; ++z) sum += rowSumKernel(f + size_t(z) * size_t(cols), cols);
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
    : m_rows(rows), m_cols(cols), m_cells(size_t(rows) * size_t(cols)), m_cellSize(cellSize), m_boundary(boundary),
      m_sources(rows, cols), m_transforms(rows, cols, cellSize) {
    assert(rows >= 2 && cols >= 2 && cellSize > 0.0f);
    m_h = allocReal(m_cells);
    m_v = allocReal(m_cells);
    for (int t = 0; t < 2; ++t) m_float[t] = allocFloat(m_cells);
    if (boundary == RippleBoundary::Absorbing) m_spongeWidth = std::clamp(spongeWidth, 1, std::min(rows, cols) / 2);
    m_transforms.prepareHorizontal(m_medium);
    m_rowSums.assign(3 * size_t(rows), 0.0);
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
    // Sources of 20 cells (or a quarter of the field) in a lattice, EWaveSources::PARALLEL_MIN_CELLS of
    // footprint in all: the smallest batch the bands are split for.
    const float r = std::min(20.0f, float(std::min(m_rows, m_cols)) / 4.0f);
    const size_t count = EWaveSources::PARALLEL_MIN_CELLS / size_t((2.0f * r + 1.0f) * (2.0f * r + 1.0f)) + 1;
    std::vector<EWaveSource> batch(count);
    for (size_t i = 0; i < count; ++i)
        batch[i] = {float((i * 37) % size_t(m_cols)), float((i * 61) % size_t(m_rows)), r, 1.0f};
    m_sources.setThreads(measuredThreads("ewave sources " + size, workerCount(), [&](int n) {
        m_sources.setThreads(n);
        addSources(batch, 1.0f / 60.0f);
    }));
    clear();
}

EWaveField::~EWaveField() {
    fftw_free(m_h);
    fftw_free(m_v);
    for (float* f : m_float) fftwf_free(f);
}

void EWaveField::setMedium(const EWaveMedium& medium) {
    assert(medium.gravity > 0.0 && medium.capillarity >= 0.0);
    m_medium = medium;
    m_preparedDt = -1.0f;
    m_transforms.prepareHorizontal(m_medium);
}

void EWaveField::keepHorizontalDisplacement(bool on) { m_transforms.keepDisplacement(on); }

void EWaveField::keepHorizontalVelocity(bool on) {
    assert(on || !m_transforms.displacement());
    m_transforms.keepVelocity(on);
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

// The per-mode coefficients (EWaveTransforms::prepare) and the sponge factors, which depend on Δt
// too: both are rebuilt when Δt or the damping changes.
void EWaveField::prepare(float dt) {
    m_transforms.prepare(m_medium, dt, m_decayTime, m_viscosity);
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
    const int pairs = m_transforms.pairs();
    const int pairChunks = m_stepThreads > 1 ? (pairs + 1) / 2 : pairs;  // two bands of row pairs, or one
    // --- 1. forward transforms of h and v, each whole on one worker
    parallelFor(0, 2, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) m_transforms.forward(t, m_float[t]);
    });
    // --- 2. per mode, in row bands: the packed change and the horizontal fields' spectra of the
    //        new state
    parallelFor(0, pairs, pairChunks, [&](int p0, int p1) { m_transforms.changeRows(p0, p1); });
    m_transforms.finishChange();
    // --- 3. the change's inverse transform, added to h and v, the boundary, their float copies
    //        (and h's row sums); the horizontal fields' inverse transforms and their boundary
    inverseTransforms(true);
    double sums[3] = {};  // Σh, Σ(Δh)², Σ(s·Δv)²: the rows in order, the same bits on any worker count
    for (size_t z = 0; z < size_t(m_rows); ++z)
        for (int k = 0; k < 3; ++k) sums[k] += m_rowSums[3 * z + size_t(k)];
    m_transforms.balance(sums[1], sums[2]);
    // --- 4. the volume the rounding and the sponge moved, put back
    if (m_boundary != RippleBoundary::Fixed) conserveVolume(sums[0]);
}

// The inverse transforms over the workers: the state's (its transform and finishRows, the larger
// task) and each horizontal field's (its transform and its boundary).
void EWaveField::inverseTransforms(bool state) {
    // Tasks: 0 the state; 1, 2 the horizontal fields u, ξ.
    const bool displacement = m_transforms.displacement(), velocity = m_transforms.velocity();
    const int first = state ? 0 : 1, end = !velocity ? 1 : displacement ? 3 : 2;
    if (end <= first) return;
    const int chunk = m_stepThreads > 1 ? 1 : end - first;
    parallelFor(first, end, chunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) {
            if (t == 0) {
                m_transforms.inverseChange();
                finishRows(0, m_rows);
            } else {
                m_transforms.inverseHorizontal(t - 1);
                if (state) finishHorizontal(t - 1);  // derived from a state that had its boundary: none again
            }
        }
    });
}

// Horizontal field f (0: u, 1: ξ) after its transform: the boundary as finishRows applies it to v
// (Fixed: the outer ring 0; Absorbing: the band scaled by the sponge factors, towards 0).
void EWaveField::finishHorizontal(int f) {
    glm::vec2* const u = m_transforms.horizontal(f);
    const int rows = m_rows, cols = m_cols, w = m_spongeWidth;
    switch (m_boundary) {
    case RippleBoundary::Periodic:
        break;
    case RippleBoundary::Fixed:
        std::fill(u, u + cols, glm::vec2(0.0f));
        std::fill(u + size_t(rows - 1) * size_t(cols), u + m_cells, glm::vec2(0.0f));
        for (int z = 1; z < rows - 1; ++z) u[size_t(z) * size_t(cols)] = u[size_t(z) * size_t(cols) + size_t(cols - 1)] = glm::vec2(0.0f);
        break;
    case RippleBoundary::Absorbing:
        for (int z = 0; z < rows; ++z) {
            glm::vec2* r = u + size_t(z) * size_t(cols);
            const float* s = m_sponge.data() + size_t(z) * size_t(cols);
            auto scale = [&](int x0, int x1) {
                for (int x = x0; x < x1; ++x) r[x] *= s[x];
            };
            if (z < w || z >= rows - w) {
                scale(0, cols);
            } else {
                scale(0, w);
                scale(cols - w, cols);
            }
        }
        break;
    }
}

// As the step's passes 1–3 with no change: the state as it is, its boundary already applied.
void EWaveField::deriveHorizontal() {
    if (!m_transforms.velocity()) return;  // nothing to derive: the fields stay 0
    syncFloatCopies();
    const int pairChunk = m_stepThreads > 1 ? 1 : 2;
    parallelFor(0, m_transforms.displacement() ? 2 : 1, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) {
            const int field = 1 - t;  // v first
            m_transforms.forward(field, m_float[field]);
        }
    });
    const int pairs = m_transforms.pairs(), pairChunks = m_stepThreads > 1 ? (pairs + 1) / 2 : pairs;
    parallelFor(0, pairs, pairChunks, [&](int p0, int p1) { m_transforms.horizontalRows(p0, p1); });
    m_transforms.sumVelocityWavenumber();
    inverseTransforms(false);
}

// The step changes no mode but k = 0 of h by more than rounding, so the shift is that rounding
// (~1e-8 of the change's RMS over the field) plus, with the sponge, the water it moved:
// spread over the whole field it is the k = 0 mode alone, as a volume's rise would be.
void EWaveField::conserveVolume(double sum) {
    const double shift = (m_volume - sum) / double(m_cells);
    shiftKernel(m_h, m_float[0], shift, m_cells);
}

// Rows [z0, z1) of h and v: the change added (change(): (Δh, s·Δv) pairs), then the boundary (Fixed:
// the outer ring 0; Absorbing: the band scaled by the sponge factors), the float copies following
// in the same sweep; h's row sums (m_rowSums) for conserveVolume.
void EWaveField::finishRows(int z0, int z1) {
    const int rows = m_rows, cols = m_cols, w = m_spongeWidth;
    const float invS = 1.0f / m_transforms.changeScale();
    const double level = m_volume / double(m_cells);  // the sponge's far field: the mean level (v: 0)
    const float* const change = m_transforms.change();
    for (int z = z0; z < z1; ++z) {
        const size_t row = size_t(z) * size_t(cols);
        double* const h = m_h + row;
        double* const v = m_v + row;
        float* const hc = m_float[0] + row;
        float* const vc = m_float[1] + row;
        const float* const c = change + 2 * row;
        auto add = [&](int x0, int x1) { addKernel(h + x0, v + x0, hc + x0, vc + x0, c + 2 * x0, invS, x1 - x0); };
        auto band = [&](int x0, int x1) {
            addScaleKernel(h + x0, v + x0, hc + x0, vc + x0, c + 2 * x0, invS, m_sponge.data() + row + size_t(x0), x1 - x0, level);
        };
        switch (m_boundary) {
        case RippleBoundary::Periodic:
            add(0, cols);
            break;
        case RippleBoundary::Fixed:
            add(0, cols);
            for (int x : {0, cols - 1}) h[x] = v[x] = 0.0, hc[x] = vc[x] = 0.0f;
            if (z == 0 || z == rows - 1) {
                std::fill(h, h + cols, 0.0), std::fill(v, v + cols, 0.0);
                std::fill(hc, hc + cols, 0.0f), std::fill(vc, vc + cols, 0.0f);
            }
            break;
        case RippleBoundary::Absorbing:
            // Only the band: rows in it whole, the other rows at their two ends.
            if (z < w || z >= rows - w) {
                band(0, cols);
            } else {
                band(0, w);
                add(w, cols - w);
                band(cols - w, cols);
            }
            break;
        }
        m_rowSums[3 * size_t(z)] = m_boundary == RippleBoundary::Fixed ? 0.0 : rowSumKernel(h, cols);
        squaresKernel(c, cols, m_rowSums.data() + 3 * size_t(z) + 1);
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
    m_volume = volumeSum(m_h, m_rows, m_cols);
    m_stale = false;
    m_vRows0 = m_rows;
    m_vRows1 = 0;
}

void EWaveField::applySources() const {
    const auto [r0, r1] = m_sources.applyTo(m_v);
    if (r0 >= r1) return;
    m_vRows0 = std::min(m_vRows0, r0);  // v's float copy is stale there
    m_vRows1 = std::max(m_vRows1, r1);
}

void EWaveField::addSource(float gx, float gz, float radiusCells, float accel, float dt) {
    const EWaveSource s{gx, gz, radiusCells, accel};
    addSources({&s, 1}, dt);
}

void EWaveField::addSources(std::span<const EWaveSource> sources, float dt) { m_sources.add(sources, dt); }

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
    for (int f = 0; f < 2; ++f) scrollCells(m_transforms.horizontal(f), m_rows, m_cols, glm::ivec2(dx, dz), glm::vec2(0.0f));
    syncHeight();
    if (!keep) return;
    m_volume = volume;
    conserveVolume(volumeSum(m_h, m_rows, m_cols));
}

void EWaveField::clear() {
    applySources();
    std::fill(m_h, m_h + m_cells, 0.0);
    std::fill(m_v, m_v + m_cells, 0.0);
    m_transforms.clearHorizontal();
    syncHeight();
}

} // namespace ob::interaction
