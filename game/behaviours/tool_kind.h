// The player's tools by name: what the left button does (world/tools.h acts them out; a goal
// scene's [game] tools lists those it allows).
#pragma once
#include "core/schema.h"

#include <cstdint>

namespace ob::game {

/// What the left button does.
enum class Tool : uint8_t {
    Grab,    ///< 1: drag a body on a spring to the cursor; release throws it
    Stir,    ///< 2: a sphere source follows the cursor's point on the water
    Drop,    ///< 3: a click drops the palette's object 3 m above the water point (3 again: the next object)
    Erase,   ///< 4: a click removes the body (ship, school as a whole) under the cursor
    Cannon,  ///< 5: a click aims the player's cannon at the water point and fires
};
constexpr std::array<const char*, 5> names(Tool) { return {"grab", "stir", "drop", "erase", "cannon"}; }

} // namespace ob::game
