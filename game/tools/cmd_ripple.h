// `oceanbox ripple`: a bare ripple solver on .npy fields (docs/references.md#contracts): [Kang2008] eq. 1–2 (kang2008)
// or the dispersive ewave field (docs/references.md#dispersive-ripples).
#pragma once
#include <string>

namespace ob::game {

/// Arguments of `oceanbox ripple [--model kang2008] --in H.npy [--prev P.npy] --steps K
/// --damping DF --out OUT.npy` and of `oceanbox ripple --model ewave --in H.npy [--vel V.npy]
/// --steps K --dt DT --cell-size D --damping TAU [--viscosity NU] --boundary B --out OUT.npy`.
struct RippleArgs {
    // (Field order kept: callers aggregate-initialise the first five.)
    std::string in;         ///< kang2008 Vh(t), ewave h: float32 .npy of shape [N, M], N, M >= 1 (ewave: >= 2)
    std::string prev;       ///< kang2008 Vh(t−1): same shape as in; empty = same as in
    std::string out;        ///< where Vh(t) / h after `steps` steps is written (.npy, float32)
    int steps = 1;          ///< K >= 0 steps
    float damping = 1.0f;   ///< kang2008: DF in [0, 1]; ewave: decay time τ, s, >= 0 (0 = none)
    std::string model = "kang2008";  ///< "kang2008" or "ewave"
    std::string vel;        ///< ewave v (m/s): same shape as in; empty = 0
    float viscosity = 0.0f; ///< ewave: effective viscosity ν, m²/s, >= 0
    float dt = 1.0f / 60.0f;    ///< ewave: step, s, > 0
    float cellSize = 0.25f;     ///< ewave: metres per cell, > 0
    std::string boundary;   ///< ewave: "periodic" (default), "fixed", "absorbing"; kang2008: "fixed" only
};

/// kang2008: runs eq. 1–2 with the fixed boundary (outer ring held at 0; the input's ring
/// values feed the first step) for args.steps steps and writes Vh(t). ewave: steps (h, v)
/// exactly per Fourier mode and writes h. Returns 0; throws ob::InputError (one line naming
/// the flag or file and what is wrong) for bad input, ob::RuntimeError if the output cannot
/// be written.
int rippleCommand(const RippleArgs& args);

} // namespace ob::game
