// Objects of a scene ([[objects]]): floating bodies simulated by Bullet, pushed by the water
// through probe spheres (buoyancy, drag) and pushing it back through bounding spheres.
#pragma once
#include "core/schema.h"
#include "ecs/schedule.h"
#include "gfx/renderer.h"
#include "physics/buoyancy.h"
#include "physics/physics_world.h"

#include <string>
#include <vector>

namespace ob::game {

/// One [[objects]] entry.
struct ObjectDef {
    std::string type = "sphere";          ///< "sphere" (uses radius) or "box" (uses size)
    glm::vec3 position{0.0f, 2.0f, 0.0f}; ///< start centre, world m
    glm::vec3 velocity{0.0f};             ///< start velocity, m/s
    float radius = 0.5f;                  ///< sphere radius, m, [0.01, 100]
    glm::vec3 size{1.0f, 1.0f, 1.0f};     ///< box edge lengths [x, y, z], m, each [0.01, 1000]
    float density = 500.0f;               ///< kg/m³, [1, 100000] (water: 1025; below floats)
    glm::vec3 color{0.75f, 0.32f, 0.18f}; ///< base colour, linear RGB
    std::string model;                    ///< glTF 2.0 file drawn instead of the built-in mesh ("" = built-in)
};

template <class V> void describe(V& v, ObjectDef& d) {
    v.field("type", d.type, Choices{"sphere", "box"}, "body shape");
    v.field("position", d.position, any(), "start centre, world m");
    v.field("velocity", d.velocity, any(), "start velocity, m/s");
    v.field("radius", d.radius, range(0.01, 100), "sphere radius, m");
    v.field("size", d.size, range(0.01, 1000), "box edge lengths, m");
    v.field("density", d.density, range(1, 100000), "density, kg/m³");
    v.field("color", d.color, range(0, 1), "base colour (linear RGB)");
    v.field("model", d.model, Choices{}, "glTF 2.0 file (.gltf/.glb) drawn instead of the built-in mesh");
}

/// A probe sphere in the body's frame: where the water pushes (buoyancy, drag).
struct Probe {
    glm::vec3 offset{0.0f};  ///< m
    float radius = 0.5f;     ///< m
};

/// A simulated body: its Bullet id, its probes, and what the water did last step.
struct Body {
    std::string type;
    physics::BodyId id = physics::BodyId::None;
    std::vector<Probe> probes;
    float volume = 0.0f;             ///< m³ of the solid
    float submergedFraction = 0.0f;  ///< of the probes' volume under the surface, last step
};

/// How an object looks: mesh, scale (unit mesh → object), colour.
struct Renderable {
    gfx::MeshKind mesh = gfx::MeshKind::Sphere;
    glm::vec3 scale{1.0f};
    glm::vec3 color{0.8f};
    std::string model;    ///< glTF file replacing `mesh` ("" = built-in)
};

/// Creates the physics resource and one entity per object (Transform, Motion, Body,
/// Renderable, SphereSet with the paper's cannonball sphere: SHR 1, AF 0, SD −1: it pushes down).
void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects);
/// Physics phase: water forces on every probe, the Bullet step, poses back to the entities.
void physicsSystem(ecs::World& world, const ecs::Tick& tick);
/// What the opaque pass draws this frame.
std::vector<gfx::ObjectDraw> objectDraws(ecs::World& world);

} // namespace ob::game
