// T rights a capsized ship: every ship heeled past CAPSIZE_DEG is put back upright on its
// heading, at rest in rotation, where it floats (a hull that cannot right itself stays
// usable; one that can does so on its own in the physics).
#pragma once
#include "ecs/schedule.h"

#include <glm/gtc/quaternion.hpp>

namespace ob::game {

/// A ship whose deck leans more than this from level is capsized (deg).
constexpr float CAPSIZE_DEG = 60.0f;

/// Whether a body turned `rotation` is capsized (its up axis more than CAPSIZE_DEG from the vertical).
bool capsized(const glm::quat& rotation);
/// The rotation upright on the same heading (the bow's direction on the water kept).
glm::quat uprightOnHeading(const glm::quat& rotation);
/// Script phase, after the steps' input: T rights every capsized ship.
void rightingSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
