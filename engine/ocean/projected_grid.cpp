// Projected grid corners: ray/plane intersections in homogeneous coordinates.
#include "ocean/projected_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace ob::ocean {

// Where the ray through NDC (x, y) meets y = 0, as a homogeneous point. With M the inverse
// view-projection, the ray is M·(x, y, s, 1) over NDC depth s; its y is q.y + s·m.y with
// q = M·(x, y, 0, 1) and m = M's z column, so the hit is q − (q.y / m.y)·m: LINEAR in
// (x, y) with one scale for every pixel, which is what makes interpolating the corners in
// homogeneous coordinates exact (the screen-to-plane map is a homography).
static glm::vec4 planeHit(const glm::mat4& inverseViewProjection, float x, float y) {
    glm::vec4 q = inverseViewProjection * glm::vec4(x, y, 0.0f, 1.0f);
    const glm::vec4& m = inverseViewProjection[2];
    return q - (q.y / m.y) * m;
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

    // Water rows of the screen, a hair short of the horizon (there w → 0). The edge nearest
    // the camera reaches 4× further: crests there rise on screen and would open a gap.
    const float lo = -1.0f - margin, hi = 1.0f + margin, gap = 1e-4f;
    const float nearLo = -1.0f - 4.0f * margin, nearHi = 1.0f + 4.0f * margin;
    float nearY, farY;
    if (above) {
        nearY = nearLo;
        farY = std::min(hi, horizonY - gap);
        if (farY <= nearY) return out;
    } else {
        nearY = nearHi;
        farY = std::max(lo, horizonY + gap);
        if (farY >= nearY) return out;
    }
    if (std::abs(inv[2].y) < 1e-12f) return out;  // NDC depth never changes height: degenerate camera
    out.corner = {planeHit(inv, lo, nearY), planeHit(inv, hi, nearY), planeHit(inv, lo, farY), planeHit(inv, hi, farY)};
    // One common scale (and sign) for all four, so w > 0 on the water side and max w = 1.
    float maxW = std::max(std::abs(out.corner[0].w), std::abs(out.corner[1].w));
    if (!(maxW > 0.0f)) return out;
    float scale = (out.corner[0].w > 0.0f ? 1.0f : -1.0f) / maxW;
    for (glm::vec4& c : out.corner) c *= scale;
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
