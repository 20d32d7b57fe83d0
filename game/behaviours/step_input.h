// The player's input as the behaviours see it, step by step (filled by world/controls).
#pragma once
#include "platform/input.h"

namespace ob::game {

/// What the fixed steps see of the input (a resource): events drained up to each step's
/// clock time, so a press is seen by exactly one step whatever the frame rate.
struct StepInput : platform::InputState {
    bool keysMoveCamera = false;  ///< the camera flies: W/S/A/D/Q/E are the camera's, not the ship's
};

} // namespace ob::game
