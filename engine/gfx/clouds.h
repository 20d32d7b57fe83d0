// The cloud layer on the sun's own ray ([sky], docs/look.md#weather): how much of the sun's
// direct light a broken sky's clouds hold back at this moment, found once a frame on the CPU
// from the same noise the sky draws (shaders/common_clouds.glsl, read here as C++), so the
// light on the sea, the glitter and the sun's disc dim as a cloud passes the sun and come back
// in its gaps. Pure math: no GL.
#pragma once
#include "view_data/sky_def.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob::gfx {

/// The share, [0, 1], of the light from behind the cloud layer that it hides along the unit
/// direction `dir` (toward the sky), the clouds drifted by `drift` (m): 0 in a gap or a clear
/// sky, CLOUD_HIDES of it behind a cloud's core, all of it under an overcast.
float cloudOpacity(const SkyDef& sky, glm::vec2 drift, glm::vec3 dir);

} // namespace ob::gfx
