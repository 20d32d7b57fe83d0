// Floating bodies: spawning, water forces (Archimedes + drag per probe), Bullet stepping.
#include "objects.h"

#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "interaction/sphere_set.h"
#include "water/composite_water.h"
#include "water_systems.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace ob::game {

// Probes with the solid's volume: a sphere is its own probe (exact Archimedes); a box is
// a 3×3×3 lattice of equal spheres whose volumes sum to the box's.
static std::vector<Probe> probesFor(const ObjectDef& o) {
    if (o.type == "sphere") return {Probe{glm::vec3(0.0f), o.radius}};
    std::vector<Probe> probes;
    float volume = o.size.x * o.size.y * o.size.z;
    float r = std::cbrt(volume / (27.0f * 4.0f / 3.0f * float(M_PI)));
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) probes.push_back({glm::vec3(i, j, k) * o.size / 3.0f, r});
    return probes;
}

void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects) {
    auto& physicsWorld = world.setResource(std::make_unique<physics::PhysicsWorld>(def));
    world.setResource(std::make_unique<physics::PhysicsDef>(def));
    for (const ObjectDef& o : objects) {
        const bool sphere = o.type == "sphere";
        float volume = sphere ? 4.0f / 3.0f * float(M_PI) * o.radius * o.radius * o.radius : o.size.x * o.size.y * o.size.z;
        float mass = o.density * volume;
        physics::BodyState start;
        start.position = o.position;
        start.linearVelocity = o.velocity;
        physics::BodyId id = sphere ? physicsWorld.addSphere(o.radius, mass, start) : physicsWorld.addBox(o.size * 0.5f, mass, start);

        ecs::Entity e = world.create();
        world.add<ecs::Transform>(e, {o.position});
        world.add<ecs::Motion>(e, {o.velocity, mass});
        world.add<Body>(e, {o.type, id, probesFor(o), volume, 0.0f});
        world.add<Renderable>(e, {sphere ? gfx::MeshKind::Sphere : gfx::MeshKind::Box, sphere ? glm::vec3(o.radius) : o.size * 0.5f, o.color, o.model});
        interaction::BoundingSphere bounding;
        bounding.radius = sphere ? o.radius : 0.5f * std::min({o.size.x, o.size.y, o.size.z});
        bounding.direction = interaction::SphereDirection::Down;  // a floating body pushes the water down
        bounding.heightRatio = 1.0f;
        bounding.accelerationFactor = 0.0f;
        world.add<interaction::SphereSet>(e, {{bounding}, {}});
    }
}

// The ripple level a body floats in: the patch averaged on a ring just outside the body's
// own footprint. A body sees the waves of others arriving (a ship rocks in another's wake)
// but not the crater it stamps itself, which would feed its buoyancy back into its stamps.
static float rippleAround(const interaction::RipplePatch& patch, glm::vec2 xz, float radius) {
    const float ring = radius + 2.0f * patch.def().cell_size;
    float sum = 0.0f;
    for (int k = 0; k < 8; ++k) {
        float a = float(k) * float(M_PI) / 4.0f;
        sum += patch.heightAt(xz + ring * glm::vec2(std::cos(a), std::sin(a)));
    }
    return sum / 8.0f;
}

void physicsSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* physicsWorld = world.resource<physics::PhysicsWorld>();
    const auto* def = world.resource<physics::PhysicsDef>();
    if (!physicsWorld) return;
    const water::WaterQuery* water = nullptr;
    if (OceanState* ocean = world.resource<OceanState>()) water = ocean->water.get();
    const water::FlatWater flat(0.0f);
    if (!water) water = &flat;
    const float dt = float(tick.dt);
    const auto* patch = world.resource<interaction::RipplePatch>();

    // --- water forces, per probe
    auto& bodies = world.pool<Body>();
    for (size_t b = 0; b < bodies.size(); ++b) {
        Body& body = bodies.components()[b];
        const auto* spheres = world.find<interaction::SphereSet>(bodies.entities()[b]);
        const float reach = spheres && !spheres->spheres.empty() ? spheres->spheres[0].radius : 0.0f;
        physics::BodyState s = physicsWorld->state(body.id);
        float submerged = 0.0f, total = 0.0f;
        for (const Probe& probe : body.probes) {
            physics::ProbeState p;
            p.centre = s.position + s.rotation * probe.offset;
            p.radius = probe.radius;
            p.velocity = s.linearVelocity + glm::cross(s.angularVelocity, p.centre - s.position);
            water::WaterSample w = water->sample(p.centre.x, p.centre.z);
            p.surfaceHeight = w.height;
            p.surfaceNormal = w.normal;
            p.surfaceVelocity = w.verticalVelocity;
            if (patch) {
                glm::vec2 xz(p.centre.x, p.centre.z);
                p.surfaceHeight += rippleAround(*patch, xz, reach) - patch->heightAt(xz);
                // Drag is against the ocean's motion only: between a stamp and the next
                // step the ripple cells near a body always move, which is no real current.
                p.surfaceVelocity -= patch->velocityAt(xz, dt);
            }
            physics::ProbeForce f = physics::probeForce(*def, p);
            physicsWorld->applyForce(body.id, f.force, f.point);
            float v = probe.radius * probe.radius * probe.radius;
            submerged += f.submergedFraction * v;
            total += v;
        }
        body.submergedFraction = total > 0.0f ? submerged / total : 0.0f;
        if (body.submergedFraction > 0.0f)
            physicsWorld->dampAngular(body.id, std::pow(1.0f - def->angular_damping, dt * body.submergedFraction));
    }

    // --- rigid-body step
    physicsWorld->step(dt);

    // --- poses back to the entities
    for (size_t i = 0; i < bodies.size(); ++i) {
        ecs::Entity e = bodies.entities()[i];
        physics::BodyState s = physicsWorld->state(bodies.components()[i].id);
        ecs::Transform& t = world.get<ecs::Transform>(e);
        t.position = s.position;
        t.rotation = s.rotation;
        world.get<ecs::Motion>(e).velocity = s.linearVelocity;
    }
}

std::vector<gfx::ObjectDraw> objectDraws(ecs::World& world) {
    std::vector<gfx::ObjectDraw> draws;
    auto& renderables = world.pool<Renderable>();
    for (size_t i = 0; i < renderables.size(); ++i) {
        const Renderable& r = renderables.components()[i];
        const ecs::Transform* t = world.find<ecs::Transform>(renderables.entities()[i]);
        if (!t) continue;
        glm::mat4 model = glm::translate(glm::mat4(1.0f), t->position) * glm::mat4_cast(t->rotation) * glm::scale(glm::mat4(1.0f), r.scale);
        draws.push_back({r.mesh, model, r.color, r.model});
    }
    return draws;
}

} // namespace ob::game
