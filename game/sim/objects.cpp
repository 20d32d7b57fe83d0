// Floating bodies: spheres and boxes, water forces (Archimedes + drag per probe), Bullet stepping.
#include "sim/objects.h"
#include "sim/step_poses.h"

#include "ecs/components.h"
#include "currents/current_layer.h"
#include "interaction/ripple_def.h"
#include "interaction/ripple_patch.h"
#include "interaction/sphere_set.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace ob::game {

std::vector<Probe> latticeProbes(glm::vec3 size, glm::ivec3 counts) {
    const int n = counts.x * counts.y * counts.z;
    const float volume = size.x * size.y * size.z;
    const float r = std::cbrt(volume / (float(n) * 4.0f / 3.0f * float(M_PI)));
    std::vector<Probe> probes;
    probes.reserve(size_t(n));
    const glm::vec3 cell = size / glm::vec3(counts);
    for (int i = 0; i < counts.x; ++i)
        for (int j = 0; j < counts.y; ++j)
            for (int k = 0; k < counts.z; ++k)
                probes.push_back({(glm::vec3(i, j, k) + 0.5f) * cell - 0.5f * size, r});
    return probes;
}

// Probes with the solid's volume: a sphere is its own probe (exact Archimedes); a box is
// a 3×3×3 lattice.
static std::vector<Probe> probesFor(const ObjectDef& o) {
    if (o.type == ObjectType::Sphere) return {Probe{glm::vec3(0.0f), o.sphere.radius}};
    return latticeProbes(o.box.size, glm::ivec3(3));
}

namespace {

// The keys a describe() visits, in order.
struct DefKeyLister {
    std::vector<std::string> keys;
    template <class T, class... Rest> void field(const char* key, T&, Rest&&...) { keys.push_back(key); }
};

template <class Def> std::vector<std::string> defKeysOf() {
    DefKeyLister lister;
    Def def;
    describe(lister, def);
    return lister.keys;
}

} // namespace

std::vector<std::pair<std::string, std::string>> keysNotReadBy(ObjectType type) {
    const std::vector<std::string> typeKeys[] = {defKeysOf<SphereBodyDef>(), defKeysOf<BoxBodyDef>(), defKeysOf<ShipDef>(),
                                                 defKeysOf<CannonDef>(), defKeysOf<FishSchoolDef>()};
    static_assert(std::size(typeKeys) == enumNames<ObjectType>.size(), "one settings struct per object type");
    const std::vector<std::string>& own = typeKeys[size_t(type)];
    std::string reads;
    for (const std::string& k : own) reads += (reads.empty() ? "" : ", ") + k;
    std::vector<std::pair<std::string, std::string>> refused;
    for (const std::vector<std::string>& keys : typeKeys)
        for (const std::string& key : keys) {
            const auto same = [&](const auto& r) { return r.first == key; };
            if (std::find(own.begin(), own.end(), key) != own.end() || std::any_of(refused.begin(), refused.end(), same)) continue;
            refused.push_back({key, std::string("a ") + enumName(type) + " has no '" + key + "' (it reads " + reads +
                                        " besides type, name, position, color, model and the bounding sphere's keys)"});
        }
    return refused;
}

const physics::PhysicsDef* findPhysicsDef(ecs::World& world) {
    const auto* settings = world.resource<PhysicsSettings>();
    return settings ? settings->def : nullptr;
}

const physics::PhysicsDef& physicsDef(ecs::World& world) {
    const physics::PhysicsDef* def = findPhysicsDef(world);
    if (!def) throw std::logic_error("an object spawned before spawnObjects set [physics]");
    return *def;
}

float rippleCellSize(ecs::World& world) {
    if (const auto* patch = world.resource<interaction::RipplePatch>()) return patch->def().cell_size;
    return interaction::RippleDef{}.cell_size;
}

interaction::BoundingSphere boundingSphereFor(const ObjectDef& o, const interaction::BoundingSphere& paper, float cellSize) {
    if (o.spheres != SphereValues::Custom) return paper;
    interaction::BoundingSphere s = paper;
    s.radius = o.sphere_cells * cellSize;
    s.heightRatio = o.sphere_height_ratio;
    s.accelerationFactor = o.sphere_af;
    s.afFromMotion = false;
    return s;
}

ecs::Entity spawnBody(ecs::World& world, ObjectType type, const std::string& name, physics::BodyId id,
                      std::vector<Probe> probes, float volume, float mass, const physics::BodyState& start,
                      const Renderable& look) {
    ecs::Entity e = world.create();
    world.add<ecs::Transform>(e, {start.position, start.rotation});
    world.add<ecs::Motion>(e, {start.linearVelocity, mass});
    Body body;
    body.id = id;
    body.probes = std::move(probes);
    body.volume = volume;
    world.add<Body>(e, std::move(body));
    world.add<Renderable>(e, look);
    world.add<ObjectTag>(e, {type, name});
    return e;
}

void destroyBody(ecs::World& world, ecs::Entity e) {
    if (const Body* body = world.find<Body>(e))
        if (auto* physicsWorld = world.resource<physics::PhysicsWorld>()) physicsWorld->remove(body->id);
    world.destroy(e);
}

ecs::Entity findObject(ecs::World& world, const std::string& name) {
    if (name.empty()) return ecs::Entity::None;
    auto& tags = world.pool<ObjectTag>();
    for (size_t i = 0; i < tags.size(); ++i)
        if (tags.components()[i].name == name) return tags.entities()[i];
    return ecs::Entity::None;
}

// A sphere or a box: a floating body whose bounding sphere is the body itself (the paper's
// cannonball: SHR 1, AF 0, SD −1: it pushes the water down). A fixed one is a static Bullet
// body (mass 0: balls bounce off it) with no probes and no bounding sphere: it obstructs the
// ripples instead of pushing them (Obstacle).
ecs::Entity spawnFloatingBody(ecs::World& world, const ObjectDef& o, uint64_t /*seed*/) {
    auto& physicsWorld = *world.resource<physics::PhysicsWorld>();
    const bool sphere = o.type == ObjectType::Sphere;
    const bool fixed = sphere ? o.sphere.fixed : o.box.fixed;
    const float radius = o.sphere.radius;
    const glm::vec3 size = o.box.size;
    float volume = sphere ? 4.0f / 3.0f * float(M_PI) * radius * radius * radius : size.x * size.y * size.z;
    float mass = fixed ? 0.0f : (sphere ? o.sphere.density : o.box.density) * volume;
    physics::BodyState start;
    start.position = o.position;
    if (!sphere && o.box.yaw_deg != 0.0f) start.rotation = glm::angleAxis(glm::radians(o.box.yaw_deg), glm::vec3(0, 1, 0));
    if (!fixed) start.linearVelocity = sphere ? o.sphere.velocity : o.box.velocity;
    physics::BodyId id = sphere ? physicsWorld.addSphere(radius, mass, start) : physicsWorld.addBox(size * 0.5f, mass, start);
    // Built-in meshes and models alike are unit shapes, [−1, 1]³ or of radius 1 (the props of
    // tools/model_props.cpp): the body's size stretches them.
    Renderable look{sphere ? gfx::MeshKind::Sphere : gfx::MeshKind::Box, sphere ? glm::vec3(radius) : size * 0.5f, o.color, o.model};
    ecs::Entity e = spawnBody(world, o.type, o.name, id, fixed ? std::vector<Probe>{} : probesFor(o), volume, mass, start, look);
    if (fixed) {
        world.add<Obstacle>(e, {sphere ? Obstacle::Shape::Sphere : Obstacle::Shape::Box, sphere ? glm::vec3(radius) : size * 0.5f});
        return e;
    }
    interaction::BoundingSphere paper;
    paper.radius = sphere ? radius : 0.5f * std::min({size.x, size.y, size.z});
    paper.direction = interaction::SphereDirection::Down;  // a floating body pushes the water down
    paper.heightRatio = 1.0f;
    paper.accelerationFactor = 0.0f;
    world.add<interaction::SphereSet>(e, {{boundingSphereFor(o, paper, rippleCellSize(world))}, {}, false});
    return e;
}

// The ripples round a body: the patch averaged on a ring just outside the body's own
// footprint. A body sees the waves of others arriving (a ship rocks in another's wake) but not
// the crater it stamps itself, which would feed its buoyancy back into its stamps. Level (m) and
// horizontal velocity (m/s); their vertical velocity is left out for the same reason: between a
// stamp and the next step the cells near a body always move, which is no motion of the water.
struct RippleRing {
    float level = 0.0f;
    glm::vec2 velocity{0.0f};
};
static RippleRing rippleAround(const interaction::RipplePatch& patch, glm::vec2 xz, float radius) {
    const float ring = radius + 2.0f * patch.def().cell_size;
    RippleRing sum;
    for (int k = 0; k < 8; ++k) {
        const float a = float(k) * float(M_PI) / 4.0f;
        const glm::vec2 p = xz + ring * glm::vec2(std::cos(a), std::sin(a));
        sum.level += patch.heightAt(p) / 8.0f;
        sum.velocity += patch.horizontalVelocityAt(p) / 8.0f;
    }
    return sum;
}

// The wind at a height above the sea (m) from the wind at 10 m: the neutral log profile
// U(z) = U10·ln(z/z0)/ln(10/z0), sea roughness z0 = 2e-4 m (Charnock's over a wind sea), z ≥ 0.1 m.
static float windProfile(float height) {
    constexpr float Z0 = 2e-4f;
    return std::log(std::max(height, 0.1f) / Z0) / std::log(10.0f / Z0);
}

namespace {

constexpr double MIN_FORCE_HZ = 60.0;  // the water's forces on bodies are recomputed at least this often
constexpr int MAX_SUBSTEPS = 64;       // and at most this many times a step

// What every body's water forces read this step.
struct WaterContext {
    const physics::PhysicsDef& def;
    const water::WaterQuery& water;
    const interaction::RipplePatch* patch;
    const currents::CurrentLayer* layer;
    glm::vec3 wind10;  // the wind 10 m up, m/s
    float dt;
};

// A hull's hydrostatic buoyancy from its columns (buoyancy.h), over the water at its nodes: the
// sea without the ripples, read at the hull's still-water line, plus the ripples round each node
// (as for the probes: not the hull's own crater).
physics::ProbeForce hullForce(const WaterContext& c, const physics::HullGrid& hull, const physics::BodyState& s, float mass,
                              float reach, glm::vec3 waves) {
    const float draft = hull.size.y * std::clamp(mass / (c.def.water_density * hull.size.x * hull.size.y * hull.size.z), 0.0f, 1.0f);
    const water::WaterLayers sea{.ripples = false, .currents = false, .orbital = true};
    std::vector<float> heights(size_t(hull.nodeCount()));
    for (int n = 0; n < hull.nodeCount(); ++n) {
        const glm::vec2 q = hull.node(n);
        const glm::vec3 at = s.position + s.rotation * glm::vec3(q.x, draft - 0.5f * hull.size.y, q.y);
        heights[size_t(n)] = c.water.sample(at.x, at.z, sea).height;
        if (c.patch) heights[size_t(n)] += rippleAround(*c.patch, {at.x, at.z}, reach).level;
    }
    const physics::HullBuoyancy b = physics::hullBuoyancy(c.def, hull, s.position, s.rotation, heights);
    physics::ProbeForce f;
    f.force = b.force;
    f.point = b.point;
    // Its heave stiffness ρ·g·(waterplane) while the waterline is on its sides, taken implicitly
    // toward the waves' vertical motion (buoyancy.h: implicitDamping).
    if (b.volume > 0.0f && b.volume < hull.size.x * hull.size.y * hull.size.z) {
        const float k = c.def.water_density * c.def.gravity * hull.size.x * hull.size.z;
        f.damping = glm::vec3(0.0f, k * c.dt, 0.0f);
        f.dampingTarget = glm::vec3(0.0f, k * c.dt * waves.y, 0.0f);
    }
    return f;
}

// The water a body drags along: its probes' added mass (kg) and its inertia tensor about the
// body's centre (kg·m², world: Σ m_a·(|r|²·1 − r·rᵀ) for the motion the probes' drag sees; a
// ship's probes see only the vertical, so its yaw keeps its hull model's inertia).
struct AddedInertia {
    float mass = 0.0f;
    glm::mat3 moment{0.0f};
};

glm::mat3 addedMoment(glm::vec3 r, float mass, float horizontal) {
    const glm::mat3 all = glm::dot(r, r) * glm::mat3(1.0f) - glm::outerProduct(r, r);
    const glm::mat3 vertical(r.z * r.z, 0.0f, -r.x * r.z, 0.0f, 0.0f, 0.0f, -r.x * r.z, 0.0f, r.x * r.x);  // (ω × r)·ŷ's share
    return mass * (horizontal * all + (1.0f - horizontal) * vertical);
}

// Morison's forces on each of a body's probes (buoyancy.h) into `forces`; sets the body's
// submerged fraction, the waves' velocity round it and each probe's water velocity (for the
// next step's Du/Dt). Returns the probes' added inertia.
AddedInertia probeForces(const WaterContext& c, ecs::World& world, ecs::Entity entity, Body& body, const physics::BodyState& s,
                  float reach, std::vector<physics::ProbeForce>& forces) {
    const float mass = world.get<ecs::Motion>(entity).mass;
    const bool fresh = body.probeWater.size() != body.probes.size();  // a new body: no rate yet
    const Obstacle* obstacle = world.find<Obstacle>(entity);
    const bool displaces = obstacle && obstacle->shape == Obstacle::Shape::Hull;  // a hull (a displacer of the current layer)
    body.probeWater.resize(body.probes.size(), glm::vec3(0.0f));
    float probeVolume = 0.0f;
    for (const Probe& probe : body.probes) probeVolume += probe.radius * probe.radius * probe.radius;
    forces.clear();
    float submerged = 0.0f, wet = 0.0f;
    AddedInertia added;
    glm::vec3 waterSum(0.0f);
    for (size_t k = 0; k < body.probes.size(); ++k) {
        const Probe& probe = body.probes[k];
        physics::ProbeState p;
        p.centre = s.position + s.rotation * probe.offset;
        p.radius = probe.radius;
        p.velocity = s.linearVelocity + glm::cross(s.angularVelocity, p.centre - s.position);
        // The ocean and current without the ripples: their level and motion come from round
        // the body (below), not from the crater it stamps itself.
        const water::WaterLayers sea{.ripples = false, .currents = false, .orbital = true};
        const water::WaterSample w = c.water.sampleBelow(p.centre, sea);
        p.surfaceHeight = w.height;
        p.surfaceNormal = w.normal;
        const glm::vec3 waves = w.velocity;  // the waves' orbits at the centre: what a hull's model adds its current to
        p.waterVelocity = waves;
        // A hull reads the current through its hull model, ahead of its bow (ship.cpp): under it
        // the layer holds the flow its own forces make, which is no flow it sits in.
        if (c.layer && !displaces) {
            const glm::vec2 u = c.layer->velocityAt({p.centre.x, p.centre.z});
            p.waterVelocity += glm::vec3(u.x, 0.0f, u.y);
        }
        if (c.patch) {
            const RippleRing ripples = rippleAround(*c.patch, {p.centre.x, p.centre.z}, reach);
            p.surfaceHeight += ripples.level;
            // e^{kz}, z from the level the ripples ride on (an Eulerian layer: CompositeWater::velocityAt)
            const glm::vec2 u = ripples.velocity *
                                std::exp(c.patch->velocityWavenumber() * std::min(p.centre.y - w.height, ripples.level));
            p.waterVelocity += glm::vec3(u.x, 0.0f, u.y);
        }
        const glm::vec3 before = std::exchange(body.probeWater[k], p.waterVelocity);
        if (!fresh && c.dt > 0.0f) p.waterAcceleration = (p.waterVelocity - before) / c.dt;
        // The drag sees this much of the horizontal motion through the water (ships: none,
        // their hull model resists it), and the water's horizontal push likewise.
        p.velocity.x = p.waterVelocity.x + body.horizontalDrag * (p.velocity.x - p.waterVelocity.x);
        p.velocity.z = p.waterVelocity.z + body.horizontalDrag * (p.velocity.z - p.waterVelocity.z);
        p.horizontalInertia = body.horizontalDrag;
        p.hydrostatic = body.hull ? 0.0f : 1.0f;
        p.wind = c.wind10 * windProfile(p.centre.y + p.radius - p.surfaceHeight);
        const float v = probe.radius * probe.radius * probe.radius;
        p.dt = c.dt;
        const physics::ProbeForce f = physics::probeForce(c.def, p);
        forces.push_back(f);
        submerged += f.submergedFraction * v;
        added.mass += f.addedMass;
        added.moment += addedMoment(p.centre - s.position, f.addedMass, body.horizontalDrag);
        if (f.submergedFraction > 0.0f) {
            waterSum += waves * f.submergedFraction;
            wet += f.submergedFraction;
        }
    }
    body.submergedFraction = probeVolume > 0.0f ? submerged / probeVolume : 0.0f;
    if (body.submergedFraction == 0.0f)  // in flight: a ballistic body (windage is leeway, the drift of what floats)
        for (physics::ProbeForce& f : forces) {
            f.damping -= std::exchange(f.airDamping, glm::vec3(0.0f));
            f.dampingTarget -= std::exchange(f.airTarget, glm::vec3(0.0f));
        }
    body.waveVelocity = wet > 0.0f ? waterSum / wet : glm::vec3(0.0f);
    if (body.hull) forces.push_back(hullForce(c, *body.hull, s, mass, reach, body.waveVelocity));
    return added;
}

// A reaction on the current layer bounded implicitly, as the drag is on the body: within a step
// it can bring the layer's water under the probe (ρ·depth·π·r²) to the probe's own velocity, not
// past it (an extreme drag would otherwise throw the layer and the body against each other).
glm::vec3 layerBound(const WaterContext& c, const physics::BodyState& s, glm::vec3 point, float radius, glm::vec3 force) {
    if (!c.layer || c.dt <= 0.0f) return force;
    const glm::vec3 v = s.linearVelocity + glm::cross(s.angularVelocity, point - s.position);
    const glm::vec2 u = c.layer->velocityAt({point.x, point.z});
    const float mass = c.def.water_density * c.layer->def().depth * float(M_PI) * radius * radius;
    const float most = mass * glm::length(glm::vec2(v.x, v.z) - u) / c.dt;
    const float horizontal = glm::length(glm::vec2(force.x, force.z));
    return horizontal > most ? force * glm::vec3(most / horizontal, 1.0f, most / horizontal) : force;
}

// Applies the probes' and the behaviours' forces to a body with its added mass taken
// implicitly: with m_a = Σ ρ·C_a·V the body moves as if of mass m + m_a under every force
// (m·dv/dt = F − m_a·dv/dt), so its acceleration is s = m/(m + m_a) of the forces' and
// (1 − s)·m·g lifts it (Bullet pulls m·g; m_a is weightless water; Bullet keeps m). A light body
// (a ball of 1 kg/m³) then rises at (ρ/ρ_body − 1)·g/(1 + ρ·C_a/ρ_body) ≈ 2g, not at 1000 g.
// Every horizontal water force's reaction goes to the current layer's impulses.
void applyForces(const WaterContext& c, physics::PhysicsWorld& physicsWorld, Body& body, float mass, const physics::BodyState& s,
                 float reach, AddedInertia added, std::span<physics::ProbeForce> forces, WaterImpulses* impulses) {
    const float addedMass = added.mass;
    // Horizontally the added mass counts as much as the probes' drag does (ships: not at
    // all; their hull model, tuned on the hull's own surge and sway, stands in for it).
    const glm::vec3 scale(mass / (mass + body.horizontalDrag * addedMass), mass / (mass + addedMass),
                          mass / (mass + body.horizontalDrag * addedMass));
    // The water turning with the body resists every torque: its moment of inertia adds to the
    // body's (a light body's hydrostatic moments would otherwise turn it faster than any step
    // resolves); Bullet turns the body with its own, so the torque is scaled by I·(I + I_a)⁻¹.
    const glm::mat3 inertia = physicsWorld.inertiaTensor(body.id), effective = inertia + added.moment;
    const glm::mat3 turn = glm::determinant(effective) > 0.0f ? inertia * glm::inverse(effective) : glm::mat3(1.0f);
    if (mass > 0.0f && !forces.empty()) {
        // The drags and the buoyancy's stiffness at the end of the step (buoyancy.h: implicitDamping),
        // under every explicit force and torque of the step, gravity and the ballast's included.
        glm::vec3 force(0.0f, -mass * c.def.gravity, 0.0f), torque = glm::cross(s.rotation * body.massCentre, force);
        for (const physics::ProbeForce& f : forces) force += f.force, torque += glm::cross(f.point - s.position, f.force);
        for (const AppliedForce& f : body.forces) force += f.force, torque += glm::cross(f.point - s.position, f.force);
        const physics::BodyResponse response{mass / scale, effective, s.position, s.linearVelocity, s.angularVelocity};
        physics::implicitDamping(response, force, torque, c.dt, forces);
    }
    // The forces act whole at their points; the translation takes the scale through one force
    // at the centre, (s − 1)·ΣF, the rotation through one torque (below).
    glm::vec3 outside(0.0f), total(0.0f), torque(0.0f);  // outside: the forces from outside the water (air, hands, moorings)
    for (size_t k = 0; k < forces.size(); ++k) {
        const physics::ProbeForce& f = forces[k];
        physicsWorld.applyForce(body.id, f.force, f.point);
        total += f.force;
        torque += glm::cross(f.point - s.position, f.force);
        const float radius = k < body.probes.size() ? body.probes[k].radius : std::max(reach, 0.5f);  // past the probes: the hull's
        if (impulses) impulses->react(layerBound(c, s, f.point, radius, scale * (f.force - f.airForce)), f.point, c.dt, radius);
        outside += f.airForce;
    }
    for (const AppliedForce& f : body.forces) {
        physicsWorld.applyForce(body.id, f.force, f.point);
        total += f.force;
        torque += glm::cross(f.point - s.position, f.force);
        if (!f.water) outside += f.force;
        else if (impulses) impulses->react(scale * f.force, f.point, c.dt, std::max(reach, 0.5f));
    }
    body.forces.clear();
    if (body.massCentre != glm::vec3(0.0f)) {  // gravity's moment about the box's centre: a couple, no net force
        const glm::vec3 weight(0.0f, -mass * c.def.gravity, 0.0f);
        physicsWorld.applyForce(body.id, weight, s.position + s.rotation * body.massCentre);
        physicsWorld.applyForce(body.id, -weight, s.position);
        torque += glm::cross(s.rotation * body.massCentre, weight);
    }
    if (added.moment != glm::mat3(0.0f)) physicsWorld.applyTorque(body.id, turn * torque - torque);
    if (addedMass > 0.0f) {
        physicsWorld.applyForce(body.id, (scale - 1.0f) * total + glm::vec3(0.0f, (1.0f - scale.y) * mass * c.def.gravity, 0.0f),
                                s.position);
        // The added mass's reaction: the water the body drags along took (1 − s) of the outside forces.
        if (impulses) impulses->react((scale - 1.0f) * outside, s.position, c.dt, std::max(reach, 0.5f));
    }
    if (body.submergedFraction > 0.0f)
        physicsWorld.dampAngular(body.id, std::pow(1.0f - c.def.angular_damping, c.dt * body.submergedFraction));
}

} // namespace

// A body that reaches the surface this step faster than it crosses its own size in one step
// (a drop, a throw, a strong gravity) enters it over as many substeps as that takes: its probes
// feel the water on the way in rather than being found deep under it at the end of the step.
static int entrySubsteps(ecs::World& world, const water::WaterQuery& water, float dt) {
    int n = 1;
    auto& bodies = world.pool<Body>();
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Body& body = bodies.components()[i];
        if (body.probes.empty()) continue;
        float size = 0.0f;
        for (const Probe& p : body.probes) size = std::max(size, glm::length(p.offset) + p.radius);
        const ecs::Entity e = bodies.entities()[i];
        const glm::vec3 x = world.get<ecs::Transform>(e).position, v = world.get<ecs::Motion>(e).velocity;
        const float travel = glm::length(v) * dt;
        if (travel <= size) continue;
        const float gap = std::abs(x.y - water.sample(x.x, x.z, {.ripples = false, .orbital = true}).height);
        if (gap < size + travel) n = std::max(n, int(std::ceil(travel / size)));
    }
    return n;
}

void physicsSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* physicsWorld = world.resource<physics::PhysicsWorld>();
    const physics::PhysicsDef* def = findPhysicsDef(world);
    if (!physicsWorld) return;
    const water::WaterQuery* water = nullptr;
    glm::vec3 wind10(0.0f);
    if (OceanState* ocean = world.resource<OceanState>()) {
        water = ocean->water.get();
        const glm::vec2 d = ocean->def.wind_direction;
        if (glm::dot(d, d) > 0.0f) wind10 = ocean->def.wind_speed * glm::normalize(glm::vec3(d.x, 0.0f, d.y));
    }
    const water::FlatWater flat(0.0f);
    if (!water) water = &flat;
    // The water's forces are resolved at 60 Hz at least: a slower step (sim.step_hz down to 1) is
    // cut into substeps, each with its own probe forces, so a body cannot fall through the
    // surface or out of its wave within one step.
    const int substeps = std::clamp(std::max(int(std::ceil(tick.dt * MIN_FORCE_HZ - 1e-6)), entrySubsteps(world, *water, float(tick.dt))),
                                    1, MAX_SUBSTEPS);
    const float dt = float(tick.dt) / float(substeps);
    const WaterContext context{*def, *water, world.resource<interaction::RipplePatch>(), world.resource<currents::CurrentLayer>(),
                               wind10, dt};
    auto* impulses = world.resource<WaterImpulses>();
    auto& bodies = world.pool<Body>();
    std::vector<physics::ProbeForce> forces;
    std::vector<std::vector<AppliedForce>> behaviours(substeps > 1 ? bodies.size() : 0);  // each substep's again
    for (size_t b = 0; b < behaviours.size(); ++b) behaviours[b] = bodies.components()[b].forces;
    for (int sub = 0; sub < substeps; ++sub) {
        // --- water and air forces per probe (Morison: buoyancy.h), then the behaviours' forces
        for (size_t b = 0; b < bodies.size(); ++b) {
            Body& body = bodies.components()[b];
            const ecs::Entity entity = bodies.entities()[b];
            if (sub > 0) body.forces = behaviours[b];
            const auto* spheres = world.find<interaction::SphereSet>(entity);
            const float reach = spheres && !spheres->spheres.empty() ? spheres->spheres[0].radius : 0.0f;
            const physics::BodyState s = physicsWorld->state(body.id);
            const AddedInertia added = probeForces(context, world, entity, body, s, reach, forces);
            applyForces(context, *physicsWorld, body, world.get<ecs::Motion>(entity).mass, s, reach, added, forces, impulses);
        }
        // --- rigid-body step
        physicsWorld->step(dt);
    }

    // --- poses back to the entities
    for (size_t i = 0; i < bodies.size(); ++i) {
        ecs::Entity e = bodies.entities()[i];
        physics::BodyState s = physicsWorld->state(bodies.components()[i].id);
        ecs::Transform& t = world.get<ecs::Transform>(e);
        t.position = s.position;
        t.rotation = s.rotation;
        world.get<ecs::Motion>(e).velocity = s.linearVelocity;
        bodies.components()[i].angularVelocity = s.angularVelocity;
    }
}

std::vector<gfx::ObjectDraw> objectDraws(ecs::World& world, ecs::Entity highlighted, float alpha,
                                         const std::function<void(ecs::Entity, gfx::ObjectDraw&)>& restyle) {
    std::vector<gfx::ObjectDraw> draws;
    auto& renderables = world.pool<Renderable>();
    const StepPoses* poses = world.resource<StepPoses>();
    for (size_t i = 0; i < renderables.size(); ++i) {
        const Renderable& r = renderables.components()[i];
        const ecs::Transform* current = world.find<ecs::Transform>(renderables.entities()[i]);
        if (!current) continue;
        const ecs::Transform t = drawnTransform(poses, renderables.entities()[i], *current, alpha);
        glm::mat4 model = glm::translate(glm::mat4(1.0f), t.position) * glm::mat4_cast(t.rotation) * glm::scale(glm::mat4(1.0f), r.scale);
        gfx::ObjectDraw& d = draws.emplace_back(gfx::ObjectDraw{r.mesh, model, r.color, r.model});
        d.highlight = renderables.entities()[i] == highlighted;
        d.modelTint = r.modelTint;
        const Obstacle* obstacle = world.find<Obstacle>(renderables.entities()[i]);
        d.hull = obstacle && obstacle->shape == Obstacle::Shape::Hull;
        if (restyle) restyle(renderables.entities()[i], d);  // the view's reading of a goal's state
    }
    return draws;
}

glm::vec2 rollPitchDeg(const glm::quat& rotation) {
    const glm::vec3 right = rotation * glm::vec3(1, 0, 0), up = rotation * glm::vec3(0, 1, 0), bow = rotation * glm::vec3(0, 0, 1);
    float roll = std::atan2(right.y, up.y);
    float pitch = std::asin(std::clamp(bow.y, -1.0f, 1.0f));
    return glm::degrees(glm::vec2(roll, pitch));
}

} // namespace ob::game
