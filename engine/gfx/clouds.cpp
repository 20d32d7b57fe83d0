// The cloud layer on the sun's ray (clouds.h): the sky's noise, read as C++.
#include "gfx/clouds.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/vec3.hpp>

namespace ob::gfx {

// The shader's functions as glm spells them (GLSL's names, glm's types): the one source.
namespace cloud_glsl {
using namespace glm;
#include "common_clouds.glsl"
} // namespace cloud_glsl

float cloudBeamLoss(const SkyDef& sky, glm::vec2 drift, glm::vec3 dir) {
    return cloud_glsl::cloudLayerBeamLoss(dir, sky.cloud_cover, drift, sky.cloud_height);
}

} // namespace ob::gfx
