// The ewave field's spectral half (EWaveField, ewave_field.h): the FFTW plans and spectra, the
// per-mode step's coefficients, and the horizontal surface velocity and displacement derived from
// the new state's spectrum (SPEC §2.5c; docs/ewave.md).
#pragma once
#include "interaction/ewave/ewave_medium.h"

#include <array>
#include <cstddef>
#include <glm/vec2.hpp>
#include <vector>

struct fftwf_plan_s;

namespace ob::interaction {

/// What the field's step does in Fourier space, on float arrays it owns (FFTW-aligned):
///   - forward(t, copy): the real-to-complex transform of field t's float copy (0: h, 1: v) into
///     spectrum t;
///   - changeRows: per mode of the half spectrum, Δĥ = (a − 1)·ĥ + b·v̂, Δv̂ = c·ĥ + (a − 1)·v̂
///     (double; a, b, c of EWaveField::modeStep times 1/(rows·cols), stored once for rows j and
///     rows − j, which share |K|), written packed: the whole spectrum of Δh + i·s·Δv (s a power of
///     two, changeScale); in the same pass the horizontal fields' spectra i·K/(|K|·tanh(|K|d))·(v̂', ĥ')
///     of the new state, packed as ux + i·uz (ξx + i·ξz), and the sums of velocityWavenumber;
///   - inverseChange: one complex transform of the packed change, in place: (Δh, s·Δv) per cell;
///   - inverseHorizontal(f): one complex transform, in place: (ux, uz) or (ξx, ξz) per cell.
/// Two real fields a, b whose spectra are Hermitian make one complex field a + i·b: its spectrum
/// at K is â(K) + i·b̂(K), at −K conj(â(K)) + i·conj(b̂(K)), both written from the half spectrum's
/// mode K; one complex inverse transform of it gives a and b interleaved, for about 3/4 of the
/// cost of their two real ones (FFTW, float, measured: docs/ewave.md). The scale s brings s·Δv to
/// Δh's size (the ratio of their norms at the last step, to the nearest power of two, so it is
/// exact: balance): the transform's rounding, a fraction of the larger of the two, stays a
/// fraction of each.
/// Each transform is whole on one thread; the row pairs of changeRows may be split over two
/// workers, pairs [0, pairs()/2) and the rest (the bits do not depend on the split). The field adds the changes to its state and applies its boundary.
class EWaveTransforms {
public:
    /// rows (z) and cols (x) >= 2, cellSize in metres > 0; plans measured (or read from the shared
    /// wisdom) here.
    EWaveTransforms(int rows, int cols, float cellSize);
    ~EWaveTransforms();
    EWaveTransforms(const EWaveTransforms&) = delete;
    EWaveTransforms& operator=(const EWaveTransforms&) = delete;

    /// The per-mode coefficients for a step of dt in `medium` with decay time τ (s; 0 = none) and
    /// extra viscosity ν (m²/s).
    void prepare(const EWaveMedium& medium, float dt, float decayTime, float viscosity);
    /// The horizontal fields' per-mode factors of `medium` (its depth: tanh(|K|d)).
    void prepareHorizontal(const EWaveMedium& medium);
    /// Whether changeRows makes the velocity's spectrum (and the field runs its inverse transform);
    /// on unless told (off: the horizontal fields and velocityWavenumber stay 0; not with the displacement).
    void keepVelocity(bool on);
    bool velocity() const { return m_velocity; }
    /// Whether changeRows makes the displacement's spectrum too (and one more inverse transform runs).
    void keepDisplacement(bool on);
    bool displacement() const { return m_displacement; }

    /// Pass 1 for field t (0: h, 1: v): r2c of `copy` (rows·cols floats, FFTW-aligned) into spectrum t.
    void forward(int t, const float* copy);
    /// The row pairs changeRows and horizontalRows take: p = 0..rows/2, rows p and rows − p.
    int pairs() const { return m_rows / 2 + 1; }
    /// Pass 2 on the spectrum's row pairs [p0, p1): the packed change and the horizontal fields'
    /// spectra of the new state. Mode 0: its coefficients are 0, so ĥ(0) is kept, and v̂(0) is dropped
    /// (Δv̂(0) = −v̂(0)): a source's uniform part lifts no water.
    void changeRows(int p0, int p1);
    /// After changeRows over all rows: the sums of velocityWavenumber, in row order (the same bits
    /// whatever the split).
    void finishChange();
    /// The next changeRows' scale from the last change's sums over the cells of Δh² and (s·Δv)²
    /// (Parseval: its spectra's norms), to the nearest power of two.
    void balance(double sumH2, double sumV2);
    /// deriveHorizontal's pass 2: the horizontal fields' spectra of the state as transformed.
    void horizontalRows(int p0, int p1);
    /// The rows' sums into velocityWavenumber, in row order (the same bits whatever the split).
    void sumVelocityWavenumber();
    /// Pass 3 for the state: the packed change's inverse transform, in place (change()).
    void inverseChange();
    /// Pass 3 for horizontal field f (0: u, 1: ξ), in place (horizontal(f)).
    void inverseHorizontal(int f);

    /// The change in real space after inverseChange: rows·cols pairs (Δh, s·Δv), s = changeScale().
    const float* change() const { return m_full[0]; }
    /// The scale of Δv in change() (a power of two), used by the last changeRows.
    float changeScale() const { return m_usedScale; }
    /// Horizontal field f (0: u, m/s; 1: ξ, m), rows·cols pairs (x, z) row-major.
    glm::vec2* horizontal(int f) { return reinterpret_cast<glm::vec2*>(m_full[1 + f]); }
    const glm::vec2* horizontal(int f) const { return reinterpret_cast<const glm::vec2*>(m_full[1 + f]); }
    /// Σ|K|·|v̂'|² / Σ|v̂'|² over K ≠ 0 of the last changeRows/horizontalRows, rad/m; 0 when still.
    double velocityWavenumber() const { return m_velocityWavenumber; }
    /// Every horizontal field and velocityWavenumber 0 (a cleared field).
    void clearHorizontal();

private:
    void changeRow(int j, float* staged);   // changeRows' row j (see the .cpp)
    void horizontalRow(int j, bool change, float* staged);  // û (ξ̂) of spectrum row j's new state, its sums (see the .cpp)
    float* stagedRows(int p0);               // the band's scratch for the −K values (the .cpp's packing)
    std::array<int, 2> pair(int p) const;    // the rows of pair p (−1: none)
    float rowKz(int j) const;                // kz of spectrum row j, rad/m (0 at the Nyquist row)
    // Full-spectrum rows of a packed array: row j's own half (columns 0..cols/2) and the row whose
    // columns cols − i mirror row j's columns i (row (rows − j) mod rows).
    float* fullRow(int f, int j) { return m_full[f] + 2 * size_t(j) * size_t(m_cols); }
    float* mirrorRow(int f, int j) { return fullRow(f, (m_rows - j) % m_rows); }

    int m_rows, m_cols, m_specCols;
    size_t m_cells, m_modes;
    float m_cellSize;
    float* m_spec[2] = {};             // per field: its spectrum, complex rows × (cols/2 + 1) (re, im)
    // Packed whole spectra, complex rows × cols, then in place their inverse transforms' pairs:
    // 0 the change (Δh, s·Δv), 1 the velocity (ux, uz, m/s), 2 the displacement (ξx, ξz, m).
    float* m_full[3] = {};
    fftwf_plan_s* m_forward = nullptr;   // r2c rows × cols, out of place, input kept (new-array execute)
    fftwf_plan_s* m_backward = nullptr;  // complex rows × cols, backward, in place
    std::vector<double> m_coef;        // per row 0..rows/2, three planes of its modes: a − 1, b, c (modeStep's, times 1/(rows·cols))
    std::vector<float> m_riesz;        // per mode of rows 0..rows/2: 1/(|K|·tanh(|K|d)), m; 0 at K = 0
    std::vector<float> m_kabs;         // per mode of rows 0..rows/2: |K|, rad/m
    std::vector<float> m_kx;           // per spectrum column: kx, rad/m, 0 at the Nyquist column
    std::vector<float> m_weight;       // per spectrum column: its modes' count in the full spectrum (1 or 2)
    std::vector<double> m_rowSums;     // per spectrum row: Σw·|K|·|v̂'|², Σw·|v̂'|² (velocityWavenumber)
    std::vector<float> m_power;        // per mode: w·|v̂'|² (the step's fused pass, summed per row after it)
    std::vector<float> m_staged;       // per band of rows (two at most): a row's −K values of two packed arrays
    double m_velocityWavenumber = 0.0; // rad/m
    float m_scale = 1.0f;              // the next changeRows' s (balance)
    float m_usedScale = 1.0f;          // changeScale: the last changeRows' s
    bool m_velocity = true;            // keepVelocity
    bool m_displacement = false;       // keepDisplacement
};

} // namespace ob::interaction
