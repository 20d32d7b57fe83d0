// `oceanbox ripple`: the bare ripple solver on .npy fields (SPEC §4; seed 001 eq. 1–2).
#pragma once
#include <string>

namespace ob::game {

/// Arguments of `oceanbox ripple --in H.npy [--prev P.npy] --steps K --damping DF --out OUT.npy`.
struct RippleArgs {
    std::string in;         ///< Vh(t): float32 .npy of shape [N, M], N, M >= 1
    std::string prev;       ///< Vh(t−1): same shape as in; empty = same as in
    std::string out;        ///< where Vh(t) after `steps` steps is written (.npy, float32)
    int steps = 1;          ///< K >= 0 steps of eq. 1–2
    float damping = 1.0f;   ///< DF in [0, 1]
};

/// Runs eq. 1–2 with the fixed boundary (outer ring held at 0; the input's ring values feed
/// the first step) for args.steps steps and writes Vh(t). Returns 0; throws ob::InputError
/// (one line naming the flag or file and what is wrong) for bad input, ob::RuntimeError if
/// the output cannot be written.
int rippleCommand(const RippleArgs& args);

} // namespace ob::game
