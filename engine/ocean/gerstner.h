// Gerstner waves (trochoids): docs/references.md#gerstner-waves, [Lee2007] eq. 8 and §2.3, [Min2023] §2; waves drawn
// from the ocean's spectrum for the band the FFT leaves out, after Thon et al. 2000 ([Lee2007] §1).
#pragma once
#include "core/schema.h"
#include "ocean/ocean_def.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob::ocean {

/// One trochoid ([Min2023]'s form): θ = kx·α + kz·β − ω·t − φ, ω = sqrt(g·k). The wave travels
/// toward +K; every particle circles its rest point with radius `amplitude`.
struct GerstnerWave {
    float kx = 0.1f;        ///< wave vector x, rad/m, [−1000, 1000]; K = (kx, kz) must not be 0
    float kz = 0.0f;        ///< wave vector z, rad/m, [−1000, 1000]; wavelength 2π/|K|
    float amplitude = 0.5f; ///< a, metres, [0, 10000]; k·a < 1 (else the surface self-intersects)
    float phase = 0.0f;     ///< φ, radians, any
};

template <class V> void describe(V& v, GerstnerWave& d) {
    v.field("kx", d.kx, range(-1000, 1000), "wave vector x, rad/m (wavelength 2π/|K|)");
    v.field("kz", d.kz, range(-1000, 1000), "wave vector z, rad/m");
    v.field("amplitude", d.amplitude, range(0, 10000), "radius of the particle orbits, metres (k·a < 1)");
    v.field("phase", d.phase, any(), "phase φ, radians");
}

/// The Gerstner layer, section [gerstner]: explicit waves, plus `count` waves drawn from the
/// [ocean] spectrum in the long-wave band the FFT cannot hold (both lists are used: explicit
/// first). Generation scheme (generateWaves):
///  - band: wavelengths [min_wavelength, max_wavelength]. Auto min = √π·ocean.patch_size: the
///    FFT's modes sample the spectrum on cells of side Δk = 2π/L, and the cell around K = 0 is
///    the one it leaves empty (Ph(0) = 0); the disc k < 2√π/L has that cell's area. Auto max:
///    the longest wavelength with at most 0.5% of the band's variance beyond it.
///  - `count` bins of equal width in log k; bin m holds variance E_m = ∫∫ F(K) d²K of the
///    spectrum F(K) = 2·Ph(K)/Δk² (spectrum.h), so the wave's amplitude is a_m = sqrt(2·E_m)
///    (a sinusoid of amplitude a has variance a²/2) times amplitude_scale.
///  - k_m: a seeded uniform point of the bin in log k; direction: drawn (seeded, inverse CDF)
///    from the bin's angular distribution, always downwind (a Gerstner wave travels toward
///    +K; Phillips' (K̂·ŵ)² is symmetric, so its upwind half is folded onto the downwind half,
///    variance kept); phase: seeded uniform in [0, 2π).
struct GerstnerDef {
    std::vector<GerstnerWave> waves;  ///< explicit trochoids ([[gerstner.waves]]); default none
    int count = 0;                    ///< spectrum-derived waves added after `waves`, [0, 64]; 0 = none
    std::uint64_t seed = 1;           ///< seed of the generated waves' wave numbers, directions and phases
    float min_wavelength = 0.0f;      ///< shortest generated wave, metres, [0, 1e6]; 0 = auto √π·ocean.patch_size (below it the FFT already holds the energy: a lower value counts it twice)
    float max_wavelength = 0.0f;      ///< longest generated wave, metres, [0, 1e7]; 0 = auto (≤ 0.5% of the band's variance beyond)
    float amplitude_scale = 1.0f;     ///< factor on generated amplitudes, [0, 100]; 1 = the spectrum's own
    float steepness_warning = 1.0f;   ///< Σ k·a over all waves at or above which loading warns, [0, 100]; 1 = aligned crests can fold
};

template <class V> void describe(V& v, GerstnerDef& d) {
    v.list("waves", d.waves, "explicit trochoids (kx, kz rad/m; amplitude m; phase rad)");
    v.field("count", d.count, range(0, 64), "waves drawn from the [ocean] spectrum for wavelengths longer than the FFT tile; 0 = none", LIVE);
    v.field("seed", d.seed, "seed of the generated waves");
    v.field("min_wavelength", d.min_wavelength, range(0, 1e6), "shortest generated wave, metres; 0 = √π·ocean.patch_size");
    v.field("max_wavelength", d.max_wavelength, range(0, 1e7), "longest generated wave, metres; 0 = auto (99.5% of the band's variance)");
    v.field("amplitude_scale", d.amplitude_scale, range(0, 100), "factor on generated amplitudes", LIVE);
    v.field("steepness_warning", d.steepness_warning, range(0, 100), "Σ k·a at or above which loading warns");
}

// ---------------------------------------------------------------------------------------
// Validation and generation.

/// Problems of def, one line each naming the key path ("gerstner.waves[3]: k·a = 1.2 ≥ 1: the
/// surface would self-intersect"); empty = accepted. With `ocean`, the generated waves are
/// drawn and checked too. Σ k·a ≥ steepness_warning is accepted but logged (logWarn) and, if
/// `warnings` is given, appended to it.
std::vector<std::string> validate(const GerstnerDef& def, const OceanDef* ocean = nullptr,
                                  std::vector<std::string>* warnings = nullptr);

/// Band of the generated waves, rad/m: kMin ≤ k ≤ kMax.
struct GerstnerBand {
    double kMin = 0.0; ///< 2π / longest wavelength
    double kMax = 0.0; ///< 2π / shortest wavelength
};

/// The band def.min/max_wavelength resolve to for ocean (autos resolved as GerstnerDef says).
GerstnerBand generationBand(const GerstnerDef& def, const OceanDef& ocean);

/// def.count waves drawn from ocean's spectrum (scheme: GerstnerDef); same inputs, same waves.
std::vector<GerstnerWave> generateWaves(const GerstnerDef& def, const OceanDef& ocean);

/// def.waves followed by generateWaves(def, ocean).
std::vector<GerstnerWave> resolveWaves(const GerstnerDef& def, const OceanDef& ocean);

/// Σ k·a over waves (< 1 keeps every superposition free of loops).
double steepnessSum(std::span<const GerstnerWave> waves);

// ---------------------------------------------------------------------------------------
// Evaluation (docs/references.md#gerstner-waves). With C = cos θ, S = sin θ, per wave a, k, ω, K̂ = K/k:
//   x = α − Σ K̂x·a·S,   z = β − Σ K̂z·a·S,   y = Σ a·C
//   ∂r/∂α = (1 − Σ kx²/k·a·C, −Σ kx·a·S, −Σ kx·kz/k·a·C)   in (x, y, z)
//   ∂r/∂β = (−Σ kx·kz/k·a·C, −Σ kz·a·S, 1 − Σ kz²/k·a·C)
//   n = ∂r/∂β × ∂r/∂α (y up; [Min2023]'s α × β in its (x, z, y) order), n.y = det ∂(x,z)/∂(α,β).
//   ∂y/∂t = Σ a·ω·S,   ∂(x, z)/∂t = Σ K̂·a·ω·C   (at the fixed rest point: particle velocity)

/// The raw sums at one rest point, from which position, normal, Jacobian and velocity follow.
struct GerstnerSums {
    float dx = 0, dz = 0;              ///< horizontal displacement x − α, z − β, metres
    float y = 0;                       ///< height, metres
    float pxx = 0, pxz = 0, pzz = 0;   ///< Σ kx²/k·a·C, Σ kx·kz/k·a·C, Σ kz²/k·a·C (dimensionless)
    float qx = 0, qz = 0;              ///< Σ kx·a·S, Σ kz·a·S = −∂y/∂α, −∂y/∂β (dimensionless)
    float vy = 0;                      ///< ∂y/∂t at the rest point, m/s
    float vx = 0, vz = 0;              ///< ∂x/∂t, ∂z/∂t at the rest point, m/s

    /// Unnormalised normal ∂r/∂β × ∂r/∂α (x, y, z).
    glm::vec3 normalRaw() const;
    /// Unit normal, y up.
    glm::vec3 normal() const;
    /// Surface slope (∂y/∂x, ∂y/∂z) in world coordinates: −n.xz / n.y of the analytic normal.
    glm::vec2 slope() const;
};

/// A rest point (α, β) at time t.
struct GerstnerPoint {
    glm::vec3 position{0.0f};     ///< (x, y, z), metres
    glm::vec3 normal{0, 1, 0};    ///< unit normal, y up
    float verticalVelocity = 0;   ///< ∂y/∂t of the particle, m/s
    glm::vec2 displacement{0.0f}; ///< (x − α, z − β), metres
};

/// Waves in structure-of-arrays form (padded to whole SIMD blocks with zero-amplitude waves)
/// and their phases at one time; evaluates one point or many (vectorised over points).
class GerstnerField {
public:
    /// No waves: a flat, still plane.
    GerstnerField() = default;
    /// waves under gravity g (m/s², > 0), time 0. Waves with K = 0 are skipped.
    GerstnerField(std::span<const GerstnerWave> waves, float gravity);

    /// Sets the time, seconds: each wave's ω·t + φ is reduced mod 2π in double, so any t works.
    void setTime(double t);
    /// Time of the last setTime(), seconds.
    double time() const { return m_time; }
    /// Number of (non-padding) waves.
    int waveCount() const { return m_count; }
    /// ω of wave m, rad/s.
    float omega(int m) const { return m_omega[size_t(m)]; }

    /// Sums at rest point (α, β), metres (vectorised over the waves).
    GerstnerSums sums(float alpha, float beta) const;
    /// Sums at `count` rest points (vectorised over the points).
    void sums(const float* alpha, const float* beta, size_t count, GerstnerSums* out) const;

    /// The particle velocity (x, y, z), m/s, of the particle of rest point (α, β) whose orbit
    /// centre lies `depth` m below the mean surface (depth ≤ 0 reads the surface): Gerstner's
    /// exact solution, each wave's orbit scaled by e^{−k·depth}:
    ///   Σ e^{−k·depth}·(K̂·a·ω·C, a·ω·S).
    glm::vec3 velocity(float alpha, float beta, float depth) const;
    /// Position, unit normal, particle velocity and displacement of rest point (α, β).
    GerstnerPoint evaluate(float alpha, float beta) const;
    /// evaluate() at `count` rest points.
    void evaluate(const float* alpha, const float* beta, size_t count, GerstnerPoint* out) const;

private:
    int m_count = 0;
    int m_padded = 0;
    double m_time = 0.0;
    // Per wave (SoA, m_padded long): θ = kx·α + kz·β − psi; the rest are products of a, k, K̂, ω.
    std::vector<float> m_kx, m_kz, m_psi, m_omega, m_k;
    std::vector<float> m_ax, m_az, m_a;          // K̂x·a, K̂z·a, a
    std::vector<float> m_pxx, m_pxz, m_pzz;      // kx²/k·a, kx·kz/k·a, kz²/k·a
    std::vector<float> m_qx, m_qz;               // kx·a, kz·a
    std::vector<float> m_wa, m_wax, m_waz;       // ω·a, ω·K̂x·a, ω·K̂z·a
    std::vector<double> m_omegaD, m_phaseD;      // ω, φ in double for the phase reduction
};

} // namespace ob::ocean
