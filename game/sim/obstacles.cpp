// Waterline footprints of the obstructing bodies.
#include "sim/obstacles.h"

#include "ecs/components.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ob::game {

std::optional<interaction::ObstacleShape> waterlineFootprint(const Obstacle& obstacle, const glm::vec3& position,
                                                             const glm::quat& rotation) {
    using interaction::ObstacleShape;
    if (obstacle.shape == Obstacle::Shape::Sphere) {
        const float r = obstacle.half.x, y = position.y;
        if (std::abs(y) >= r) return std::nullopt;
        return ObstacleShape::disc({position.x, position.z}, std::sqrt(r * r - y * y));
    }
    // The vertical reach of the turned box: Σ |R·e_i|.y·half_i.
    const glm::vec3 ex = rotation * glm::vec3(1, 0, 0), ey = rotation * glm::vec3(0, 1, 0), ez = rotation * glm::vec3(0, 0, 1);
    const float reach = std::abs(ex.y) * obstacle.half.x + std::abs(ey.y) * obstacle.half.y + std::abs(ez.y) * obstacle.half.z;
    if (position.y - reach >= 0.0f || position.y + reach <= 0.0f) return std::nullopt;
    const glm::vec2 axis(ex.x, ex.z);
    const float length = glm::length(axis);
    if (length < 1e-3f) return std::nullopt;  // on its side: no upright footprint to give
    ObstacleShape s;
    s.kind = obstacle.shape == Obstacle::Shape::Hull ? ObstacleShape::Kind::Ellipse : ObstacleShape::Kind::Rect;
    s.centre = {position.x, position.z};
    s.axis = axis / length;
    // The first axis is local x; the second, (−axis.y, axis.x), is local z turned the same way.
    s.half = {obstacle.half.x, obstacle.half.z};
    return s;
}

std::vector<interaction::ObstacleShape> obstacleFootprints(ecs::World& world) {
    std::vector<interaction::ObstacleShape> shapes;
    auto& obstacles = world.pool<Obstacle>();
    for (size_t i = 0; i < obstacles.size(); ++i) {
        const ecs::Transform* t = world.find<ecs::Transform>(obstacles.entities()[i]);
        if (!t) continue;
        if (auto s = waterlineFootprint(obstacles.components()[i], t->position, t->rotation)) shapes.push_back(*s);
    }
    return shapes;
}

} // namespace ob::game
