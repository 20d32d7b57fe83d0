// The bodies that obstruct the ripple layer (Obstacle: fixed bodies, hulls) as footprints on
// the mean water plane, handed to the ripple patch each step (interaction/obstruction.h).
#pragma once
#include "ecs/schedule.h"
#include "interaction/obstruction.h"
#include "sim/objects.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace ob::water {
class WaterQuery;
}

namespace ob::game {

/// Where a body of `obstacle` at `position`, `rotation` cuts the plane y = 0 (world m), or
/// nothing when it does not reach it. A box's footprint takes the body's turn about +y only (its
/// local x axis projected on the plane; a box tipped far over keeps its upright footprint, a
/// fair account of a wall or a pillar); a hull's is hullWaterplane at y = 0, with its hollow.
std::optional<interaction::ObstacleShape> waterlineFootprint(const Obstacle& obstacle, const glm::vec3& position,
                                                             const glm::quat& rotation);

/// A floating hull box of half extents `half` (beam x, depth y, length z) at `position`,
/// `rotation`, where it cuts the water plane y = waterY: the ellipse inscribed in that cut,
/// displacing (interaction::ObstacleShape::displaces). Its semi-axes are half the cut's span
/// across the hull (the section through its middle, so roll narrows or widens it: a box rolled
/// by φ with the plane on its sides spans beam/cos φ) and along it (pitch likewise), its centre
/// the middle of the two spans; nothing where the hull clears the plane or lies on its end.
std::optional<interaction::ObstacleShape> hullWaterplane(const glm::vec3& half, const glm::vec3& position,
                                                         const glm::quat& rotation, float waterY);

/// Every Obstacle entity's waterline footprint, in entity order. Fixed bodies cut the mean
/// plane y = 0; hulls cut the sea under their centre (`water` without its ripples: a ship on a
/// swell's crest still sits in the water; null: y = 0) and hold the ripples at their hollow
/// (Obstacle::hollow).
std::vector<interaction::ObstacleShape> obstacleFootprints(ecs::World& world, const water::WaterQuery* water);

/// The hulls' clip outlines taken from their models (a resource of the world, made on first
/// use): one a model file and box.
struct HullOutlines {
    std::map<std::tuple<std::string, float, float, float>, std::shared_ptr<const assets::HullOutline>> byModel;
};

/// Every hull's clip volume for the renderer (gfx::HullClip: no water drawn inside it): its
/// box from the Obstacle, the outline of the model it is drawn with (assets::hullOutline, made
/// once a model and box), else the box.
std::vector<gfx::HullClip> hullClips(ecs::World& world);

} // namespace ob::game
