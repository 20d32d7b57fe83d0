// The sun's place by the hour (a clock time of a day at a latitude, the usual spherical
// astronomy: Meeus, "Astronomical Algorithms", ch. 13, with the sun's declination fixed for
// the day) and the direction the renderer lights with. Pure math: no GL.
#pragma once
#include "view_data/render_def.h"

#include <glm/vec3.hpp>

namespace ob::gfx {

/// Unit vector toward the sun at local solar time `hour` (h, 12 = noon) at latitude `latitudeDeg`
/// with the sun's declination `declinationDeg`. World axes: y up, +x east, +z south (north −z),
/// so the sun rises toward +x, stands toward +z at noon (northern latitudes above the
/// declination) and sets toward −x. With the hour angle H = 15°·(hour − 12), latitude φ and
/// declination δ: east = −cos δ·sin H, north = sin δ·cos φ − cos δ·sin φ·cos H,
/// up = sin δ·sin φ + cos δ·cos φ·cos H. Below the horizon (night) y < 0.
glm::vec3 sunAtHour(float hour, float latitudeDeg, float declinationDeg);

/// The direction the renderer lights with: sunAtHour of [render] time_of_day when it is set
/// (≥ 0), else sun_direction normalised.
glm::vec3 sunDirection(const RenderDef& def);

} // namespace ob::gfx
