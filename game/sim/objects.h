// Objects of a scene ([[objects]]): floating bodies simulated by Bullet, pushed by the water
// through probe spheres (buoyancy, drag) and pushing it back through bounding spheres; ships,
// cannons and fish schools are objects with a behaviour (ship.h, cannon.h, fish.h).
#pragma once
#include "core/schema.h"
#include "ecs/schedule.h"
#include "view_data/scene_view.h"
#include "interaction/sphere_stamp.h"
#include "physics/buoyancy.h"
#include "physics/physics_world.h"

#include <functional>
#include <string>
#include <optional>
#include <vector>

namespace ob::game {

/// What an [[objects]] entry is.
enum class ObjectType : uint8_t { Sphere, Box, Ship, Cannon, FishSchool };
constexpr std::array<const char*, 5> names(ObjectType) { return {"sphere", "box", "ship", "cannon", "fish_school"}; }

/// Where a fish school swims.
enum class SchoolShape : uint8_t { Circle, Region };
constexpr std::array<const char*, 2> names(SchoolShape) { return {"circle", "region"}; }

/// Where an object's bounding-sphere values come from.
enum class SphereValues : uint8_t {
    Paper,   ///< [Kang2008] §V's values for the type
    Custom,  ///< the sphere_cells, sphere_height_ratio and sphere_af keys
};
constexpr std::array<const char*, 2> names(SphereValues) { return {"paper", "custom"}; }

/// [[objects]] type "sphere": a floating solid sphere.
struct SphereBodyDef {
    glm::vec3 velocity{0.0f};  ///< start velocity, m/s
    float radius = 0.5f;       ///< m, [0.01, 10000]
    float density = 500.0f;    ///< kg/m³, [1, 100000] (water: 1025; below floats)
    bool fixed = false;        ///< never moves: a static body (balls bounce off) that obstructs the ripples where it cuts the surface
};

template <class V> void describe(V& v, SphereBodyDef& d) {
    v.field("velocity", d.velocity, any(), "start velocity, m/s");
    v.field("radius", d.radius, range(0.01, 10000), "sphere radius, m");
    v.field("density", d.density, range(1, 100000), "density, kg/m³ (water 1025)");
    v.field("fixed", d.fixed, "never moves; obstructs the ripples where it cuts the surface");
}

/// [[objects]] type "box": a floating box.
struct BoxBodyDef {
    glm::vec3 velocity{0.0f};          ///< start velocity, m/s
    glm::vec3 size{1.0f, 1.0f, 1.0f};  ///< edge lengths [x, y, z], m, [0.01, 10000]
    float density = 500.0f;            ///< kg/m³, [1, 100000] (water: 1025; below floats)
    float yaw_deg = 0.0f;              ///< start turn about +y, deg, [-360, 360] (a wall's direction)
    bool fixed = false;                ///< never moves: a static body (a wall, a pier, a post) that obstructs the ripples where it cuts the surface
};

template <class V> void describe(V& v, BoxBodyDef& d) {
    v.field("velocity", d.velocity, any(), "start velocity, m/s");
    v.field("size", d.size, range(0.01, 10000), "box edge lengths, m");
    v.field("density", d.density, range(1, 100000), "density, kg/m³ (water 1025)");
    v.field("yaw_deg", d.yaw_deg, range(-360, 360), "start turn about +y, deg");
    v.field("fixed", d.fixed, "never moves (a wall, a pier, a post); obstructs the ripples where it cuts the surface");
}

/// [[objects]] type "ship": a box hull driven by a pilot (the player or its waypoints).
struct ShipDef {
    glm::vec3 velocity{0.0f};           ///< start velocity, m/s
    float density = 500.0f;             ///< kg/m³ of the hull box, [1, 100000]: its draft is depth × density / water's
    glm::vec3 hull{3.0f, 1.5f, 10.0f};  ///< hull box: beam x, depth y, length z (bow +z), m, [0.1, 1000]; a model is scaled from this default
    /// The centre of mass's height above the keel, a fraction of the depth, [0, 1]: 0.5 a uniform
    /// box; 0.2 (KG = 0.3 m) a ballasted hull, whose righting arm stays positive to about 125°.
    float cg_height = 0.2f;
    bool player = false;                ///< steered with W/S (throttle) A/D (rudder)
    float yaw_deg = 0.0f;               ///< start heading, deg about +y, 0 faces +z, 90 faces +x, [-360, 360]
    float speed = 5.0f;                 ///< cruise (scripted) or top (player) speed, m/s, [0, 100]
    std::vector<glm::vec2> waypoints;   ///< scripted: [x, z] points visited in order, looping (none: holds its heading)
};

template <class V> void describe(V& v, ShipDef& d) {
    v.field("velocity", d.velocity, any(), "start velocity, m/s");
    v.field("density", d.density, range(1, 100000), "hull density, kg/m³ (draft = depth × density / water's)");
    v.field("hull", d.hull, range(0.1, 1000), "hull beam, depth, length, m (a model is scaled from 3 × 1.5 × 10)");
    v.field("cg_height", d.cg_height, range(0, 1), "centre of mass above the keel, fraction of the depth (ballast)");
    v.field("player", d.player, "W/S throttle, A/D rudder");
    v.field("yaw_deg", d.yaw_deg, range(-360, 360), "heading, deg about +y (0 faces +z)");
    v.field("speed", d.speed, range(0, 100), "cruise or top speed, m/s");
    v.field("waypoints", d.waypoints, any(), "scripted: [[x, z], ...] visited in order, looping, m");
}

/// [[objects]] type "cannon": fires iron balls ([Kang2008] §V-1).
struct CannonDef {
    bool player = false;          ///< aimed with the arrows, fires with Space
    float yaw_deg = 0.0f;         ///< aim azimuth, deg about +y, 0 faces +z, 90 faces +x, [-360, 360]
    float elevation_deg = 30.0f;  ///< barrel above the horizon, deg, [-10, 89]
    float muzzle_speed = 25.0f;   ///< ball speed leaving the barrel, m/s, [1, 1000]
    float rate = 0.0f;            ///< shots per second on its own, [0, 100] (0: only on events and the fire key)
    float ball_radius = 0.25f;    ///< cannonball radius, m, [0.01, 10]
    float ball_density = 7800.0f; ///< cannonball density, kg/m³ (iron), [1, 100000]
    float sink_depth = 15.0f;     ///< a ball this far under the mean surface is removed, m, [0.1, 10000]
};

template <class V> void describe(V& v, CannonDef& d) {
    v.field("player", d.player, "arrows aim, Space fires");
    v.field("yaw_deg", d.yaw_deg, range(-360, 360), "aim azimuth, deg about +y (0 faces +z)");
    v.field("elevation_deg", d.elevation_deg, range(-10, 89), "barrel elevation, deg");
    v.field("muzzle_speed", d.muzzle_speed, range(1, 1000), "muzzle speed, m/s");
    v.field("rate", d.rate, range(0, 100), "shots per second on its own (0: events and the fire key only)");
    v.field("ball_radius", d.ball_radius, range(0.01, 10), "cannonball radius, m");
    v.field("ball_density", d.ball_density, range(1, 100000), "cannonball density, kg/m³");
    v.field("sink_depth", d.sink_depth, range(0.1, 10000), "balls deeper than this are removed, m");
}

/// [[objects]] type "fish_school": fish swimming and jumping ([Kang2008] §V-2).
struct FishSchoolDef {
    float radius = 0.5f;                      ///< "circle": radius of its circle, m, [0.01, 10000]
    glm::vec3 size{1.0f, 1.0f, 1.0f};         ///< "region": [x, _, z] extent, m, [0.01, 10000]
    float speed = 5.0f;                       ///< swimming speed, m/s, [0, 100]
    int count = 10;                           ///< number of fish, [1, 1000000]
    SchoolShape shape = SchoolShape::Circle;  ///< swim on a "circle" (radius) or inside a "region" (size)
    float depth = 1.5f;                       ///< swimming depth below the mean surface, m, [0, 1000]
    float jump_height = 1.0f;                 ///< apex of a jump above the mean surface, m, [0, 100]
    float jump_interval = 3.0f;               ///< mean time between one fish's jumps, s, [0.1, 1e6]
    float length = 0.6f;                      ///< body length of a fish, m, [0.01, 100]
    bool draw = true;                         ///< draw the fish (false: spheres only, as the paper's sweep)
};

template <class V> void describe(V& v, FishSchoolDef& d) {
    v.field("radius", d.radius, range(0.01, 10000), "circle radius, m");
    v.field("size", d.size, range(0.01, 10000), "region: [x, _, z] extent, m");
    v.field("speed", d.speed, range(0, 100), "swimming speed, m/s");
    v.field("count", d.count, range(1, 1000000), "number of fish");
    v.field("shape", d.shape, "swim on a circle (radius) or in a region (size)");
    v.field("depth", d.depth, range(0, 1000), "swimming depth, m");
    v.field("jump_height", d.jump_height, range(0, 100), "jump apex above the mean surface, m");
    v.field("jump_interval", d.jump_interval, range(0.1, 1e6), "mean time between a fish's jumps, s");
    v.field("length", d.length, range(0.01, 100), "fish body length, m");
    v.field("draw", d.draw, "draw the fish (false: spheres only)");
}

/// One [[objects]] entry: the keys every type reads, and the settings of its type (only that
/// struct's keys are read; another type's key is an error naming the type).
struct ObjectDef {
    ObjectType type = ObjectType::Sphere; ///< "sphere", "box", "ship", "cannon" or "fish_school"
    std::string name;                     ///< the name events and the follow camera use ("" = none)
    glm::vec3 position{0.0f, 2.0f, 0.0f}; ///< start centre, world m (fish_school: centre of its water, y ignored)
    glm::vec3 color{0.75f, 0.32f, 0.18f}; ///< base colour, linear RGB
    std::string model;                    ///< glTF 2.0 file drawn instead of the built-in mesh ("" = built-in)
    // --- bounding spheres ([Kang2008] §V)
    SphereValues spheres = SphereValues::Paper; ///< "paper": the type's values from [Kang2008] §V; "custom": the three keys below
    float sphere_cells = 5.0f;            ///< custom: SR, sphere radius in ripple cells, [0.1, 512]
    float sphere_height_ratio = 1.0f;     ///< custom: SHR, [0.01, 100]
    float sphere_af = 0.0f;               ///< custom: AF (eq. 7), [-0.99, 10]
    // --- the type's own keys
    SphereBodyDef sphere;
    BoxBodyDef box;
    ShipDef ship;
    CannonDef cannon;
    FishSchoolDef school;
};

/// The keys of the types other than `type` that `type` does not read, each with the error a
/// file that sets it gets ("a cannon has no 'density' (it reads ...)").
std::vector<std::pair<std::string, std::string>> keysNotReadBy(ObjectType type);

template <class V> void describe(V& v, ObjectDef& d) {
    v.field("type", d.type, "what the object is");
    v.field("name", d.name, "name used by events and the follow camera");
    v.field("position", d.position, any(), "start centre, world m (fish_school: centre, y ignored)");
    v.field("color", d.color, range(0, 1), "base colour (linear RGB)");
    v.field("model", d.model, "glTF 2.0 file (.gltf/.glb) drawn instead of the built-in mesh");
    v.field("spheres", d.spheres, "bounding spheres: [Kang2008]'s values for the type, or custom");
    v.field("sphere_cells", d.sphere_cells, range(0.1, 512), "custom spheres: SR, radius in ripple cells");
    v.field("sphere_height_ratio", d.sphere_height_ratio, range(0.01, 100), "custom spheres: SHR");
    v.field("sphere_af", d.sphere_af, range(-0.99, 10), "custom spheres: AF (eq. 7)");
    switch (d.type) {  // a reader has read `type` by now
    case ObjectType::Sphere: v.fields(d.sphere); break;
    case ObjectType::Box: v.fields(d.box); break;
    case ObjectType::Ship: v.fields(d.ship); break;
    case ObjectType::Cannon: v.fields(d.cannon); break;
    case ObjectType::FishSchool: v.fields(d.school); break;
    }
    if constexpr (requires { v.refuse("", std::string()); })
        for (const auto& [key, why] : keysNotReadBy(d.type)) v.refuse(key.c_str(), why);
}

/// What kind of object an entity is, and its scene name (every spawned object has one).
struct ObjectTag {
    ObjectType type = ObjectType::Sphere;  ///< the [[objects]] type (a cannon's ball: Sphere, with a Cannonball)
    std::string name;                      ///< "" = unnamed
};

/// A probe sphere in the body's frame: where the water pushes (buoyancy, drag).
struct Probe {
    glm::vec3 offset{0.0f};  ///< m
    float radius = 0.5f;     ///< m
};

/// A force a behaviour adds for the next physics step.
struct AppliedForce {
    glm::vec3 force{0.0f};  ///< N, world
    glm::vec3 point{0.0f};  ///< world point of application, m
    /// True: the water's on the body (a hull's resistance, keel, propeller thrust): its opposite
    /// goes into the current layer. False: from outside the water (a hand, a mooring line).
    bool water = false;
};

/// A horizontal impulse a body put into the water this step (the opposite of what the water
/// did to it: Newton's third law), for the current layer to take (sim/currents_system).
struct WaterImpulse {
    glm::vec2 at{0.0f};       ///< world (x, z), m
    glm::vec2 impulse{0.0f};  ///< N·s
    float radius = 0.5f;      ///< m, the footprint it spreads over
};

/// The step's impulses into the water (a resource: the physics adds, the current layer takes).
struct WaterImpulses {
    std::vector<WaterImpulse> items;
    /// Adds −force·dt at `at` (the reaction of a horizontal water force on a body).
    void react(glm::vec3 force, glm::vec3 at, float dt, float radius) {
        if (force.x != 0.0f || force.z != 0.0f) items.push_back({{at.x, at.z}, -dt * glm::vec2(force.x, force.z), radius});
    }
};

/// A simulated body: its Bullet id, its probes, and what the water did last step.
struct Body {  // what it is: the entity's ObjectTag
    physics::BodyId id = physics::BodyId::None;
    std::vector<Probe> probes;
    float volume = 0.0f;             ///< m³ of the solid
    float submergedFraction = 0.0f;  ///< of the probes' volume under the surface, last step
    float horizontalDrag = 1.0f;     ///< scale of the probes' drag on horizontal motion (ships: 0, the hull model resists)
    glm::vec3 waveVelocity{0.0f};    ///< the waves' orbital velocity averaged over the wet probes, last step, m/s (no
                                     ///< current, no ripples: a hull model adds the current it sails in, see ship.cpp)
    std::vector<glm::vec3> probeWater;  ///< each probe's water velocity last step, m/s (its rate is the water's Du/Dt)
    /// A hull's box: its buoyancy from its columns (physics::hullBuoyancy), its probes carrying
    /// the rest (drag, the water's acceleration, added mass); none: the probes carry it all.
    std::optional<physics::HullGrid> hull;
    /// Where its mass's centre is in its frame, m (a ship's ballast: below the hull box's centre);
    /// Bullet turns the body about the box's centre, so gravity there makes the couple it lacks.
    glm::vec3 massCentre{0.0f};
    glm::vec3 angularVelocity{0.0f}; ///< rad/s, world, after the last step
    std::vector<AppliedForce> forces;  ///< behaviour forces for the next step (cleared by the step)
};

/// A body that obstructs the ripple layer where it cuts the mean water plane (y = 0): its
/// footprint there (interaction/obstruction.h), from its pose each step (sim/obstacles.h).
struct Obstacle {
    enum class Shape : uint8_t {
        Box,     ///< a box of half extents `half` (fixed boxes, walls, the cannon's pillar)
        Sphere,  ///< a sphere of radius half.x: the disc where it cuts the plane
        Hull,    ///< a hull box of half extents `half` (beam, depth, length): its waterplane, an ellipse
    };
    Shape shape = Shape::Box;
    glm::vec3 half{0.5f};  ///< m, in the body's frame
    float hollow = 0.0f;   ///< Hull: depth of its hollow in the ripple layer, m, >= 0 (the pressure head of its keel spheres)
};

/// How an object looks: mesh, scale (unit mesh → object), colour.
struct Renderable {
    gfx::MeshKind mesh = gfx::MeshKind::Sphere;
    glm::vec3 scale{1.0f};
    glm::vec3 color{0.8f};
    std::string model;    ///< glTF file replacing `mesh` ("" = built-in)
    glm::vec3 modelTint{1.0f};  ///< multiplies a model's own colours (1: as modelled; a goal's state is the view's, view/goal_looks.h)
};

/// A lattice of counts.x × counts.y × counts.z equal probe spheres at the cell centres of a
/// box of `size` (m, centred on the origin) whose volumes sum to the box's.
std::vector<Probe> latticeProbes(glm::vec3 size, glm::ivec3 counts);
/// Where the simulation reads [physics] (a resource): the world's scene section itself
/// (world/scene_settings.h), so a live change is read in place; the layers below the world
/// cannot name the scene, so they hold its section's address. spawnObjects sets it.
struct PhysicsSettings {
    const physics::PhysicsDef* def = nullptr;  ///< lives as long as the world
};
/// The scene's [physics] (gravity, water density, drag), set by spawnObjects before any object
/// is spawned. Throws std::logic_error before that.
const physics::PhysicsDef& physicsDef(ecs::World& world);
/// As physicsDef, or null before spawnObjects.
const physics::PhysicsDef* findPhysicsDef(ecs::World& world);
/// The ripple patch's cell size (m), or the [ripples] default when there is no patch: the
/// unit of the custom sphere_cells key (every other sphere is sized in metres).
float rippleCellSize(ecs::World& world);
/// The bounding sphere of an object's "custom" keys, or `paper` (sized in metres) when
/// spheres = "paper"; a custom radius in metres from its SR cells of `cellSize` m.
interaction::BoundingSphere boundingSphereFor(const ObjectDef& def, const interaction::BoundingSphere& paper, float cellSize);

/// Creates a sphere or a box (def.type) in a world that has the physics resource: a floating
/// body whose bounding sphere is the body itself. Spawning any type: sim/spawning.h.
ecs::Entity spawnFloatingBody(ecs::World& world, const ObjectDef& def, uint64_t seed);
/// Creates a floating Bullet body entity (Transform, Motion, Body, Renderable, ObjectTag);
/// the caller adds its SphereSet. `probes` in the body frame; mass in kg.
ecs::Entity spawnBody(ecs::World& world, ObjectType type, const std::string& name, physics::BodyId id,
                      std::vector<Probe> probes, float volume, float mass, const physics::BodyState& start,
                      const Renderable& look);
/// Removes a body entity and its Bullet body.
void destroyBody(ecs::World& world, ecs::Entity e);
/// The first entity whose ObjectTag name is `name` (None if there is none).
ecs::Entity findObject(ecs::World& world, const std::string& name);
/// Physics phase: water forces on every probe and the behaviours' forces, the Bullet step,
/// poses back to the entities.
void physicsSystem(ecs::World& world, const ecs::Tick& tick);
/// What the opaque pass draws this frame; `highlighted`'s draw is lit up. Each body `alpha`
/// of the way through the latest step (sim/step_poses.h; 1: where the step left it);
/// `restyle`, when given, recolours a draw (the view's reading of goal state).
std::vector<gfx::ObjectDraw> objectDraws(ecs::World& world, ecs::Entity highlighted = ecs::Entity::None, float alpha = 1.0f,
                                         const std::function<void(ecs::Entity, gfx::ObjectDraw&)>& restyle = {});
/// Roll and pitch (deg) of a rotation for a body whose bow is local +z and deck local +y:
/// pitch = bow above the horizon, roll = about the bow axis, + when local +x rises.
glm::vec2 rollPitchDeg(const glm::quat& rotation);

} // namespace ob::game
