// The geometry the goals decide with: a ball's path against a target (swept sphere against a
// sphere or an oriented box) and a ship's path across a gate (segment against segment, with
// the side it crossed from). Pure functions of positions: no world, no physics engine.
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob::game {

/// Whether a sphere of radius `r` moving from `from` to `to` (one step) comes within `r` of a
/// sphere of radius `radius` at `centre`: the closest point of the segment to the centre.
bool sweptSphereTouchesSphere(glm::vec3 from, glm::vec3 to, float r, glm::vec3 centre, float radius);

/// Whether a sphere of radius `r` moving from `from` to `to` touches a box of half extents
/// `half` at `centre` turned by `rotation`: the segment, in the box's frame, against the box
/// grown by r on every face (slab test; at edges and corners it reaches up to r·(√3 − 1) past
/// the rounded shape, under 2 cm for a cannonball).
bool sweptSphereTouchesBox(glm::vec3 from, glm::vec3 to, float r, glm::vec3 centre, glm::quat rotation, glm::vec3 half);

/// How a path from `from` to `to` (x, z) crosses the gate between the buoys at `port` and
/// `starboard` (x, z): +1 the right way (port on its left hand, starboard on its right), −1
/// the wrong way, 0 not at all. Heading f has starboard f × ŷ = (−f.z, f.x) in (x, z), so the
/// right way is along n = ((s − p).z, −(s − p).x). A path ending exactly on the line crosses; one
/// starting on it does not, so a crossing counts once.
int gateCrossing(glm::vec2 port, glm::vec2 starboard, glm::vec2 from, glm::vec2 to);

} // namespace ob::game
