// A live change of the sea: the FFT spectrum, λ and the Gerstner waves cross-fade from the sea
// as it is to a new [ocean]/[gerstner] over about 2 s, keeping the spectrum's random phases
// (docs/references.md#spectral-ocean eq. 2 and 4: h̃0 = ξ·sqrt(Ph/2), the same ξ for any wind).
//
// Where the fade happens: in k-space, on h̃0. Eq. 2 is linear in h̃0 and ω(k) = sqrt(g·k) does
// not depend on the wind, so blending h̃0 is exactly blending the two seas' h̃(K,t), hence
// their maps (eq. 1, 6, 7 are linear too), with one FFT per cascade as before. Both h̃0 have
// the same ξ, so a mode keeps its phase and only its amplitude moves from sqrt(Ph_old/2) to
// sqrt(Ph_new/2): no energy dip midway, as blending two independent seas would have.
//
// The bound a test checks (fadeWeight's slope is at most 1.5/T): at every rest point, with s the
// weight of the new sea and h_old, h_new the two seas alone,
//   h(t+Δt) − h(t) = (1−s₁)·Δh_old + s₁·Δh_new + (s₁ − s₀)·(h_new − h_old)(t)    (exact)
//   |Δh| ≤ max(|Δh_old|, |Δh_new|) + 1.5·Δt/T·|h_new − h_old|.
// An instant switch has the jump |h_new − h_old| instead, T/(1.5·Δt) = 80 times the fade's
// term at 60 Hz and T = 2 s.
#pragma once
#include "ocean/gerstner.h"
#include "ocean/ocean_def.h"
#include "ocean/spectrum.h"

#include <algorithm>
#include <span>
#include <vector>

namespace ob::ocean {

class OceanFftCpu;

/// Seconds a live change of the sea takes: long against a step (no visible pop, bodies ride
/// it), short against a player waiting for the storm.
constexpr double SEA_FADE_SECONDS = 2.0;

/// Weight of the new sea `elapsed` seconds into a fade of `duration` seconds: smoothstep of
/// elapsed/duration, 0 before, 1 after (duration ≤ 0: an instant switch). Its slope is at
/// most 1.5/duration and 0 at both ends, so the surface's speed has no kink either.
double fadeWeight(double elapsed, double duration);

/// The cross-fade of one live change. Not copyable (holds two spectra per cascade).
class SeaFade {
public:
    /// From what `fft` and `waves` hold now (the last maps computed: mid-fade, the blend) to the
    /// sea of `ocean` and `gerstner` (same resolution, patch size, cascades and gravity as fft's),
    /// starting at `start` s over `duration` s. Builds the new h̃0 from ocean.seed's ξ (eq. 4).
    SeaFade(const OceanFftCpu& fft, std::span<const GerstnerWave> waves, const OceanDef& ocean,
            const GerstnerDef& gerstner, double start, double duration = SEA_FADE_SECONDS);
    /// As above with the new sea's Gerstner waves given (resolveWaves(gerstner, ocean), when the
    /// caller has them already).
    SeaFade(const OceanFftCpu& fft, std::span<const GerstnerWave> waves, const OceanDef& ocean,
            std::vector<GerstnerWave> newWaves, double start, double duration = SEA_FADE_SECONDS);

    /// Weight of the new sea at time t, s.
    double weight(double t) const { return fadeWeight(t - m_start, m_duration); }
    /// Whether the fade is over at time t (weight 1).
    bool done(double t) const { return weight(t) >= 1.0; }
    /// Writes the blended h̃0 of every cascade and λ into fft at time t (before fft.update(t)).
    /// From the end on, fft holds the new sea's h̃0 bit for bit.
    void apply(OceanFftCpu& fft, double t) const;
    /// The Gerstner waves at time t: the old set with amplitudes ×(1 − s), then the new set's
    /// waves ×s (a wave in both, same K and φ, once with the blended amplitude). A Gerstner
    /// height is linear in the amplitudes, so the layer blends like the FFT's.
    std::vector<GerstnerWave> waves(double t) const;
    /// The new sea's h̃0 of cascade c (CascadeSpectrum(ocean, c)).
    const CascadeSpectrum& target(int cascade) const { return m_to[size_t(cascade)]; }
    /// Start time, s.
    double start() const { return m_start; }
    /// End time, s (weight 1 from then on).
    double end() const { return m_start + std::max(m_duration, 0.0); }

private:
    std::vector<CascadeSpectrum> m_from, m_to;
    float m_lambdaFrom = 0.0f, m_lambdaTo = 0.0f;
    std::vector<GerstnerWave> m_wavesFrom, m_wavesTo;
    double m_start = 0.0;
    double m_duration = SEA_FADE_SECONDS;
};

} // namespace ob::ocean
