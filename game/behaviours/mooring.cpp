// Moored and flooding bodies (behaviours/mooring.h).
#include "behaviours/mooring.h"

#include "ecs/components.h"
#include "sim/objects.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ob::game {

void moor(ecs::World& world, ecs::Entity body, float period) {
    if (period <= 0.0f || !world.has<Body>(body) || world.has<Moored>(body)) return;
    if (const ecs::Transform* t = world.find<ecs::Transform>(body)) world.add<Moored>(body, {t->position, period});
}

void hole(ecs::World& world, ecs::Entity body) {
    if (world.has<Body>(body) && !world.has<Flooding>(body)) world.add<Flooding>(body, {});
}

void mooringSystem(ecs::World& world, const ecs::Tick& tick) {
    const float dt = float(tick.dt);
    auto& moored = world.pool<Moored>();
    for (size_t i = 0; i < moored.size(); ++i) {
        const ecs::Entity e = moored.entities()[i];
        Body* body = world.find<Body>(e);
        if (!body) continue;
        const Moored& m = moored.components()[i];
        const float omega = 2.0f * float(M_PI) / m.period;
        const float implicit = 1.0f + 2.0f * omega * dt + omega * omega * dt * dt;
        const glm::vec3 p = world.get<ecs::Transform>(e).position;
        const ecs::Motion& motion = world.get<ecs::Motion>(e);
        glm::vec3 force = -motion.mass * (omega * omega * (p - m.anchor) + (2.0f * omega + omega * omega * dt) * motion.velocity) / implicit;
        force.y = 0.0f;
        body->forces.push_back({force, p});
    }
}

void floodingSystem(ecs::World& world, const ecs::Tick& tick) {
    auto& flooding = world.pool<Flooding>();
    if (flooding.size() == 0) return;
    const auto& physics = physicsDef(world);
    std::vector<ecs::Entity> gone;
    for (size_t i = 0; i < flooding.size(); ++i) {
        const ecs::Entity e = flooding.entities()[i];
        Body* body = world.find<Body>(e);
        if (!body) continue;
        Flooding& f = flooding.components()[i];
        const glm::vec3 p = world.get<ecs::Transform>(e).position;
        if (p.y < -f.gone_depth) {
            gone.push_back(e);
            continue;
        }
        f.filled = std::min(1.0f, f.filled + float(tick.dt) / f.fill_s);
        body->forces.push_back({glm::vec3(0.0f, -f.filled * physics.water_density * body->volume * physics.gravity, 0.0f), p});
    }
    for (ecs::Entity e : gone) destroyBody(world, e);
}

} // namespace ob::game
