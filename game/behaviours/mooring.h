// What a floating body does on its own besides floating: held where it was moored (a target,
// a gate buoy), or flooding once holed until it is gone under (a target hit). Each is a
// component on the body and a system of the fixed step; whoever sets the body up adds it.
#pragma once
#include "ecs/schedule.h"

#include <glm/vec3.hpp>

namespace ob::game {

/// A body held near where it was moored: a critically damped horizontal spring of `period`.
struct Moored {
    glm::vec3 anchor{0.0f};  ///< where it was moored, world m (its y is not held)
    float period = 3.0f;     ///< s, > 0
};

/// A holed body taking water: a weight that grows from 0 to the water's weight of its whole
/// volume (ρ_w·V·g) over `fill_s`, so it sinks whatever its density; gone `gone_depth` under
/// the mean level.
struct Flooding {
    float fill_s = 1.5f;       ///< s to fill
    float gone_depth = 8.0f;   ///< m under y = 0 where it leaves the world
    float filled = 0.0f;       ///< of its volume flooded so far, [0, 1]
};

/// Moors `body` where it is now (nothing when it is not a body, or `period` <= 0: it drifts free).
void moor(ecs::World& world, ecs::Entity body, float period);
/// Holes `body`: it floods and sinks (once; a second call does nothing).
void hole(ecs::World& world, ecs::Entity body);

/// Script phase: the moored bodies' springs, for the next physics step, taken implicitly
/// (backward Euler of x'' = −ω²x − 2ωx' over dt): stable at any period, so the stiffest legal
/// mooring (1 ms) holds its body rather than throwing it.
void mooringSystem(ecs::World& world, const ecs::Tick& tick);
/// Script phase: the flooding bodies' weight of water, for the next physics step; a body
/// under its gone_depth leaves the world.
void floodingSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
