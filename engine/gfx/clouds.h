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

/// The share, [0, 1], of the sun's direct beam the cloud layer holds back along the unit
/// direction `dir` (toward the sun), the clouds drifted by `drift` (m): 0 under a clear sky,
/// the thin veil's few percent in a gap, all of it behind a cloud's core or under an overcast.
float cloudBeamLoss(const SkyDef& sky, glm::vec2 drift, glm::vec3 dir);

} // namespace ob::gfx
