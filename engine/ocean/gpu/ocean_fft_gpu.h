// GPU spectral ocean: compute shaders synthesise h̃(K,t) and the packed derivative spectra,
// run the 2-D inverse FFT (radix-2 DIT, stages paired into radix-4 steps, one line per
// workgroup in shared memory, rows then columns; [Lee2007] §3.3, [CodingTower]) and write
// OceanTextures with imageStore. The CPU twin is OceanFftCpu.
#pragma once
#include "gfx/handles.h"
#include "ocean/ocean_def.h"
#include "ocean/spectrum.h"

#include <vector>

namespace ob::ocean {

class OceanTextures;

/// The FFT ocean on the GPU: same h̃0 (CascadeSpectrum(def, c)), same packing (eq. 9: (h,
/// ∂Dx/∂z), (Dx, Dz), (∂h/∂x, ∂h/∂z), (∂Dx/∂x, ∂Dz/∂z)) and same unnormalised transform
/// (eq. 1) as OceanFftCpu, so both backends give equal maps up to float rounding.
///
/// Time precision: t goes to the GPU as a double, and ω·t is formed and reduced mod 2π per
/// mode in double (fp64 is core since GL 4.0; one multiply and a rounding per mode), as the
/// CPU path does: the phase error is ~1e-16·ω·t rad, < 1e-6 rad for ω·t < 10⁹ rad (days of
/// sim time). The reduced phase and everything after it is float. (A float ω·t would be off
/// by ~1e-4 rad at t = 1000 s, 1e-2 rad after a day.)
///
/// Cost: 4 dispatches per update (synthesis, row FFTs, column FFTs, unpack), each reading and
/// writing the 4·C·N² complex work buffer once. On llvmpipe (2-core EPYC, measured with
/// `tests_gl "[.ocean_gpu_bench]"`) it takes 2.5 / 6.3 / 21 / 74 ms at N = 64 / 128 / 256 / 512
/// against 0.03 / 0.15 / 0.47 / 2.2 ms for OceanFftCpu + 0.01–0.5 ms for OceanTextures::upload:
/// on a software renderer the CPU backend is the faster choice.
class OceanFftGpu {
public:
    /// Largest N: one row of complex floats must fit the 16 KiB shared array of ocean_fft.comp.
    static constexpr int MAX_RESOLUTION = 2048;

    /// Builds every cascade's h̃0 like OceanFftCpu (CascadeSpectrum(def, c)), uploads it with ω
    /// and 1/k once, and compiles the shaders. Needs a current GL context. Throws
    /// ob::InputError naming the key for resolution not a power of two in [4, 2048], cascades
    /// outside [1, 4] or non-positive sizes; ob::RuntimeError when a shader fails to build.
    explicit OceanFftGpu(const OceanDef& def);

    /// Writes level 0 of every layer of out (resolution and cascade count must match) with
    /// the maps at time t, seconds (any t). No CPU round trip; ends with a memory barrier, so
    /// sampling, glGetTextureImage and generateMipmaps() see the result.
    void update(double t, OceanTextures& out);

    /// Replaces cascade c's h̃0, ω and k with those of s (tests, tools: CascadeSpectrum::setH0).
    /// s must have this resolution; its patch size becomes cascade c's.
    void setSpectrum(int cascade, const CascadeSpectrum& s);

    /// N, points per side of every cascade.
    int resolution() const { return m_n; }
    /// Number of cascades, [1, 4].
    int cascadeCount() const { return int(m_patchSizes.size()); }
    /// Side of cascade c's tile, metres.
    double patchSize(int cascade) const { return m_patchSizes[size_t(cascade)]; }
    /// λ of X + λ·D and of the Jacobian: −choppiness.
    float lambda() const { return m_lambda; }
    /// Sets λ for the next update() (a live change of ocean.choppiness).
    void setLambda(float lambda);
    /// Time of the last update(), seconds (0 before the first).
    double time() const { return m_time; }

    /// Benchmarks: with profiling on, update() finishes the GL queue before and after the
    /// inverse FFT dispatches (stage 2) and keeps their wall time ([Lee2007] Table 3's "FFT
    /// only"). Off by default: the two glFinish calls stall the pipeline.
    void setProfiling(bool on) { m_profiling = on; }
    /// Wall ms of the last profiled update()'s FFT dispatches (0 when not profiling).
    double lastTransformMs() const { return m_transformMs; }

private:
    int m_n = 0;
    int m_log2n = 0;
    float m_lambda = 0.0f;
    double m_time = 0.0;
    bool m_profiling = false;
    double m_transformMs = 0.0;
    std::vector<double> m_patchSizes;
    gfx::Program m_synthesize;   // ocean_spectrum.comp: h̃(K,t) → four packed spectra
    gfx::Program m_fft;          // ocean_fft.comp: N-point inverse DFT of rows or columns, in place
    gfx::Program m_unpack;       // ocean_unpack.comp: packed fields → displacement, slopes, J
    gfx::Buffer m_modes;         // per cascade, N² vec4 FFT order: (cosRe, sinRe, cosIm, sinIm) of h̃
    gfx::Buffer m_quarter;       // per cascade, (N/2+1)² {double ω; float 1/k; pad} by [|m|][|n|]
    gfx::Buffer m_waveNumbers;   // per cascade, N floats: 2π·s/L per FFT-order position s
    gfx::Buffer m_twiddles;      // N/2 vec2: exp(+2πi·k/N), computed in double
    gfx::Buffer m_spectra;       // per cascade, 4 × N² vec2 [transform][row][col]: FFT in place
};

} // namespace ob::ocean
