// A ripple field stepped outside a scene (the `ripple` tool): its arrays in, the model's step
// run, its height out. Each model's registration (ripple_solvers.h) runs it as `stepArrays`.
#pragma once
#include "interaction/ripple_def.h"

#include <vector>

namespace ob::interaction {

/// rows × cols cells, row-major (z·cols + x), any size the model takes.
struct RippleArrays {
    int rows = 0, cols = 0;
    std::vector<float> height;  ///< kang2008 Vh(t), ewave h, m; the height after the steps on return
    std::vector<float> second;  ///< the model's other level: kang2008 Vh(t−1) (empty: = height), ewave v (m/s; empty: 0)
    float cellSize = 1.0f;      ///< m (ewave)
    float dt = 1.0f / 60.0f;    ///< s a step (ewave; kang2008 steps per frame)
    RippleBoundary boundary = RippleBoundary::Fixed;
    float damping = 0.0f;       ///< kang2008 DF; ewave's decay time, s (0 = none)
    float viscosity = 0.0f;     ///< ewave's extra viscosity, m²/s
    int steps = 0;
};

/// Runs `arrays.steps` steps of the model named `model` (a RippleModels NAME, checked by the
/// caller) on `arrays`, the height after them left in arrays.height.
void stepRippleArrays(std::string_view model, RippleArrays& arrays);

} // namespace ob::interaction
