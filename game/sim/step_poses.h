// Render interpolation's memory: every transform as the latest fixed step found it. With the
// state the step left, it bounds what a frame between two steps draws (render.interpolate).
#pragma once
#include "ecs/components.h"
#include "ecs/world.h"

namespace ob::game {

/// The poses at the start of the latest fixed step (a resource; world/interpolation.h keeps it).
struct StepPoses {
    ecs::Pool<ecs::Transform> before;  ///< every transform before the latest step moved it
    float alpha = 1.0f;                ///< the weight the latest frame draws with, [0, 1] (1: the latest step)
};

/// Where entity `e`, now at `current`, is drawn: `alpha` of the way from its pose before the
/// latest step to `current` (position lerped, orientation slerped the short way). `current`
/// itself at alpha 1, without poses, or for an entity the latest step made.
ecs::Transform drawnTransform(const StepPoses* poses, ecs::Entity e, const ecs::Transform& current, float alpha);

} // namespace ob::game
