// The ewave field's spectral half (EWaveField, ewave_field.h): the FFTW plans and spectra, the
// per-mode step's coefficients, and the horizontal surface velocity and displacement derived from
// the new state's spectrum (SPEC §2.5c; docs/ewave.md).
#pragma once
#include "interaction/ewave/ewave_medium.h"

#include <cstddef>
#include <vector>

struct fftwf_plan_s;

namespace ob::interaction {

/// What the field's step does in Fourier space, on float arrays it owns (FFTW-aligned):
///   - forward(t, copy): the real-to-complex transform of field t's float copy (0: h, 1: v) into
///     spectrum t;
///   - changeRows: per mode, in place, Δĥ = (a − 1)·ĥ + b·v̂, Δv̂ = c·ĥ + (a − 1)·v̂ (double; a, b, c
///     of EWaveField::modeStep times 1/(rows·cols), stored once for rows j and rows − j, which
///     share |K|), and in the same pass the horizontal fields' spectra i·K/(|K|·tanh(|K|d))·(v̂', ĥ')
///     of the new state and the sums of velocityWavenumber;
///   - inverseChange(t): the complex-to-real transform of spectrum t (now its change) into change(t);
///   - inverseHorizontal(f): field f of ux, uz, ξx, ξz into horizontal(f).
/// Each transform is whole on one thread; rows of changeRows may be split over workers (the bits
/// do not depend on the split). The field adds the changes to its state and applies its boundary.
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
    /// Whether changeRows makes the velocity's spectra (and the field runs their inverse transforms);
    /// on unless told (off: the horizontal fields and velocityWavenumber stay 0; not with the displacement).
    void keepVelocity(bool on);
    bool velocity() const { return m_velocity; }
    /// Whether changeRows makes the displacement's spectra too (and two more inverse transforms run).
    void keepDisplacement(bool on);
    bool displacement() const { return m_displacement; }

    /// Pass 1 for field t (0: h, 1: v): r2c of `copy` (rows·cols floats, FFTW-aligned) into spectrum t.
    void forward(int t, const float* copy);
    /// Pass 2 on spectrum rows [j0, j1): the horizontal fields' spectra of the new state, then both
    /// spectra become their changes. Mode 0: its coefficients are 0, so ĥ(0) is kept, and v̂(0) is
    /// dropped (Δv̂(0) = −v̂(0)): a source's uniform part lifts no water.
    void changeRows(int j0, int j1);
    /// deriveHorizontal's pass 2: the horizontal fields' spectra of the state as transformed.
    void horizontalRows(int j0, int j1);
    /// The rows' sums into velocityWavenumber, in row order (the same bits whatever the split).
    void sumVelocityWavenumber();
    /// Pass 3 for field t: c2r of its change's spectrum into change(t) (destroys the spectrum).
    void inverseChange(int t);
    /// Pass 3 for horizontal field f (0, 1: ux, uz; 2, 3: ξx, ξz) into horizontal(f).
    void inverseHorizontal(int f);

    /// Field t's change in real space, rows·cols floats (after inverseChange).
    const float* change(int t) const { return m_change[t]; }
    /// Horizontal field f, rows·cols floats row-major (ux, uz in m/s; ξx, ξz in m).
    float* horizontal(int f) { return m_horiz[f]; }
    const float* horizontal(int f) const { return m_horiz[f]; }
    /// Σ|K|·|v̂'|² / Σ|v̂'|² over K ≠ 0 of the last changeRows/horizontalRows, rad/m; 0 when still.
    double velocityWavenumber() const { return m_velocityWavenumber; }
    /// Every horizontal field and velocityWavenumber 0 (a cleared field).
    void clearHorizontal();

private:
    void horizontalRow(int j, bool change);  // û (ξ̂) of spectrum row j's new state, its sums (see the .cpp)
    float rowKz(int j) const;                // kz of spectrum row j, rad/m (0 at the Nyquist row)

    int m_rows, m_cols, m_specCols;
    size_t m_cells, m_modes;
    float m_cellSize;
    float* m_spec[2] = {};             // per field: its spectrum, then its change's, complex rows × (cols/2 + 1) (re, im)
    float* m_change[2] = {};           // per field: its change in real space, rows·cols
    fftwf_plan_s* m_forward = nullptr;   // r2c rows × cols, out of place, input kept (new-array execute)
    fftwf_plan_s* m_backward = nullptr;  // c2r, out of place (destroys its input)
    std::vector<double> m_coef;        // per mode of rows 0..rows/2: a − 1, b, c (modeStep's, times 1/(rows·cols))
    // The horizontal fields: ux, uz (m/s), ξx, ξz (m).
    float* m_horiz[4] = {};            // rows·cols each, row-major: the inverse transforms' output
    float* m_horizSpec[4] = {};        // their spectra, complex rows × (cols/2 + 1)
    std::vector<float> m_riesz;        // per mode of rows 0..rows/2: 1/(|K|·tanh(|K|d)), m; 0 at K = 0
    std::vector<float> m_kabs;         // per mode of rows 0..rows/2: |K|, rad/m
    std::vector<float> m_kx;           // per spectrum column: kx, rad/m, 0 at the Nyquist column
    std::vector<float> m_weight;       // per spectrum column: its modes' count in the full spectrum (1 or 2)
    std::vector<double> m_rowSums;     // per spectrum row: Σw·|K|·|v̂'|², Σw·|v̂'|² (velocityWavenumber)
    std::vector<float> m_power;        // per mode: w·|v̂'|² (the step's fused pass, summed per row after it)
    double m_velocityWavenumber = 0.0; // rad/m
    bool m_velocity = true;            // keepVelocity
    bool m_displacement = false;       // keepDisplacement
};

} // namespace ob::interaction
