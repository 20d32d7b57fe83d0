// CPU spectral ocean: per cascade, h̃(K,t) and its derivative spectra inverse-transformed with
// FFTW, two real fields per complex transform. docs/references.md#spectral-ocean eq. 1–9; [Lee2007] §2.1, §3.3.
#pragma once
#include "ocean/displacement_bounds.h"
#include "ocean/ocean_def.h"
#include "ocean/ocean_texels.h"
#include "ocean/spectrum.h"
#include "ocean/velocity_bands.h"

#include <memory>
#include <vector>

struct fftwf_plan_s;

namespace ob::ocean {

/// One output map of a cascade: N×N floats, row-major [j][i], j along z, i along x, at the
/// point X = (i·L/N, j·L/N) of the tile (L = the cascade's patch size).
enum class OceanChannel : int {
    Height = 0,   ///< h, metres (eq. 1)
    DispX = 1,    ///< Dx, metres (eq. 7), not multiplied by λ
    DispZ = 2,    ///< Dz, metres (eq. 7), not multiplied by λ
    SlopeX = 3,   ///< ∂h/∂x, dimensionless (eq. 6)
    SlopeZ = 4,   ///< ∂h/∂z, dimensionless (eq. 6)
    Jacobian = 5, ///< J = (1+λ∂Dx/∂x)(1+λ∂Dz/∂z) − (λ∂Dx/∂z)² of X → X + λD; < 1 compresses, ≤ 0 folds (foam)
};

/// Number of OceanChannel maps.
constexpr int OCEAN_CHANNEL_COUNT = 6;
/// Channels of the `dump ocean` array [N, N, 5]: h, Dx, Dz, ∂h/∂x, ∂h/∂z (docs/references.md#contracts).
constexpr int OCEAN_DUMP_CHANNELS = 5;
/// Packed complex transforms per cascade (PackedSpectra, eq. 9).
constexpr int OCEAN_PACKED_TRANSFORMS = 4;

/// The FFT ocean on the CPU (FFTW single precision). Plans are measured once per machine and
/// shared through FFTW wisdom in $XDG_CACHE_HOME/oceanbox/fftw_wisdom_f (else
/// ~/.cache/oceanbox/fftw_wisdom_f, under a file lock), so every run uses the same plan and
/// gets the same bits; without a writable cache, FFTW_ESTIMATE plans (also the same every run).
class OceanFftCpu {
public:
    /// Builds every cascade of def (seeded h̃0, FFT plans). threads: workers for update(),
    /// 0 = auto (from N = 128 on, 1 or all of ob::workerCount() up to 4, whichever was measured
    /// faster for this N and cascade count on this machine, see measuredThreads; 1 below). Any count gives the
    /// same bits: each transform runs whole on one thread, the other stages point by point. Throws ob::InputError
    /// naming the key for a def no loader would accept (resolution not a power of two in
    /// [4, 4096], cascades outside [1, 4], non-positive sizes).
    explicit OceanFftCpu(const OceanDef& def, int threads = 0);
    ~OceanFftCpu();
    OceanFftCpu(const OceanFftCpu&) = delete;
    OceanFftCpu& operator=(const OceanFftCpu&) = delete;

    /// Computes every cascade's channels at time t, seconds (any t; equal t, equal maps), and
    /// with setMakeTexels the renderer's texels of them.
    void update(double t);
    /// With `on`, every later update() also makes the renderer's texels of its maps (OceanTexels:
    /// the interleaved layers and their mips) on the thread that runs it: a view's CPU backend.
    void setMakeTexels(bool on);
    bool makesTexels() const { return m_texels != nullptr; }
    /// The texels of the last update(), or null (off, or none made since it was turned on).
    const OceanTexels* texels() const { return m_texels && m_texels->time == m_time ? m_texels.get() : nullptr; }

    /// Time of the last update(), seconds (0 before the first).
    double time() const { return m_time; }
    /// N, points per side of every cascade.
    int resolution() const { return m_n; }
    /// Number of cascades, [1, 4].
    int cascadeCount() const { return int(m_cascades.size()); }
    /// Side of cascade c's tile, metres.
    double patchSize(int cascade) const;
    /// λ of X + λ·D and of the Jacobian: −choppiness (SPEC eq. 7 sign: λ < 0 sharpens crests).
    float lambda() const { return m_lambda; }
    /// Sets λ for the next update() (a live change of ocean.choppiness: λ = −choppiness).
    void setLambda(float lambda) { m_lambda = lambda; }
    /// Workers update() uses.
    int threadCount() const { return m_threads; }
    /// With `on` (the default), every later update() also makes each cascade's velocity band maps
    /// (velocityPacked: transforms() more packed FFTs a cascade, the depth decay of the water's
    /// velocity under the surface); off, a query decays the cascade as one band.
    void setVelocityBands(bool on) { m_velocityBands = on; }
    /// Whether update() makes the velocity band maps.
    bool makesVelocityBands() const { return m_velocityBands; }
    /// Cascade c's velocity bands: knots and per-mode weights (fixed by N, the tile and its band of k).
    const VelocityBands& velocityBands(int cascade) const;
    /// Velocity transform k ∈ [0, velocityBands(c).transforms()) of cascade c from the last
    /// update(), or null when that update made none: N·N interleaved pairs, row-major [j][i],
    /// (w_b, u_b) for k = b < E, (v_2j, v_2j+1) for k = E + j (E = mappedBands(); m/s: the
    /// vertical velocity and the orbit's x and z velocity −∂D/∂t of band b's share of the modes).
    const float* velocityPacked(int cascade, int k) const;

    /// Wall ms of the last update()'s stages (seen from the calling thread; barriers end each).
    struct StageMs {
        double synthesis = 0.0;   ///< eq. 2, 6, 7 into the packed spectra
        double transforms = 0.0;  ///< the packed inverse FFTs (FFTW)
        double unpack = 0.0;      ///< channels and the Jacobian
    };
    /// Stage times of the last update() (benchmarks: [Lee2007] Table 3's "FFT only").
    const StageMs& lastStageMs() const { return m_stageMs; }

    /// Channel ch of cascade c after the last update(): N·N floats, row-major [j][i].
    const float* channel(int cascade, OceanChannel ch) const;
    /// How far the maps of the last update() move a rest point, all cascades together: the
    /// extremes of h over the texels, and the largest |λ·(Dx, Dz)|. Any texture filtering
    /// (bilinear, mip averages) stays within them.
    DisplacementBounds displacementBounds() const;
    /// Writes cascade c as [N][N][5] floats (h, Dx, Dz, ∂h/∂x, ∂h/∂z per point) into out.
    void fillDump(int cascade, float* out) const;
    /// Raw result of packed transform k ∈ [0, 4): N·N interleaved pairs, row-major [j][i]:
    /// 0 (h, ∂Dx/∂z), 1 (Dx, Dz), 2 (∂h/∂x, ∂h/∂z), 3 (∂Dx/∂x, ∂Dz/∂z).
    const float* packed(int cascade, int k) const;

    /// Cascade c's spectrum (h̃0 may be edited by hand; update() picks the edit up).
    CascadeSpectrum& spectrum(int cascade);
    /// Cascade c's spectrum.
    const CascadeSpectrum& spectrum(int cascade) const;

private:
    struct Cascade;
    void synthesizeRows(int pairBegin, int pairEnd);
    void transform(int index);
    void unpackRows(int rowBegin, int rowEnd);
    void updateMaps(double t);
    int transformCount() const;

    int m_n = 0;
    int m_threads = 1;
    float m_lambda = 0.0f;
    double m_time = 0.0;
    bool m_velocityBands = true;
    double m_velocityTime = -1.0;  // time of the velocity band maps (< 0: none)
    StageMs m_stageMs;
    fftwf_plan_s* m_plan = nullptr;  // one in-place backward plan for every buffer (new-array execute)
    std::vector<std::unique_ptr<Cascade>> m_cascades;
    std::vector<float*> m_velocityBuffers;  // every cascade's velocity transforms in order (fftwf_complex arrays)
    std::unique_ptr<OceanTexels> m_texels;  // setMakeTexels
};

} // namespace ob::ocean
