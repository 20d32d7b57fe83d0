// Righting a capsized ship by key (world/righting.h).
#include "world/righting.h"

#include "behaviours/ship.h"
#include "behaviours/step_input.h"
#include "core/log.h"
#include "ecs/components.h"
#include "physics/physics_world.h"
#include "sim/objects.h"

#include <cmath>

namespace ob::game {

bool capsized(const glm::quat& rotation) {
    return (rotation * glm::vec3(0, 1, 0)).y < std::cos(glm::radians(CAPSIZE_DEG));
}

glm::quat uprightOnHeading(const glm::quat& rotation) {
    // The bow's heading on the water; a ship standing on its bow or stern keeps the heading
    // its deck's normal points along.
    glm::vec3 bow = rotation * glm::vec3(0, 0, 1);
    if (bow.x * bow.x + bow.z * bow.z < 1e-4f) bow = rotation * glm::vec3(0, 1, 0) * (bow.y > 0.0f ? -1.0f : 1.0f);
    const float yaw = std::atan2(bow.x, bow.z);
    return glm::angleAxis(yaw, glm::vec3(0, 1, 0));
}

void rightingSystem(ecs::World& world, const ecs::Tick&) {
    const auto* input = world.resource<StepInput>();
    auto* physicsWorld = world.resource<physics::PhysicsWorld>();
    if (!input || !physicsWorld || !input->wasPressed(platform::Key::T)) return;
    auto& ships = world.pool<Ship>();
    int righted = 0;
    for (size_t i = 0; i < ships.size(); ++i) {
        const ecs::Entity e = ships.entities()[i];
        ecs::Transform* t = world.find<ecs::Transform>(e);
        const Body* body = world.find<Body>(e);
        if (!t || !body || !capsized(t->rotation)) continue;
        physics::BodyState state = physicsWorld->state(body->id);
        state.rotation = t->rotation = uprightOnHeading(t->rotation);
        state.angularVelocity = glm::vec3(0.0f);
        physicsWorld->setState(body->id, state);
        ++righted;
    }
    logInfo("%s", righted > 0 ? "T: capsized ships righted" : "T: no ship is capsized");
}

} // namespace ob::game
