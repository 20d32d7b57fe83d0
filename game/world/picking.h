// Picking: the ray through a pixel of the view, where it first meets the water surface that
// is drawn (the composite of Gerstner, cascades and ripples, found by marching and bisection)
// and which body or fish school it meets first.
#pragma once
#include "ecs/world.h"
#include "view_data/scene_view.h"
#include "water/water_query.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

namespace ob::game {

/// A half line: origin (world m) and unit direction.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    glm::vec3 at(float t) const { return origin + t * direction; }
};

/// The ray from the eye through framebuffer pixel `pixel` (px, origin top left; the pixel's
/// centre at +0.5) of a view of `size` px.
Ray pixelRay(const gfx::CameraView& view, glm::ivec2 size, glm::vec2 pixel);

/// The largest slope |∇h| the water march assumes (a 45° face): a steeper face can let the
/// march step past a thin crest and hit the water behind it.
constexpr float PICK_MAX_SLOPE = 1.0f;
/// The march's least step per metre of distance from the eye: at grazing views the safe step
/// (|f| over the slope bound) shrinks without end; this keeps the march to a few hundred
/// samples, at the price of stepping over a crest thinner than it (0.4 m at 100 m, where a
/// pixel of a 720-pixel-high 60° view spans 0.15 m).
constexpr float PICK_STEP_PER_M = 0.004f;
/// The march stops once |ray height − water height| is below this (m).
constexpr float PICK_TOLERANCE_M = 0.002f;

/// Where the ray first crosses the water surface within `maxDistance` (m) of its origin,
/// from above or from below, or nothing. The surface is `water.sample()`: every layer.
std::optional<glm::vec3> pickWater(const water::WaterQuery& water, const Ray& ray, float maxDistance);

/// What the ray meets first that the player's tools act on.
struct BodyPick {
    ecs::Entity entity = ecs::Entity::None;  ///< a body (ship, ball, crate...) or a fish school
    glm::vec3 point{0.0f};                   ///< where the ray meets it (world m)
    float distance = 0.0f;                   ///< from the ray's origin (m)
};

/// The first body (a Bullet ray test) or fish (within its length of the ray) the ray meets
/// within `maxDistance` (m).
std::optional<BodyPick> pickBody(ecs::World& world, const Ray& ray, float maxDistance);

} // namespace ob::game
