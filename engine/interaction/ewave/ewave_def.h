// The ewave ripple solver's settings and its registration (dispersive waves, docs/references.md#dispersive-ripples): its
// keys sit flat in [ripples]; the solver itself is in ewave_solver.h.
#pragma once
#include "core/schema.h"
#include "interaction/ripple_knob.h"

#include <memory>
#include <vector>

namespace ob::interaction {

struct RippleDef;
class RippleSolver;
struct RippleDefError;
struct RippleArrays;

/// ewave's own keys of [ripples]. The water's own damping, its kinematic viscosity, comes from
/// [environment] water_viscosity (EWaveMedium::of); these are gameplay extras, off by default, so
/// a wake lasts as long as real water lets it and rings leave by spreading and through the border.
struct EWaveDef {
    float decay_time = 0.0f;  ///< e-folding time of every wave's amplitude, s, [0, 1e6]; 0 = none (gameplay)
    float viscosity = 0.0f;   ///< extra viscosity on top of the water's, m²/s, [0, 10]: a wave of wavenumber k
                              ///< also decays as exp(−2νk²t) (short waves first); 0 = only the water's
    float depth = 0.0f;       ///< uniform water depth d, m, [0, 1e4]; 0 = deep (no bottom): ω² = (g·k + (σ/ρ)·k³)·tanh(k·d)
};

template <class V> void describe(V& v, EWaveDef& d) {
    v.field("decay_time", d.decay_time, range(0, 1e6), "ewave: e-folding time of a wave's amplitude (s; 0 = none)", LIVE);
    v.field("viscosity", d.viscosity, range(0, 10),
            "ewave: extra viscosity on top of environment.water_viscosity, damps short waves (m2/s; 0 = none)", LIVE);
    v.field("depth", d.depth, range(0, 1e4), "ewave: uniform water depth (m; 0 = deep water, no bottom)");
}

/// The registration of ewave (interaction/ripple_solvers.h lists it).
struct EWaveModel {
    static constexpr const char* NAME = "ewave";  ///< ripples.model's word
    using Def = EWaveDef;
    /// The live panel's knob.
    static constexpr RippleKnob<Def> KNOB{"ripples.decay_time", &Def::decay_time, "ripple decay s", 0.0f, 60.0f, "%.1f",
                                          "extra e-folding time of the ripples' amplitude (0 = none: the water's own "
                                          "viscosity only; rings leave by spreading and through the border)"};
    /// Checks across keys this model adds (none: every key is checked by its range).
    static std::vector<RippleDefError> validate(const RippleDef& def);
    /// The CPU solver (EWaveField, FFTW) of a checked Def (ewave_solver.cpp).
    static std::unique_ptr<RippleSolver> make(const RippleDef& def);
    /// Moves a solver `make` made onto EWaveGpu (ewave/gpu/, the GL library only); false, with
    /// a warning, above EWaveGpu::MAX_RESOLUTION.
    static bool moveToGpu(RippleSolver& solver);
    /// The `ripple` tool's run of this model on plain arrays (interaction/ripple_arrays.h).
    static void stepArrays(RippleArrays& arrays);
};

} // namespace ob::interaction
