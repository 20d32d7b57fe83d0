// Dispersive ripple field on the GPU: the compute-shader twin of EWaveField::step (docs/references.md#dispersive-ripples;
// Tessendorf, eWave 2014) on the ocean's line FFT (shaders/ocean_fft.comp) and
// shaders/ewave_step.comp, tested against the CPU field.
#pragma once
#include "gfx/handles.h"
#include "interaction/ewave/ewave_field.h"

#include <span>
#include <vector>

namespace ob::interaction {

/// N×N ewave state (h, v) in one GPU buffer of complex floats, stepped by compute shaders.
///
/// Packing: one complex field carries both real fields, stored conjugated, w = h − i·v, so
/// that ocean_fft.comp's unnormalised e^{+2πi} line transform (rows, then columns) gives
/// S = conj(Z), Z the forward transform of h + i·v. Per mode (ewave_step.comp) H(K) =
/// (Z(K) + conj Z(−K))/2 and V(K) = (Z(K) − conj Z(−K))/(2i) are rotated exactly as
/// EWaveField::step does (the same EWaveField::modeStep coefficients, rounded to float once)
/// and written as conj Z'(−K), whose e^{+} transform is w' again: one transform forward, one
/// back, per step (FFTW needs two real ones each way). Then the boundary in real space: the
/// ring held at 0 (Fixed) or the CPU's sponge factors (Absorbing; EWaveField::spongeFactors)
/// towards the mean level, whose volume a sum over the field and a uniform shift then restore
/// (as EWaveField's conserveVolume, in float). The k = 0 mode keeps h's mean and drops v's.
///
/// Precision: float state and transforms. Each step's two transforms round at 2·log2 N
/// butterfly stages; the tests bound the difference to the CPU's double field after 100 steps
/// (tests_gl "[ewave_gpu]"). Sources are added on the CPU (EWaveField::addSource on the
/// mirror) and uploaded; see RipplePatch.
///
/// Cost (llvmpipe, 2 cores): see docs/benchmarks.md; a step is 6 dispatches (8 with the
/// absorbing border), no CPU round trip.
/// Needs a current GL 4.3+ context for its whole life.
class EWaveGpu {
public:
    /// Largest N: a line must fit ocean_fft.comp's shared array.
    static constexpr int MAX_RESOLUTION = 2048;

    /// Whether a rows × cols field can run here: square, N a power of two in [4, MAX_RESOLUTION].
    static bool supports(int rows, int cols);

    /// A GPU field of `like`'s size, cell size, boundary, sponge width and damping, holding its
    /// state (h, v rounded to float). supports(like.rows(), like.cols()) must hold. Throws
    /// ob::RuntimeError if a shader fails to build.
    explicit EWaveGpu(const EWaveField& like);
    EWaveGpu(const EWaveGpu&) = delete;
    EWaveGpu& operator=(const EWaveGpu&) = delete;

    /// As EWaveField::setDamping: decay time τ in s (0 = none), viscosity ν in m²/s (0 = none).
    void setDamping(float decayTime, float viscosity);
    /// Advances h and v by dt seconds (> 0), as EWaveField::step. No CPU round trip.
    void step(float dt);

    /// Replaces the state: h (m) and v (m/s), N² values each, row-major.
    void upload(std::span<const double> h, std::span<const double> v);
    /// Copies the state of a CPU field of the same size.
    void upload(const EWaveField& field) { upload(field.heightState(), field.velocityState()); }
    /// Writes the state into h and v (N² each). STALLS until every queued dispatch is done.
    void download(std::span<double> h, std::span<double> v) const;

    /// N, cells per side.
    int resolution() const { return m_n; }
    /// The boundary in use.
    RippleBoundary boundary() const { return m_boundary; }

private:
    void prepare(float dt);
    void transform(const gfx::Buffer& field);
    void dispatchStep(int mode, GLuint groups);  // ewave_step.comp in `mode` on groups × groups work groups

    int m_n = 0, m_log2n = 0;
    float m_cellSize;
    RippleBoundary m_boundary;
    int m_spongeWidth;
    float m_decayTime = 0.0f, m_viscosity = 0.0f;
    EWaveMedium m_medium = EWaveMedium::ideal();  // `like`'s g and σ/ρ
    float m_preparedDt = -1.0f;  // dt of m_rotation and m_sponge
    GLuint m_groups = 1;         // work groups of ewave_step.comp per axis
    gfx::Program m_fft;          // ocean_fft.comp: e^{+} transform of every row or column, in place
    gfx::Program m_step;         // ewave_step.comp: mode rotation, ring, sponge
    gfx::Buffer m_fields[2];     // w = h − i·v (N² vec2); the step transforms [0], writes [1], swaps
    gfx::Buffer m_rotation;      // (N/2 + 1)² vec4 (a, b, c, 0) by |row index|, |column index|
    gfx::Buffer m_sponge;        // N² float exp(−γΔt) (Absorbing)
    gfx::Buffer m_sum;           // groups² + 1 floats: Σh per work group, then their total (Absorbing)
    double m_level = 0.0;        // the mean of h at the last upload, m: what the absorbing border keeps
    gfx::Buffer m_twiddles;      // N/2 vec2 exp(+2πi·k/N), computed in double
    mutable std::vector<float> m_staging;  // upload / download: interleaved (h, −v)
};

} // namespace ob::interaction
