// The kang2008 ripple solver's settings and its registration ([Kang2008] eq. 1–2, docs/references.md#ripple-layer):
// its keys sit flat in [ripples]; the solver itself is in kang2008_solver.h.
#pragma once
#include "core/schema.h"
#include "interaction/ripple_knob.h"

#include <memory>
#include <string>
#include <vector>

namespace ob::interaction {

struct RippleDef;
class RippleSolver;
struct RippleDefError;
struct RippleArrays;

/// kang2008's own keys of [ripples].
struct Kang2008Def {
    float damping = 0.95f;  ///< DF of eq. 2, [0, 1]: 0 kills a wave next step, 1 never damps
};

template <class V> void describe(V& v, Kang2008Def& d) {
    v.field("damping", d.damping, range(0, 1), "kang2008: damping factor DF (eq. 2)", LIVE);
}

/// The registration of kang2008 (interaction/ripple_solvers.h lists it).
struct Kang2008Model {
    static constexpr const char* NAME = "kang2008";  ///< ripples.model's word
    using Def = Kang2008Def;
    /// The live panel's knob.
    static constexpr RippleKnob<Def> KNOB{"ripples.damping", &Def::damping, "ripple damping", 0.8f, 1.0f, "%.3f",
                                          "damping factor DF per step (1 = none)"};
    /// The checks of a [ripples] table across keys that this model adds (its keys are in range).
    static std::vector<RippleDefError> validate(const RippleDef& def);
    /// The CPU solver of a checked Def (kang2008_solver.cpp).
    static std::unique_ptr<RippleSolver> make(const RippleDef& def);
    /// Moves a solver `make` made onto its GPU twin (kang2008/gpu/, the GL library only: needs
    /// a current GL 4.3+ context). False leaves it on the CPU.
    static bool moveToGpu(RippleSolver& solver);
    /// The `ripple` tool's run of this model on plain arrays (interaction/ripple_arrays.h).
    static void stepArrays(RippleArrays& arrays);
};

} // namespace ob::interaction
