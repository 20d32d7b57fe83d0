// Waterline footprints of the obstructing bodies.
#include "sim/obstacles.h"

#include "assets/hull_outline.h"
#include "ecs/components.h"
#include "water/water_query.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ob::game {

namespace {

// Where the line a·u + b·w + c = 0 crosses the rectangle |u| ≤ hu, |w| ≤ hw (a section of the
// hull box: u across or along it, w up it; a·u + b·w + c the height of (u, w) above the water).
struct Cut {
    glm::vec2 mid;  // the middle of the segment, section coordinates (u, w), m
    glm::vec2 dir;  // unit, along the segment (horizontal in the world)
    float half;     // half its length, m
};

std::optional<Cut> cutSection(float a, float b, float c, float hu, float hw) {
    const glm::vec2 n(a, b);
    const float nn = glm::dot(n, n);
    if (nn < 1e-12f) return std::nullopt;  // the section lies flat in the plane: no line to cut
    const glm::vec2 p0 = -c * n / nn, dir = glm::vec2(-b, a) / std::sqrt(nn);
    // Slab clipping of p0 + t·dir to the rectangle.
    float t0 = -1e30f, t1 = 1e30f;
    const float extent[2] = {hu, hw};
    for (int i = 0; i < 2; ++i) {
        if (std::abs(dir[i]) < 1e-9f) {
            if (std::abs(p0[i]) > extent[i]) return std::nullopt;
            continue;
        }
        const float ta = (-extent[i] - p0[i]) / dir[i], tb = (extent[i] - p0[i]) / dir[i];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    if (t1 <= t0) return std::nullopt;
    return Cut{p0 + dir * (0.5f * (t0 + t1)), dir, 0.5f * (t1 - t0)};
}

} // namespace

std::optional<interaction::ObstacleShape> hullWaterplane(const glm::vec3& half, const glm::vec3& position,
                                                         const glm::quat& rotation, float waterY) {
    const glm::vec3 ex = rotation * glm::vec3(1, 0, 0), ey = rotation * glm::vec3(0, 1, 0), ez = rotation * glm::vec3(0, 0, 1);
    const float c = position.y - waterY;
    const std::optional<Cut> across = cutSection(ex.y, ey.y, c, half.x, half.y);  // the section z = 0
    const std::optional<Cut> along = cutSection(ez.y, ey.y, c, half.z, half.y);   // the section x = 0
    if (!across || !along) return std::nullopt;
    const glm::vec3 axis3 = rotation * glm::vec3(across->dir.x, across->dir.y, 0.0f);  // horizontal by construction
    const glm::vec2 axis(axis3.x, axis3.z);
    const float length = glm::length(axis);
    if (length < 1e-3f) return std::nullopt;
    const glm::vec3 mid = position + rotation * glm::vec3(across->mid.x, across->mid.y, along->mid.x);
    interaction::ObstacleShape s;
    s.kind = interaction::ObstacleShape::Kind::Ellipse;
    s.centre = {mid.x, mid.z};
    s.axis = axis / length;
    s.half = {across->half, along->half};
    s.displaces = true;
    return s;
}

std::optional<interaction::ObstacleShape> waterlineFootprint(const Obstacle& obstacle, const glm::vec3& position,
                                                             const glm::quat& rotation) {
    using interaction::ObstacleShape;
    if (obstacle.shape == Obstacle::Shape::Hull) {
        std::optional<interaction::ObstacleShape> s = hullWaterplane(obstacle.half, position, rotation, 0.0f);
        if (s) s->hollow = obstacle.hollow;
        return s;
    }
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
    s.kind = ObstacleShape::Kind::Rect;
    s.centre = {position.x, position.z};
    s.axis = axis / length;
    // The first axis is local x; the second, (−axis.y, axis.x), is local z turned the same way.
    s.half = {obstacle.half.x, obstacle.half.z};
    return s;
}

std::vector<interaction::ObstacleShape> obstacleFootprints(ecs::World& world, const water::WaterQuery* water) {
    std::vector<interaction::ObstacleShape> shapes;
    auto& obstacles = world.pool<Obstacle>();
    for (size_t i = 0; i < obstacles.size(); ++i) {
        const ecs::Transform* t = world.find<ecs::Transform>(obstacles.entities()[i]);
        if (!t) continue;
        const Obstacle& o = obstacles.components()[i];
        std::optional<interaction::ObstacleShape> s;
        if (o.shape == Obstacle::Shape::Hull) {
            water::WaterLayers sea;
            sea.ripples = false;  // the ripple layer is what the footprint obstructs, not where the hull sits
            sea.currents = false;  // heights only (the current layer may be stepping on a worker)
            const float waterY = water ? water->sample(t->position.x, t->position.z, sea).height : 0.0f;
            s = hullWaterplane(o.half, t->position, t->rotation, waterY);
            if (s) s->hollow = o.hollow;
        } else {
            s = waterlineFootprint(o, t->position, t->rotation);
        }
        if (s) shapes.push_back(*s);
    }
    return shapes;
}

namespace {

// The outline of the model `look` draws over the box of half extents `half` (the body's
// frame), from the world's cache (made there on first use).
std::shared_ptr<const assets::HullOutline> outlineOf(ecs::World& world, const Renderable& look, glm::vec3 half) {
    auto* cache = world.resource<HullOutlines>();
    if (!cache) cache = &world.setResource(std::make_unique<HullOutlines>());
    const glm::vec3 box = half / look.scale;  // the box in the model's metres
    auto& outline = cache->byModel[{look.model, box.x, box.y, box.z}];
    if (!outline) outline = std::make_shared<const assets::HullOutline>(assets::hullOutline(assets::loadGltfModel(look.model), -box, box));
    return outline;
}

} // namespace

std::vector<gfx::HullClip> hullClips(ecs::World& world) {
    std::vector<gfx::HullClip> clips;
    auto& obstacles = world.pool<Obstacle>();
    for (size_t i = 0; i < obstacles.size(); ++i) {
        const Obstacle& o = obstacles.components()[i];
        const ecs::Entity e = obstacles.entities()[i];
        const ecs::Transform* t = world.find<ecs::Transform>(e);
        if (o.shape != Obstacle::Shape::Hull || !t) continue;
        const Renderable* look = world.find<Renderable>(e);
        gfx::HullClip c;
        c.worldToHull = glm::scale(glm::mat4(1.0f), 1.0f / o.half) * glm::mat4_cast(glm::conjugate(t->rotation)) *
                        glm::translate(glm::mat4(1.0f), -t->position);
        if (look && !look->model.empty()) c.outline = outlineOf(world, *look, o.half);
        clips.push_back(c);
    }
    return clips;
}

} // namespace ob::game
