// Wave spectra and the time-dependent spectrum h̃(K,t) of the FFT ocean: docs/references.md#spectral-ocean eq. 2–7
// ([Lee2007] §2.1, [CodingTower] "Phillips"/"hTilde"); JONSWAP after Hasselmann et al. 1973.
#pragma once
#include "core/random.h"
#include "ocean/ocean_def.h"

#include <array>
#include <complex>
#include <cstdint>
#include <vector>

namespace ob::ocean {

// ---------------------------------------------------------------------------------------
// Noise (eq. 4): a portable generator, so a seed gives the same sea with any C++ library.

/// Standard normal samples from SplitMix64 uniforms and the Box–Muller transform, written
/// out (std::normal_distribution differs between libraries); same stream for a seed wherever
/// libm's log/sin/cos round correctly (glibc), otherwise within an ulp.
class GaussianRng {
public:
    /// Stream number `seed`; any value.
    explicit GaussianRng(std::uint64_t seed);
    /// Next N(0, 1) sample (samples come in Box–Muller pairs: cos branch, then sin branch).
    double next();
    /// Next raw 64-bit SplitMix64 output.
    std::uint64_t nextBits();

private:
    std::uint64_t m_state;
    double m_spare = 0.0;
    bool m_hasSpare = false;
};

/// ξ = (ξr, ξi) of eq. 4 for wave index (n, m) of cascade c: a pure function of
/// (seed, c, n, m), so a mode keeps its noise whatever the resolution.
std::complex<double> modeNoise(std::uint64_t seed, int cascade, int n, int m);

// ---------------------------------------------------------------------------------------
// Spectra. A spectrum here returns Ph(K), the per-mode variance of eq. 4 in m²:
// E|h̃0(K)|² = Ph(K), and the mode with its Hermitian partner (eq. 2) is one wave of
// variance 2·Ph(K), so the sea's mean square height is E⟨h²⟩ = Σ_K 2·Ph(K).
//
// Phillips (eq. 5), with the mode cell Δk² = (2π/L)² folded into A so that A is
// dimensionless and the sea does not change with N, L or the cascade:
//   Ph(K) = A·Δk² · exp(−1/(k·L_w)²)/k⁴ · (K̂·ŵ)² · exp(−k²l²),   L_w = V²/g,   Ph(0) = 0.
//   Variance ≈ A·π·L_w² (l → 0, the patch covering the peak), so A = 0.00088 gives the
//   Pierson–Moskowitz Hs = 4·rms = 0.21·V²/g.
//
// JONSWAP (Hasselmann et al. 1973, fetch-limited; frequency form as in Tessendorf 2001 and
// Horvath 2015 "Empirical directional wave spectra"):
//   S(ω) = α g²/ω⁵ · exp(−5/4·(ωp/ω)⁴) · γ^r,   r = exp(−(ω−ωp)²/(2σ²ωp²)),
//   σ = 0.07 (ω ≤ ωp), 0.09 (ω > ωp),   α = 0.076·(V²/(F g))^0.22,   ωp = 22·(g²/(V F))^(1/3).
//   Wavenumber form (deep water ω = sqrt(g k), Jacobian dω/dk = g/(2ω)) with cos² spreading:
//   S(K) = S(ω(k)) · dω/dk · D(θ)/k  [m⁴],   ∫S(K) d²K = ∫S(ω) dω,
//   D(θ) = (2/π)·cos²θ for |θ| < π/2, else 0, θ the angle between the wave's direction of
//   travel and ŵ. With eq. 1–2 the h̃0(K) term travels toward −K, so θ is measured from −K̂.
//   Per mode: Ph(K) = S(K)·Δk²/2 · exp(−k²l²).

/// An OceanDef's spectrum keys resolved to SI values shared by every cascade.
struct SpectrumParams {
    SpectrumKind kind = SpectrumKind::Phillips; ///< closed form
    double amplitude = 0.0;    ///< A, dimensionless (Phillips)
    double windSpeed = 0.0;    ///< V, m/s
    double windX = 1.0;        ///< ŵ.x, unit vector the wind blows toward
    double windZ = 0.0;        ///< ŵ.z
    double gravity = environment::STANDARD_ENVIRONMENT.gravity;  ///< g, m/s² (OceanDef::gravity)
    double largestWave = 0.0;  ///< L_w = V²/g, metres
    double cutoff = 0.0;       ///< l, metres (auto already resolved to 0.001·L_w)
    double alpha = 0.0;        ///< JONSWAP α, dimensionless
    double omegaPeak = 0.0;    ///< JONSWAP ωp, rad/s
    double gamma = 3.3;        ///< JONSWAP γ
};

/// Resolves def's spectrum keys (normalises the wind direction, resolves l = 0 to auto).
SpectrumParams spectrumParams(const OceanDef& def);

/// Phillips Ph(K), m², for K = (kx, kz) rad/m and mode cell side dk = 2π/L rad/m.
double phillips(double kx, double kz, double dk, const SpectrumParams& p);

/// JONSWAP 1-D frequency spectrum S(ω), m²·s, ω in rad/s (0 for ω ≤ 0 or V = 0).
double jonswapFrequency(double omega, const SpectrumParams& p);

/// JONSWAP Ph(K), m², for K = (kx, kz) rad/m and mode cell side dk = 2π/L rad/m.
double jonswap(double kx, double kz, double dk, const SpectrumParams& p);

/// Ph(K) of p.kind, m².
double modeVariance(double kx, double kz, double dk, const SpectrumParams& p);

// ---------------------------------------------------------------------------------------
// Cascades: tile c has side L_c = L/φ^(2c) (φ² = 2.618…, irrational, so no two tiles ever
// repeat together) and keeps the modes with kMin_c ≤ k < kMax_c, bands that do not overlap:
// kMax_c = kMin_(c+1) = min(6·2π/L_(c+1), π·N/L_c) (the finer tile leaves its 6 longest,
// coarsely sampled wavelengths to the coarser one; the coarser tile stops at its Nyquist).

/// Side of cascade c's tile, metres.
double cascadePatchSize(const OceanDef& def, int cascade);

/// Throws ob::InputError listing every key of def no backend can run (resolution a power of
/// two in [4, maxResolution], cascades in [1, 4], positive sizes, a wind direction), each
/// line "ocean.key: problem". Backends call it: their callers may bypass the scene loader.
void validateOceanDef(const OceanDef& def, int maxResolution);

/// Band of wave numbers |K| a cascade keeps, rad/m, half open [kMin, kMax).
struct WaveBand {
    double kMin = 0.0;  ///< rad/m, inclusive
    double kMax = 0.0;  ///< rad/m, exclusive (infinity for the last cascade)
};

/// Band of cascade c of def.
WaveBand cascadeBand(const OceanDef& def, int cascade);

/// The mean square slope ⟨|∇h|²⟩ of cascade c's waves (the ensemble mean over the noise):
/// Σ k²·(Ph(K) + Ph(−K)) over the modes of its band, as ⟨h²⟩ = Σ (Ph(K) + Ph(−K)). The
/// renderer's sun glitter adds what the cascades do not resolve (Cox & Munk 1954).
double cascadeSlopeVariance(const OceanDef& def, int cascade);

/// The surface Stokes drift of the cascades' waves, m/s, (x, z): the mean forward drift of the
/// surface particles that a real wave train carries (the model's particles close their orbits,
/// so the foam map adds it, docs/splash_foam.md §2). Deep water, one wave of amplitude a, wave
/// number k and ω = sqrt(g·k) drifts ω·k·a² toward its travel; mode K is a wave of
/// a² = 4·Ph(K) travelling toward −K, so U_s = Σ_K 4·ω·k·Ph(K)·(−K̂) over every cascade's band.
/// A spectrum even in K (Phillips' (K̂·ŵ)², waves both ways) drifts 0.
std::array<double, 2> stokesDrift(const OceanDef& def);

/// The mean square slope of a wind sea, waves of every length: Cox & Munk (1954)'s fit to
/// their photographs of sun glitter, 0.003 + 5.12e-3·U10 (U10 in m/s, clean surface).
inline double coxMunkSlopeVariance(double windSpeed) { return 0.003 + 5.12e-3 * windSpeed; }

// ---------------------------------------------------------------------------------------
// The spectrum of one cascade. Layout: N×N, row-major, FFT order. Row r holds wave index
// m = r for r < N/2 and m = r − N above (kz = 2πm/L), column c likewise n (kx = 2πn/L), so
// an unnormalised backward DFT (FFTW_BACKWARD, exp(+i…)) is eq. 1 literally at
// X = (i·L/N, j·L/N), no shift. The Nyquist row and column (n or m = −N/2) hold no wave:
// their −K is off the grid, eq. 2 cannot pair them, and they would make D and ε complex.

/// Four N×N interleaved complex arrays (FFT order) the synthesis writes, each two real
/// fields packed as F + iG (eq. 9): an unnormalised backward 2-D DFT gives f + i·g.
struct PackedSpectra {
    float* heightDxz = nullptr; ///< h̃ + i·(∂Dx/∂z)~,   (∂Dx/∂z)~ = (kx·kz/k)·h̃
    float* dispXZ = nullptr;    ///< Dx~ + i·Dz~,        D~ = −i(K/k)·h̃ (eq. 7)
    float* slopeXZ = nullptr;   ///< εx~ + i·εz~,        ε~ = iK·h̃ (eq. 6)
    float* dxxDzz = nullptr;    ///< (∂Dx/∂x)~ + i·(∂Dz/∂z)~ = (kx²/k + i·kz²/k)·h̃
};

struct VelocityBands;

/// h̃0(K) and ω(k) of one cascade, and the per-frame synthesis of eq. 2, 6, 7.
class CascadeSpectrum {
public:
    /// A calm spectrum (h̃0 = 0): N per side (power of two ≥ 4), tile side L metres, g m/s².
    CascadeSpectrum(int resolution, double patchSize, double gravity);
    /// Cascade c of def: h̃0(K) = ξ·sqrt(Ph(K)/2) (eq. 4) inside the cascade's band.
    CascadeSpectrum(const OceanDef& def, int cascade);

    /// N, points per side.
    int resolution() const { return m_n; }
    /// L, tile side, metres.
    double patchSize() const { return m_patchSize; }
    /// g, m/s².
    double gravity() const { return m_gravity; }
    /// 2π·n/L, rad/m, for a signed wave index n.
    double waveNumber(int n) const;

    /// h̃0(K) at signed wave indices (n along x, m along z), each in [−N/2, N/2).
    std::complex<float> h0(int n, int m) const;
    /// Sets h̃0(K) by hand (tests, tools); n, m in [−N/2 + 1, N/2) (no Nyquist wave).
    void setH0(int n, int m, std::complex<float> value);
    /// Sets every h̃0 to 0.
    void clear();
    /// Sets h̃0 = (1 − s)·from.h̃0 + s·to.h̃0 (both of this N and L; s in [0, 1]) with the
    /// synthesis coefficients, linear in h̃0 and blended alike: a live change's cross-fade
    /// (ocean/sea_fade.h). s = 0 and s = 1 copy `from` and `to` bit for bit.
    void blend(const CascadeSpectrum& from, const CascadeSpectrum& to, float s);

    /// ω(k) = sqrt(g·k), rad/s (eq. 3), at signed wave indices.
    double omega(int n, int m) const;
    /// h̃(K,t) = h̃0(K)e^{iωt} + conj(h̃0(−K))e^{−iωt} (eq. 2) in double: a scalar reference.
    std::complex<double> hTilde(int n, int m, double t) const;

    /// Rows are synthesised in mirrored pairs {m, −m} (ω and 1/k depend on |K| only, so one
    /// sin/cos serves four modes): N/2 + 1 pairs, |m| = 0 … N/2 (0 and N/2 are single rows).
    int rowPairCount() const;
    /// Writes the four packed spectra at time t (seconds) for the row pairs |m| ∈
    /// [pairBegin, pairEnd); disjoint ranges may run on different threads.
    void synthesize(double t, int pairBegin, int pairEnd, const PackedSpectra& out) const;
    /// Writes the velocity bands' packed spectra (ocean/velocity_bands.h) at time t for the row
    /// pairs [pairBegin, pairEnd), N×N interleaved complex each: out[b] = Ŵ_b + i·Û_b for each
    /// band b with maps, then out[E + j] = V̂_2j + i·V̂_2j+1 (E = bands.mappedBands(), V̂_E = 0),
    /// with Ŵ_b = g_b(k)·∂h̃/∂t and (Û_b, V̂_b) = i(K/k)·Ŵ_b: the vertical velocity and the
    /// orbit's horizontal one, −∂D/∂t (eq. 7), of the band's modes, exact in t.
    void synthesizeVelocity(double t, int pairBegin, int pairEnd, const VelocityBands& bands, float* const* out) const;

private:
    size_t index(int n, int m) const;
    void refreshMode(size_t idx);

    int m_n;
    double m_patchSize;
    double m_gravity;
    std::vector<std::complex<float>> m_h0;  // h̃0, FFT order
    std::vector<double> m_omega;            // ω(k), rad/s, quarter grid [|m|][|n|], (N/2+1)² (double: ω·t exact for hours)
    std::vector<float> m_invK;              // 1/k, quarter grid like m_omega, 0 at K = 0
    std::vector<float> m_k;                 // 2π·s/L per FFT-order position: kx of a column, kz of a row
    // Re h̃ = cosRe·cos ωt + sinRe·sin ωt, Im h̃ = cosIm·cos ωt + sinIm·sin ωt, from
    // a + ib = h̃0(K), p + iq = conj(h̃0(−K)): cosRe = a+p, sinRe = q−b, cosIm = b+q, sinIm = a−p.
    std::vector<float> m_cosRe, m_sinRe, m_cosIm, m_sinIm;
};

} // namespace ob::ocean
