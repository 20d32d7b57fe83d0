// Dispersive ripple field ("ewave"): Tessendorf's exponential solver of the iWave equation
// (iWave 2004, eWave 2014; docs/references.md#dispersive-ripples). Height h and vertical velocity v per cell; each step
// advances every Fourier mode of the periodic grid exactly by ω(k)² = (g·k + (σ/ρ)·k³)·tanh(k·d),
// and keeps the water's volume (the mean of h): pressures and the border move water, never make it.
// Row-major rows×cols floats, row = z, column = x; h in metres, v in m/s.
#pragma once
#include "interaction/ewave/ewave_medium.h"
#include "interaction/ewave/ewave_sources.h"
#include "interaction/ewave/ewave_transforms.h"
#include "interaction/ripple_def.h"

#include <span>
#include <vector>

namespace ob::interaction {

// The edge (RippleBoundary, interaction/ripple_def.h): Periodic is the transform's own torus;
// Fixed holds the outer ring of cells at h = v = 0 after each step (waves reflect); Absorbing
// damps h and v in a sponge band in real space, so waves do not wrap around.

/// The dispersive ripple field: state (h, v) stepped exactly per Fourier mode. The facade of three
/// parts: the state itself (here: h, v, their float copies, the volume, the boundary), its
/// transforms (EWaveTransforms, ewave_transforms.h: the plans, spectra, per-mode coefficients and
/// the horizontal fields) and its sources (EWaveSources, ewave_sources.h: the stamps' sum beside v).
///
/// State in double precision, transforms in float, applied to the step's change only: a step
/// adds to (h, v) the inverse transform of (R − 1)·(ĥ, v̂), R the mode's rotation and damping
/// (in double) and 1 the identity, rather than replacing them with the inverse transform of
/// R·(ĥ, v̂). Float transforms have a fixed gain error per mode of about 1e-7 (their rounded
/// twiddle factors are not of modulus 1 exactly); replacing the state, it repeats every step
/// and the energy drifts by 1.2e-3 over 10,000 steps (measured); on the change, which is
/// ωΔt (≲ 0.2) of the state and a quarter turn out of phase with it, that error leaves the
/// energy to 3e-6 over 10,000 steps (the energy test of docs/references.md#dispersive-ripples holds 1e-5), at the cost of
/// float transforms. Beside the state the field keeps its float copy, which the forward
/// transforms read: height() is that copy of h, for the renderer, dumps and the WaterQuery. Every
/// write keeps it current (step, addHeight, scroll, clear) or marks it: the rows the sources
/// wrote into v, and edit*'s whole state, are copied again before the next step. The sources
/// themselves are summed in float beside v and added to it when v is next read or stepped.
///
/// Step (dt seconds), three passes over the workers (whether two workers pay is measured per
/// size when the field is made, measuredThreads; the bits do not depend on the split):
///   1. the forward real-to-complex transforms of the float copies of h and v (FFTW, float,
///      each whole on one worker);
///   2. per mode, in bands of row pairs: Δĥ = (a − 1)·ĥ + b·v̂, Δv̂ = c·ĥ + (a − 1)·v̂ (double;
///      a, b, c of modeStep, stored once for rows j and rows − j, which share |k|), written as
///      the whole spectrum of the complex field Δh + i·s·Δv (s a power of two that balances the
///      two); in the same pass the horizontal velocity's spectrum i·K/(|K|·tanh(|K|d))·v̂' of the new
///      v̂', as ux + i·uz, and the sums of velocityWavenumber;
///   3. one complex inverse transform of the change, in place, added to h and v with the boundary
///      in real space and the float copies in one sweep (h's row sums with it); one of the
///      horizontal velocity, and its boundary;
///   4. the volume (Periodic, Absorbing): h's sum set back to what it was, exactly (conserveVolume).
///
/// Volume. A pressure (a source) or a sponge moves water; it cannot make or remove it, so the
/// mean of h, the k = 0 mode, is the one thing a step never changes: that mode has ω(0) = 0 and
/// would only integrate v's mean, which is dropped (ĥ(0)' = ĥ(0), v̂(0)' = 0: a source's uniform
/// part is no force on incompressible water, the volume a body displaces rises around it); the
/// sponge relaxes h towards the mean level, not 0; and what the float transforms' rounding and
/// the sponge still move is put back, exactly in double, as a uniform shift of h (pass 4). The
/// volume is set by the writes: addHeight adds to it, edits recount it, scrolls keep it, clear
/// zeroes it. Fixed holds its ring at h = 0, a drain by design: it does not keep the volume.
///
/// Damping, in physical units and independent of the step size: d = exp(−Δt/τ − 2·ν·k²·Δt),
/// τ the e-folding time of every wave's amplitude (s; 0 = none) and ν the medium's viscosity
/// plus an extra one (m²/s), which damps short waves more (energy of a mode falls as
/// exp(−2t/τ − 4νk²t); water's 1e-6 m²/s takes days to damp a 5 m wave, Lamb §348).
class EWaveField {
public:
    /// Friction at the outer edge of the absorbing sponge, 1/s (see the .cpp).
    static constexpr double SPONGE_MAX_RATE = 6.0;

    /// rows (z) and cols (x) >= 2, cellSize in metres > 0; spongeWidth in cells (Absorbing),
    /// clamped to half the smaller side. h and v start at 0; no damping until setDamping.
    EWaveField(int rows, int cols, float cellSize, RippleBoundary boundary = RippleBoundary::Periodic,
               int spongeWidth = 32);
    ~EWaveField();
    EWaveField(const EWaveField&) = delete;
    EWaveField& operator=(const EWaveField&) = delete;

    /// ω(k) of the field's medium, rad/s, for a wavenumber k in rad/m.
    double omega(double k) const { return m_medium.omega(k); }
    /// One mode's step: ĥ' = a·ĥ + b·v̂, v̂' = c·ĥ + a·v̂ with a = d·cos ωΔt, b = d·sin(ωΔt)/ω,
    /// c = −d·ω·sin ωΔt, d the damping times `scale` (k = 0, the volume: a = `scale`, b = c = 0;
    /// and v̂(0)' = 0, which the step sets itself).
    struct ModeStep {
        double a, b, c;
    };
    /// ModeStep of wavenumber k (rad/m) in `medium` over dt seconds with decay time τ (s; 0 = none)
    /// and extra viscosity ν (m²/s, on top of the medium's), times `scale` (the transforms' 1/(rows·cols)). The GPU twin uses it too.
    static ModeStep modeStep(const EWaveMedium& medium, double k, float dt, float decayTime, float viscosity, double scale);
    /// modeStep's a − 1 before `scale`, times `scale`: d·cos ωΔt − 1 without the cancellation
    /// of forming it from a (the coefficient of the step's change, see the class comment).
    static double modeStepMinusOne(const EWaveMedium& medium, double k, float dt, float decayTime, float viscosity,
                                   double scale);
    /// The absorbing sponge's per-cell factors exp(−γΔt), row-major rows·cols (1 away from the
    /// band of `spongeWidth` cells), for a step of dt seconds.
    static std::vector<float> spongeFactors(int rows, int cols, int spongeWidth, float dt);

    /// Sets g, σ/ρ, the depth and the water's viscosity (until then: EWaveMedium::ideal()).
    void setMedium(const EWaveMedium& medium);
    /// Sets the extra damping: decayTime τ in s (0 = none), viscosity ν in m²/s on top of the
    /// medium's (0 = none).
    void setDamping(float decayTime, float viscosity);
    /// Advances h and v by dt seconds (> 0). Allocates nothing once dt has been seen.
    void step(float dt);

    /// Adds a smooth vertical acceleration source for dt seconds: v += dt·accel·w(r), with the
    /// biweight w(r) = (1 − r²/R²)² for r < R (smooth at its edge, so it makes no grid noise;
    /// no square root or cosine per cell) at the exact sub-cell centre (gx, gz) in cells;
    /// R = radiusCells (>= 1 used). accel in m/s²; cells outside the field are skipped.
    void addSource(float gx, float gz, float radiusCells, float accel, float dt);
    /// addSource for each of `sources` in order (the same sum; row bands on the workers when
    /// there are many and that was measured to pay for this size: the bits do not depend on
    /// the split).
    ///
    /// The sources' velocity is summed in float (8 cells a vector operation, twice double's)
    /// in a buffer beside v and added to v when v is next read or stepped: a source's share is
    /// a forcing, rounded once to 2^-24 of itself, not the state that must keep its energy.
    void addSources(std::span<const EWaveSource> sources, float dt);

    /// Scales what the sources added since v was last read or stepped at cell `index`
    /// (z·cols + x) by `factor` in [0, 1]: where a floating hull holds the water, no pressure
    /// acts on it (EWaveSolver, docs/ewave.md#hulls).
    void scaleQueuedSources(size_t index, float factor) { m_sources.scale(index, factor); }

    /// Moves the patch by (dx, dz) whole cells: the value at (x+dx, z+dz) moves to (x, z) in h
    /// and v, so waves stay put in the world. Cells with no source: v = 0 and h the mean level,
    /// and (Periodic, Absorbing) the volume is kept, what the strips that left held about the
    /// mean level put back as a uniform shift; Fixed: h = 0, the volume recounted.
    void scroll(int dx, int dz);
    /// h = v = 0 everywhere.
    void clear();

    int rows() const { return m_rows; }
    int cols() const { return m_cols; }
    float cellSize() const { return m_cellSize; }
    RippleBoundary boundary() const { return m_boundary; }
    int spongeWidth() const { return m_spongeWidth; }
    float decayTime() const { return m_decayTime; }
    float viscosity() const { return m_viscosity; }
    /// Σh, m (times the cell area: the water's volume above the rest level): what steps keep.
    double volume() const { return m_volume; }
    const EWaveMedium& medium() const { return m_medium; }

    /// The state h, rows·cols values row-major (index z·cols + x), metres.
    std::span<const double> heightState() const { return {m_h, m_cells}; }
    /// The state v = ∂h/∂t, rows·cols values row-major, m/s (the sources added so far included:
    /// the first reader after addSources applies them, so that one must not race other readers;
    /// the sandbox steps right after its sources, and reads v between steps only).
    std::span<const double> velocityState() const {
        applySources();
        return {m_v, m_cells};
    }
    /// The state to write (loaders, tests, the GPU twin's read-back). Marks the float copies for
    /// a rebuild before the next step; call syncHeight() before reading height() in between.
    std::span<double> editHeight() {
        m_stale = true;
        return {m_h, m_cells};
    }
    std::span<double> editVelocity() {
        applySources();
        m_stale = true;
        return {m_v, m_cells};
    }
    /// h += dh at cell index (z·cols + x), its float copy with it (a drop's crater).
    void addHeight(size_t index, double dh) {
        m_h[index] += dh;
        m_volume += dh;
        m_float[0][index] = float(m_h[index]);
    }
    /// h += dh in every cell (the k = 0 mode alone), its float copy with it, and the volume.
    void addLevel(double dh);
    /// h as floats, row-major, m: the float copy of the state.
    std::span<const float> height() const { return {m_float[0], m_cells}; }
    /// Rebuilds the float copies from the state (after editHeight/editVelocity) and recounts the volume.
    void syncHeight();
    /// h at column x, row z (both in range), m.
    float heightAt(int x, int z) const { return float(m_h[size_t(z) * size_t(m_cols) + size_t(x)]); }
    /// v at column x, row z (both in range), m/s.
    float velocityAt(int x, int z) const { return float(velocityState()[size_t(z) * size_t(m_cols) + size_t(x)]); }

    // --- The horizontal surface velocity (SPEC §2.5c), derived from the state, not part of it.
    /// The horizontal surface velocity of the state the last step made, (x: along a row, z: along a
    /// column) per cell, rows·cols row-major (as height()), m/s. Per Fourier mode
    /// û = i·K·φ̂ with ∂ĥ/∂t = |K|·tanh(|K|d)·φ̂, so û = i·K/(|K|·tanh(|K|d))·v̂ (deep water: i·K/|K|·v̂,
    /// the Riesz transform of v = ∂h/∂t); K = 0 and the Nyquist component of each axis give 0.
    /// Made by each step from the new state's spectrum before the boundary, then the boundary
    /// applied to it as to v (Fixed: the ring 0; Absorbing: scaled by the sponge factors); scrolls
    /// with the state (new cells 0), 0 after clear(). An edit* leaves it as it was until the
    /// next step or deriveHorizontal(). Not part of the state: nothing hashes it.
    std::span<const glm::vec2> horizontalVelocity() const { return {m_transforms.horizontal(0), m_cells}; }
    /// The horizontal displacement of the surface, ξ̂ = i·K/(|K|·tanh(|K|d))·ĥ (∂ξ/∂t = u), m, as
    /// horizontalVelocity; all 0 unless keepHorizontalDisplacement(true) (the coarse levels' Hermite
    /// in time reads it: EWaveLevels).
    std::span<const glm::vec2> horizontalDisplacement() const { return {m_transforms.horizontal(1), m_cells}; }
    /// Whether the steps make horizontalDisplacement too (one more packed inverse transform a step).
    void keepHorizontalDisplacement(bool on);
    /// Whether the steps make horizontalVelocity (on unless told: its packed inverse transform and
    /// its share of the spectral pass). Off, it and velocityWavenumber read 0: the step without the
    /// velocity (BM_EWaveStep's `velocity` argument); h and v are the same bits either way.
    void keepHorizontalVelocity(bool on);
    /// The wavenumber the vertical velocity's variance is centred on, Σ|K|·|v̂|² / Σ|v̂|² over the
    /// modes K ≠ 0 of the state the last step made (before the boundary), rad/m; 0 when still.
    double velocityWavenumber() const { return m_transforms.velocityWavenumber(); }
    /// Derives the horizontal fields and velocityWavenumber from the state as it is now (after
    /// edit*, or a GPU twin's read-back): one forward transform of v (and of h with the
    /// displacement) and the inverse ones; no boundary (the state has had its own).
    void deriveHorizontal();
    /// Scales the horizontal velocity and displacement at cell `index` (z·cols + x) by `factor`
    /// in [0, 1]: towards 0 inside a body, as the obstruction scales v (obstructField).
    void scaleHorizontal(size_t index, float factor) {
        for (int f = 0; f < 2; ++f) m_transforms.horizontal(f)[index] *= factor;
    }

private:
    void chooseThreads();
    void prepare(float dt);
    void applySources() const;  // the sources' float sums into v, their rows marked for the float copy
    void finishRows(int z0, int z1);  // pass 3 for h and v (and h's row sums)
    void finishHorizontal(int f);  // the boundary on horizontal field f (0: u; 1: ξ)
    void inverseTransforms(bool state);  // pass 3 (state: h and v too) over the workers
    void syncFloatCopies();  // before the forward transforms
    void conserveVolume(double sum);  // pass 4: h += (volume − sum)/cells, sum = Σh

    int m_rows, m_cols;
    size_t m_cells;
    float m_cellSize;
    RippleBoundary m_boundary;
    int m_spongeWidth = 0;
    float m_decayTime = 0.0f, m_viscosity = 0.0f;
    double m_volume = 0.0;             // Σh the step keeps (addHeight adds to it, syncHeight recounts it), m
    EWaveMedium m_medium = EWaveMedium::ideal();
    float m_preparedDt = -1.0f;        // dt of the coefficients (and the sponge factors)
    int m_stepThreads = 1;             // the step's passes on 1 or 2 workers (measured, chooseThreads)
    bool m_stale = false;              // the state was written through edit*: m_float needs a rebuild
    mutable int m_vRows0 = 0, m_vRows1 = 0;  // rows [m_vRows0, m_vRows1) of v written by sources since m_float[1] was made
    double* m_h = nullptr;             // fftw_alloc'd real arrays, rows·cols
    double* m_v = nullptr;
    float* m_float[2] = {};            // per field (h, v): float(state), rows·cols; the forward transforms' input
    std::vector<float> m_sponge;       // per cell: the factor exp(−γΔt) (Absorbing), 1 away from the band
    std::vector<double> m_rowSums;     // per row, from the step's pass 3 (finishRows): Σh (for pass 4), Σ(Δh)², Σ(s·Δv)² (balance)
    // The sources' velocity not yet in v, applied by the readers of v (logically const).
    mutable EWaveSources m_sources;
    EWaveTransforms m_transforms;
};

} // namespace ob::interaction
