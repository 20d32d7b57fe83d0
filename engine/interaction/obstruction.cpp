// Obstacle footprints: signed distance to a rectangle or an ellipse on the water plane.
#include "interaction/obstruction.h"

namespace ob::interaction {

float ObstacleShape::distance(glm::vec2 p) const {
    const glm::vec2 d = p - centre;
    // In the shape's frame: first axis, then its perpendicular; by symmetry, the first quadrant.
    const glm::vec2 q = glm::abs(glm::vec2(glm::dot(d, axis), glm::dot(d, glm::vec2(-axis.y, axis.x))));
    if (kind == Kind::Rect) {
        const glm::vec2 out = q - half;
        return glm::length(glm::max(out, glm::vec2(0.0f))) + std::min(std::max(out.x, out.y), 0.0f);
    }
    // Ellipse: (|q/r| − 1)·|q/r| / |q/r²| (the implicit function over its gradient's length).
    const float k0 = glm::length(q / half);
    const float k1 = glm::length(q / (half * half));
    if (k1 == 0.0f) return -std::min(half.x, half.y);  // the centre
    return (k0 - 1.0f) * k0 / k1;
}

float ObstacleShape::hollowLevel(glm::vec2 p) const {
    if (!displaces || hollow <= 0.0f) return 0.0f;
    const glm::vec2 d = p - centre;
    const glm::vec2 r = glm::vec2(glm::dot(d, axis), glm::dot(d, glm::vec2(-axis.y, axis.x))) / half;
    const float k = kind == Kind::Ellipse ? glm::dot(r, r) : std::pow(std::max(std::abs(r.x), std::abs(r.y)), 2.0f);
    return -hollow * std::max(0.0f, 1.0f - k);
}

} // namespace ob::interaction
