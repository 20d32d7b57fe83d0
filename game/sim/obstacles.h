// The bodies that obstruct the ripple layer (Obstacle: fixed bodies, hulls) as footprints on
// the mean water plane, handed to the ripple patch each step (interaction/obstruction.h).
#pragma once
#include "ecs/schedule.h"
#include "interaction/obstruction.h"
#include "sim/objects.h"

#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <vector>

namespace ob::game {

/// Where a body of `obstacle` at `position`, `rotation` cuts the plane y = 0 (world m), or
/// nothing when it does not reach it. Box and hull footprints take the body's turn about +y
/// only (their local x axis projected on the plane; a body tipped far over keeps its upright
/// footprint, a fair account of a wall, a pillar or a floating hull).
std::optional<interaction::ObstacleShape> waterlineFootprint(const Obstacle& obstacle, const glm::vec3& position,
                                                             const glm::quat& rotation);

/// Every Obstacle entity's waterline footprint, in entity order.
std::vector<interaction::ObstacleShape> obstacleFootprints(ecs::World& world);

} // namespace ob::game
