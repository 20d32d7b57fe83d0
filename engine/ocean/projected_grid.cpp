// Projected grid corners: ray/plane intersections in homogeneous coordinates.
#include "ocean/projected_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace ob::ocean {

// Where the ray through NDC (x, y) meets y = 0, as a homogeneous point: with p0, p1 the
// unprojected near and far points (homogeneous), p1.y·p0 − p0.y·p1 has y = 0 and lies on
// their line; it is linear in each, so no division happens before the vertex shader's.
static glm::vec4 planeHit(const glm::mat4& inverseViewProjection, float x, float y) {
    glm::vec4 p0 = inverseViewProjection * glm::vec4(x, y, -1.0f, 1.0f);
    glm::vec4 p1 = inverseViewProjection * glm::vec4(x, y, 1.0f, 1.0f);
    glm::vec4 hit = p1.y * p0 - p0.y * p1;
    return hit.w < 0.0f ? -hit : hit;
}

GridCorners projectedGridCorners(const glm::mat4& viewProjection, const glm::vec3& eye, float margin) {
    GridCorners out;
    const glm::mat4 inv = glm::inverse(viewProjection);
    const bool above = eye.y >= 0.0f;
    // The horizon is the image of the horizontal directions: the screen row where rays are level.
    glm::vec4 nearCentre = inv * glm::vec4(0.0f, 0.0f, -1.0f, 1.0f);
    glm::vec4 farCentre = inv * glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    glm::vec3 forward = glm::vec3(farCentre) / farCentre.w - glm::vec3(nearCentre) / nearCentre.w;
    glm::vec3 level(forward.x, 0.0f, forward.z);
    float horizonY;
    glm::vec4 clip = viewProjection * glm::vec4(level, 0.0f);
    if (glm::dot(level, level) > 1e-12f && clip.w > 0.0f) horizonY = clip.y / clip.w;
    else horizonY = forward.y < 0.0f ? 1e9f : -1e9f;  // looking straight down or up

    // Water rows of the screen, a hair short of the horizon (there w → 0).
    const float lo = -1.0f - margin, hi = 1.0f + margin, gap = 1e-4f;
    float nearY, farY;
    if (above) {
        nearY = lo;
        farY = std::min(hi, horizonY - gap);
        if (farY <= nearY) return out;
    } else {
        nearY = hi;
        farY = std::max(lo, horizonY + gap);
        if (farY >= nearY) return out;
    }
    out.corner = {planeHit(inv, lo, nearY), planeHit(inv, hi, nearY), planeHit(inv, lo, farY), planeHit(inv, hi, farY)};
    float maxW = 0.0f;
    for (const glm::vec4& c : out.corner) maxW = std::max(maxW, c.w);
    if (!(maxW > 0.0f)) return out;
    for (glm::vec4& c : out.corner) c /= maxW;
    out.visible = true;
    return out;
}

glm::vec2 projectedGridPoint(const GridCorners& corners, glm::vec2 uv, float minW) {
    const auto& c = corners.corner;
    glm::vec4 p = glm::mix(glm::mix(c[0], c[1], uv.x), glm::mix(c[2], c[3], uv.x), uv.y);
    float w = std::max(p.w, minW);
    return glm::vec2(p.x, p.z) / w;
}

} // namespace ob::ocean
