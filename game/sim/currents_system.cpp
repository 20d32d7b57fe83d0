// The current layer's system: follow, wind, walls, impulses, step.
#include "sim/currents_system.h"

#include "currents/current_layer.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "sim/obstacles.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace ob::game {

void addCurrents(ecs::World& world, const currents::CurrentsDef& def, float waterDensity) {
    if (!def.enabled) return;
    auto& layer = world.setResource(std::make_unique<currents::CurrentLayer>(def, waterDensity));
    world.setResource(std::make_unique<WaterImpulses>());
    if (OceanState* ocean = world.resource<OceanState>())
        ocean->water->setCurrent([&layer](float x, float z) { return layer.velocityAt({x, z}); });
}

void currentsSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* layer = world.resource<currents::CurrentLayer>();
    auto* impulses = world.resource<WaterImpulses>();
    if (!layer || !impulses) return;
    if (const auto* patch = world.resource<interaction::RipplePatch>()) {
        const float half = 0.5f * patch->def().cell_size * float(patch->cols() - 1);
        layer->centerOn(patch->origin() + glm::vec2(half));
    }
    if (const OceanState* ocean = world.resource<OceanState>()) {
        const glm::vec2 d = ocean->def.wind_direction;
        layer->setWind(glm::dot(d, d) > 0.0f ? ocean->def.wind_speed * glm::normalize(d) : glm::vec2(0.0f));
        // Walls: the fixed bodies. A floating hull moves with its water and trades momentum with
        // it through its forces (WaterImpulses); held as a still wall it would stop the water it carries.
        std::vector<interaction::ObstacleShape> walls = obstacleFootprints(world, ocean->water.get());
        std::erase_if(walls, [](const interaction::ObstacleShape& s) { return s.displaces; });
        layer->setWalls(walls);
    }
    // Hulls push their water aside (a Rankine body each: CurrentLayer::Displacer), at their speed
    // along the keel through the layer's flow.
    std::vector<currents::CurrentLayer::Displacer> displacers;
    auto& obstacles = world.pool<Obstacle>();
    for (size_t k = 0; k < obstacles.size(); ++k) {
        const Obstacle& o = obstacles.components()[k];
        const ecs::Entity e = obstacles.entities()[k];
        const Body* body = world.find<Body>(e);
        if (o.shape != Obstacle::Shape::Hull || !body || body->submergedFraction <= 0.0f) continue;
        const ecs::Transform& t = world.get<ecs::Transform>(e);
        glm::vec3 keel = t.rotation * glm::vec3(0.0f, 0.0f, 1.0f);
        const glm::vec2 axis(keel.x, keel.z);
        if (glm::dot(axis, axis) < 1e-6f) continue;
        const glm::vec2 a = glm::normalize(axis), centre(t.position.x, t.position.z);
        const glm::vec3 v = world.get<ecs::Motion>(e).velocity;
        const float speed = glm::dot(glm::vec2(v.x, v.z) - layer->flowAt(centre), a);
        const float reach = std::max(o.half.z - o.half.x, 0.0f);  // the source and sink a half-beam inside the ends
        displacers.push_back({centre + a * reach, centre - a * reach, speed * 2.0f * o.half.x, o.half.x});
    }
    layer->setDisplacers(std::move(displacers));
    for (const WaterImpulse& i : impulses->items) layer->addImpulse(i.at, i.impulse, std::max(i.radius, 0.5f * layer->cellSize()));
    impulses->items.clear();
    layer->step(float(tick.dt));
}

} // namespace ob::game
