// How far the water's layers can move a point of the mean plane: what the projected grid must
// reach past the view so that displaced waves never open a gap.
#pragma once

namespace ob::ocean {

/// Bounds on a layer's displacement of any rest point (each ≥ 0, metres). Layers add, and so
/// do their bounds.
struct DisplacementBounds {
    float up = 0.0f;          ///< largest rise above y = 0
    float down = 0.0f;        ///< largest fall below y = 0
    float horizontal = 0.0f;  ///< largest horizontal move, |(x − α, z − β)|

    DisplacementBounds& operator+=(const DisplacementBounds& o) {
        up += o.up, down += o.down, horizontal += o.horizontal;
        return *this;
    }
};

} // namespace ob::ocean
