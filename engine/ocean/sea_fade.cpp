// The cross-fade of a live change of the sea (formulas and the bound: sea_fade.h).
#include "ocean/sea_fade.h"

#include "ocean/ocean_fft_cpu.h"

#include <algorithm>
#include <cassert>

namespace ob::ocean {

double fadeWeight(double elapsed, double duration) {
    if (duration <= 0.0) return elapsed >= 0.0 ? 1.0 : 0.0;
    const double u = std::clamp(elapsed / duration, 0.0, 1.0);
    return u * u * (3.0 - 2.0 * u);
}

SeaFade::SeaFade(const OceanFftCpu& fft, std::span<const GerstnerWave> waves, const OceanDef& ocean,
                 const GerstnerDef& gerstner, double start, double duration)
    : SeaFade(fft, waves, ocean, resolveWaves(gerstner, ocean), start, duration) {}

SeaFade::SeaFade(const OceanFftCpu& fft, std::span<const GerstnerWave> waves, const OceanDef& ocean,
                 std::vector<GerstnerWave> newWaves, double start, double duration)
    : m_lambdaFrom(fft.lambda()), m_lambdaTo(-ocean.choppiness), m_wavesFrom(waves.begin(), waves.end()),
      m_wavesTo(std::move(newWaves)), m_start(start), m_duration(duration) {
    assert(ocean.resolution == fft.resolution() && ocean.cascades == fft.cascadeCount());
    for (int c = 0; c < fft.cascadeCount(); ++c) {
        m_from.push_back(fft.spectrum(c));
        m_to.emplace_back(ocean, c);
    }
}

void SeaFade::apply(OceanFftCpu& fft, double t) const {
    const double s = weight(t);
    for (int c = 0; c < fft.cascadeCount(); ++c) fft.spectrum(c).blend(m_from[size_t(c)], m_to[size_t(c)], float(s));
    fft.setLambda(s >= 1.0 ? m_lambdaTo : float((1.0 - s) * m_lambdaFrom + s * m_lambdaTo));
}

std::vector<GerstnerWave> SeaFade::waves(double t) const {
    const double s = weight(t);
    if (s >= 1.0) return m_wavesTo;
    const auto same = [](const GerstnerWave& a, const GerstnerWave& b) { return a.kx == b.kx && a.kz == b.kz && a.phase == b.phase; };
    std::vector<GerstnerWave> out;
    std::vector<bool> used(m_wavesTo.size(), false);
    for (const GerstnerWave& w : m_wavesFrom) {
        GerstnerWave blended = w;
        blended.amplitude = float((1.0 - s) * w.amplitude);
        for (size_t j = 0; j < m_wavesTo.size(); ++j)
            if (!used[j] && same(w, m_wavesTo[j])) {
                blended.amplitude += float(s * m_wavesTo[j].amplitude);
                used[j] = true;
                break;
            }
        if (blended.amplitude > 0.0f) out.push_back(blended);
    }
    for (size_t j = 0; j < m_wavesTo.size(); ++j)
        if (!used[j] && s > 0.0) {
            GerstnerWave w = m_wavesTo[j];
            w.amplitude = float(s * w.amplitude);
            out.push_back(w);
        }
    return out;
}

} // namespace ob::ocean
