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

glm::vec2 ObstacleShape::pushedOut(glm::vec2 p, float offset) const {
    const glm::vec2 second(-axis.y, axis.x);
    const glm::vec2 d = p - centre;
    glm::vec2 q(glm::dot(d, axis), glm::dot(d, second));  // the shape's frame
    // The shape's own norm of q (1 on the outline): Euclidean over the semi-axes for an
    // ellipse, the larger ratio for a rectangle. At the centre itself, out along the first axis.
    const glm::vec2 r = q / half;
    float k = kind == Kind::Ellipse ? glm::length(r) : std::max(std::abs(r.x), std::abs(r.y));
    if (k < 1e-6f) {
        q = {half.x, 0.0f};
        k = 1.0f;
    }
    const glm::vec2 b = q / k;  // on the outline
    glm::vec2 n;                // its outward normal
    if (kind == Kind::Ellipse) n = b / (half * half);
    else n = std::abs(b.x) / half.x >= std::abs(b.y) / half.y ? glm::vec2(b.x, 0.0f) : glm::vec2(0.0f, b.y);
    n = glm::normalize(n);
    const glm::vec2 out = b + n * offset;
    return centre + out.x * axis + out.y * second;
}

} // namespace ob::interaction
