// Cannon behaviour: aiming, firing (a Bullet sphere per shot), removing sunk balls.
#include "behaviours/cannon.h"

#include "assets/model.h"
#include "ecs/components.h"
#include "interaction/sphere_set.h"
#include "behaviours/step_input.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace ob::game {

namespace {

constexpr float AIM_RATE_DEG_S = 30.0f;                // arrow keys turn the barrel this fast
constexpr glm::vec3 BALL_COLOR{0.05f, 0.05f, 0.06f};   // iron
constexpr glm::vec3 PILLAR_COLOR{0.35f, 0.33f, 0.30f}; // stone

// The paper's cannonball sphere ([Kang2008] §V-1): SHR 1.0, AF 0; it falls in, so it pushes the
// water down. Its size in metres is the ball's own ([Kang2008]'s SR 5 cells are its 0.5 m ball on
// 0.1 m cells, cannon.toml), so the ripple cell size changes neither the stamp's extent in the
// world nor the splash crown.
interaction::BoundingSphere paperBallSphere(float ballRadius) {
    interaction::BoundingSphere s;
    s.radius = ballRadius;
    s.direction = interaction::SphereDirection::Down;
    s.heightRatio = 1.0f;
    s.accelerationFactor = 0.0f;
    return s;
}

glm::quat aimRotation(float yawDeg, float elevationDeg) {
    return glm::angleAxis(glm::radians(yawDeg), glm::vec3(0, 1, 0)) *
           glm::angleAxis(-glm::radians(elevationDeg), glm::vec3(1, 0, 0));  // +z tilts up
}

void fire(ecs::World& world, Cannon& cannon, glm::vec3 pivot) {
    auto& physicsWorld = *world.resource<physics::PhysicsWorld>();
    const glm::vec3 aim = cannonAim(cannon.yawDeg, cannon.elevationDeg);
    const float r = cannon.def.ball_radius;
    const float volume = 4.0f / 3.0f * float(M_PI) * r * r * r;
    const float mass = cannon.def.ball_density * volume;
    physics::BodyState start;
    start.position = pivot + aim * CANNON_BARREL;
    start.linearVelocity = aim * cannon.def.muzzle_speed;
    physics::BodyId id = physicsWorld.addSphere(r, mass, start);
    ecs::Entity ball = spawnBody(world, ObjectType::Sphere, "", id, {Probe{glm::vec3(0.0f), r}}, volume, mass, start,
                                 Renderable{gfx::MeshKind::Sphere, glm::vec3(r), BALL_COLOR, cannon.ballModel});
    world.add<interaction::SphereSet>(ball, {{cannon.ballSphere}, {}, false});
    world.add<Cannonball>(ball, {cannon.def.sink_depth});
    ++cannon.shots;
}

} // namespace

Limits cannonElevationLimits() { return keyLimits<CannonDef>("elevation_deg"); }

float clampElevationDeg(float deg) {
    const Limits l = cannonElevationLimits();
    return std::clamp(deg, float(l.min), float(l.max));
}

glm::vec3 cannonAim(float yawDeg, float elevationDeg) {
    const float yaw = glm::radians(yawDeg), elevation = glm::radians(elevationDeg);
    return {std::sin(yaw) * std::cos(elevation), std::sin(elevation), std::cos(yaw) * std::cos(elevation)};
}

ecs::Entity spawnCannon(ecs::World& world, const ObjectDef& o) {
    // The pillar it stands on, from below the waves up to the pivot: a fixed body (static in
    // Bullet, balls bounce off it) that obstructs the ripples where it stands in the water.
    const float bottom = -6.0f, top = o.position.y - 0.4f;
    if (top > bottom) {
        const glm::vec3 half(0.8f, 0.5f * (top - bottom), 0.8f);
        physics::BodyState start;
        start.position = glm::vec3(o.position.x, 0.5f * (bottom + top), o.position.z);
        const physics::BodyId id = world.resource<physics::PhysicsWorld>()->addBox(half, 0.0f, start);
        ecs::Entity pillar = spawnBody(world, ObjectType::Box, "", id, {}, 8.0f * half.x * half.y * half.z, 0.0f, start,
                                       Renderable{gfx::MeshKind::Box, half, PILLAR_COLOR, assets::projectModel("pillar")});
        world.add<Obstacle>(pillar, {Obstacle::Shape::Box, half});
    }
    ecs::Entity e = world.create();
    world.add<ecs::Transform>(e, {o.position, aimRotation(o.cannon.yaw_deg, o.cannon.elevation_deg)});
    // A model is in metres with its pivot at the origin; the built-in box is the barrel.
    const glm::vec3 scale = o.model.empty() ? glm::vec3(0.22f, 0.22f, 0.5f * CANNON_BARREL) : glm::vec3(1.0f);
    world.add<Renderable>(e, {gfx::MeshKind::Box, scale, o.color, o.model});
    world.add<ObjectTag>(e, {ObjectType::Cannon, o.name});
    Cannon cannon;
    cannon.def = o.cannon;
    cannon.yawDeg = o.cannon.yaw_deg;
    cannon.elevationDeg = o.cannon.elevation_deg;
    cannon.ballModel = assets::projectModel("cannonball");
    cannon.ballSphere = boundingSphereFor(o, paperBallSphere(o.cannon.ball_radius), rippleCellSize(world));
    world.add<Cannon>(e, cannon);
    return e;
}

void cannonSystem(ecs::World& world, const ecs::Tick& tick) {
    // --- sunk balls leave the world
    auto& balls = world.pool<Cannonball>();
    std::vector<ecs::Entity> sunk;
    for (size_t i = 0; i < balls.size(); ++i) {
        const ecs::Transform* t = world.find<ecs::Transform>(balls.entities()[i]);
        if (t && t->position.y < -balls.components()[i].sinkDepth) sunk.push_back(balls.entities()[i]);
    }
    for (ecs::Entity e : sunk) destroyBody(world, e);

    // --- aim and fire
    const auto* input = world.resource<StepInput>();
    const float dt = float(tick.dt);
    auto& cannons = world.pool<Cannon>();
    for (size_t i = 0; i < cannons.size(); ++i) {
        const ecs::Entity e = cannons.entities()[i];
        if (cannons.components()[i].def.player && input) {
            Cannon& c = cannons.components()[i];
            using platform::Key;
            c.yawDeg += AIM_RATE_DEG_S * dt * float(input->isDown(Key::Left) - input->isDown(Key::Right));
            c.elevationDeg = clampElevationDeg(c.elevationDeg + AIM_RATE_DEG_S * dt * float(input->isDown(Key::Up) - input->isDown(Key::Down)));
            c.fireRequested = c.fireRequested || input->wasPressed(Key::Space);
        }
        Cannon& c = cannons.components()[i];
        ecs::Transform& pivot = world.get<ecs::Transform>(e);
        pivot.rotation = aimRotation(c.yawDeg, c.elevationDeg);
        bool shoot = c.fireRequested;
        c.fireRequested = false;
        if (c.def.rate > 0.0f) {
            c.cooldown -= tick.dt;
            if (c.cooldown <= 0.0) {
                shoot = true;
                c.cooldown += 1.0 / double(c.def.rate);
            }
        }
        if (shoot) fire(world, c, pivot.position);  // adds a ball: Transform references die here
    }
}

StampSource cannonSource() {
    return {"cannons", [](ecs::World&, SphereUse, const SphereVisitor&) {},
            [](ecs::World& world) {
                float largest = 0.0f;
                for (const Cannon& c : world.pool<Cannon>().components())
                    largest = std::max(largest, c.ballSphere.radius * c.ballSphere.heightRatio);
                return largest;
            }};
}

} // namespace ob::game
