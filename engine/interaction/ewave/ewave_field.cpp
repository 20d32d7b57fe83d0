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
    : m_rows(rows), m_cols(cols), m_cells(size_t(rows) * size_t(cols)), m_cellSize(cellSize), m_boundary(boundary),
      m_sources(rows, cols), m_transforms(rows, cols, cellSize) {
    assert(rows >= 2 && cols >= 2 && cellSize > 0.0f);
    m_h = allocReal(m_cells);
    m_v = allocReal(m_cells);
    for (int t = 0; t < 2; ++t) m_float[t] = allocFloat(m_cells);
    if (boundary == RippleBoundary::Absorbing) m_spongeWidth = std::clamp(spongeWidth, 1, std::min(rows, cols) / 2);
    m_transforms.prepareHorizontal(m_medium);
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
    const int rowChunk = m_stepThreads > 1 ? m_rows / 2 : m_rows;  // two row bands, or one
    // --- 1. forward transforms of h and v, each whole on one worker
    parallelFor(0, 2, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) m_transforms.forward(t, m_float[t]);
    });
    // --- 2. the horizontal fields' spectra of the new state, then both spectra become their
    //        changes, in row bands
    parallelFor(0, m_rows, rowChunk, [&](int j0, int j1) { m_transforms.changeRows(j0, j1); });
    m_transforms.sumVelocityWavenumber();
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
    static constexpr int STATE[] = {0, 1}, STEP[] = {0, 2, 1, 3}, STEP_DISPLACEMENT[] = {0, 2, 4, 1, 3, 5}, DERIVED[] = {2, 3, 4, 5};
    const bool displacement = m_transforms.displacement(), velocity = m_transforms.velocity();
    const int* tasks = !velocity ? STATE : state ? (displacement ? STEP_DISPLACEMENT : STEP) : DERIVED;
    const int count = (state ? 2 : 0) + (!velocity ? 0 : displacement ? 4 : 2);
    const int chunk = m_stepThreads > 1 ? 1 : count;
    parallelFor(0, count, chunk, [&](int b, int e) {
        for (int k = b; k < e; ++k) {
            const int t = tasks[k];
            if (t < 2) {
                m_transforms.inverseChange(t);
                finishRows(t, 0, m_rows);
            } else {
                m_transforms.inverseHorizontal(t - 2);
                if (state) finishHorizontal(t - 2);  // derived from a state that had its boundary: none again
            }
        }
    });
}

// Field f of the horizontal ones after its transform: the boundary as finishRows applies it to v
// (Fixed: the outer ring 0; Absorbing: the band scaled by the sponge factors, towards 0).
void EWaveField::finishHorizontal(int f) {
    float* const u = m_transforms.horizontal(f);
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
    if (!m_transforms.velocity()) return;  // nothing to derive: the fields stay 0
    syncFloatCopies();
    const int pairChunk = m_stepThreads > 1 ? 1 : 2;
    parallelFor(0, m_transforms.displacement() ? 2 : 1, pairChunk, [&](int b, int e) {
        for (int t = b; t < e; ++t) {
            const int field = 1 - t;  // v first
            m_transforms.forward(field, m_float[field]);
        }
    });
    const int rowChunk = m_stepThreads > 1 ? m_rows / 2 : m_rows;
    parallelFor(0, m_rows, rowChunk, [&](int j0, int j1) { m_transforms.horizontalRows(j0, j1); });
    m_transforms.sumVelocityWavenumber();
    inverseTransforms(false);
}

// The step changes no mode but k = 0 of h by more than rounding, so the shift is that rounding
// (~1e-8 of the change's RMS over the field) plus, with the sponge, the water it moved:
// spread over the whole field it is the k = 0 mode alone, as a volume's rise would be.
void EWaveField::conserveVolume() {
    const double shift = (m_volume - sumKernel(m_h, m_cells)) / double(m_cells);
    shiftKernel(m_h, m_float[0], shift, m_cells);
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
        addKernel(fr, copy, m_transforms.change(t) + row, cols);
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
    for (int f = 0; f < 4; ++f) scrollCells(m_transforms.horizontal(f), m_rows, m_cols, glm::ivec2(dx, dz), 0.0f);
    syncHeight();
    if (!keep) return;
    m_volume = volume;
    conserveVolume();
}

void EWaveField::clear() {
    applySources();
    std::fill(m_h, m_h + m_cells, 0.0);
    std::fill(m_v, m_v + m_cells, 0.0);
    m_transforms.clearHorizontal();
    syncHeight();
}

} // namespace ob::interaction
