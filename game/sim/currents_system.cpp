// The current layer's system: follow, wind, walls, impulses, step.
#include "sim/currents_system.h"

#include "currents/current_layer.h"
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
    for (const WaterImpulse& i : impulses->items) layer->addImpulse(i.at, i.impulse, std::max(i.radius, 0.5f * layer->cellSize()));
    impulses->items.clear();
    layer->step(float(tick.dt));
}

} // namespace ob::game
