// Ship behaviour and hull model. The probes carry the ship (Archimedes and vertical drag);
// this file adds what a hull has and a lattice of spheres has not: low resistance along the
// keel, high across it, and thrust and a rudder at the stern.
#include "behaviours/ship.h"

#include "currents/current_layer.h"

#include "ecs/components.h"
#include "interaction/sphere_set.h"
#include "behaviours/step_input.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace ob::game {

namespace {

constexpr float COAST_TIME = 4.0f;     // s: at top speed, resistance decelerates by speed / COAST_TIME
constexpr float SPEED_TIME = 2.0f;     // s: the engine closes a speed error at this rate
constexpr float SLIP_TIME = 0.4f;      // s: sideways slip decays at this rate (the keel)
constexpr float YAW_TIME = 0.5f;       // s: the rudder closes a yaw-rate error at this rate
constexpr float ROLL_TIME = 1.0f;      // s: bilge keels damp the roll rate at this rate (damping ratio ≈ 0.25
                                       // at the hull's ≈ 3 s natural roll period, as bilge keels give)
constexpr float MAX_TURN = 0.21f;      // rad/s at full rudder and full speed (≈ 3 hull lengths radius at 6 m/s)
constexpr float ARRIVE_RADIUS = 5.0f;  // m: a waypoint this close counts as reached
constexpr float HEADING_GAIN = 1.0f;   // 1/s: yaw rate asked per radian of heading error
constexpr float THROTTLE_RATE = 0.5f;  // lever travel per second while W or S is held
constexpr glm::ivec3 PROBES{5, 3, 9};  // probe lattice across, up, along the hull

// Angle in (−π, π].
float wrapAngle(float a) {
    while (a > float(M_PI)) a -= 2.0f * float(M_PI);
    while (a <= -float(M_PI)) a += 2.0f * float(M_PI);
    return a;
}

// The paper's ship sphere ([Kang2008] §V-3): SHR 0.2, AF 0.3; it presses down. Its size is in
// metres ([Kang2008]'s SR 7 cells on the ship scene's 0.2 m cells), so the ripple cell size
// changes neither the wake's width in the world nor the foam it leaves.
constexpr float PAPER_SHIP_SPHERE_RADIUS = 1.4f;  // m

interaction::BoundingSphere paperShipSphere() {
    interaction::BoundingSphere s;
    s.radius = PAPER_SHIP_SPHERE_RADIUS;
    s.direction = interaction::SphereDirection::Down;
    s.heightRatio = 0.2f;
    s.accelerationFactor = 0.3f;
    return s;
}

} // namespace

float hullHollow(const interaction::BoundingSphere& keel) {
    return keel.heightRatio * keel.radius * std::max(0.0f, 1.0f + keel.accelerationFactor);
}

ecs::Entity spawnShip(ecs::World& world, const ObjectDef& o) {
    auto& physicsWorld = *world.resource<physics::PhysicsWorld>();
    const float volume = o.ship.hull.x * o.ship.hull.y * o.ship.hull.z;
    const float mass = o.ship.density * volume;
    physics::BodyState start;
    start.position = o.position;
    start.rotation = glm::angleAxis(glm::radians(o.ship.yaw_deg), glm::vec3(0, 1, 0));
    start.linearVelocity = o.ship.velocity;
    physics::BodyId id = physicsWorld.addBox(o.ship.hull * 0.5f, mass, start);
    // A model is in metres (the hull box is its hull); the built-in unit box is scaled to the hull.
    Renderable look{gfx::MeshKind::Box, o.model.empty() ? o.ship.hull * 0.5f : o.ship.hull / ShipDef{}.hull, o.color, o.model};
    ecs::Entity e = spawnBody(world, ObjectType::Ship, o.name, id, latticeProbes(o.ship.hull, PROBES), volume, mass, start, look);
    Body& body = world.get<Body>(e);
    body.horizontalDrag = 0.0f;  // the hull model below resists horizontal motion
    body.hull = physics::HullGrid{o.ship.hull};  // its buoyancy and righting moment from the hull's own waterplane
    body.massCentre = glm::vec3(0.0f, (o.ship.cg_height - 0.5f) * o.ship.hull.y, 0.0f);  // its ballast
    // Six spheres on the keel line at the still-water line (draft = hull depth · density ratio),
    // so they always cross the surface ([Kang2008]: "always in contact").
    const float draft = o.ship.hull.y * std::min(o.ship.density / physicsDef(world).water_density, 1.0f);
    interaction::BoundingSphere sphere = boundingSphereFor(o, paperShipSphere(), rippleCellSize(world));

    // The hull: the renderer clips the water out of it (gfx::HullClip), and with
    // ripples.hulls_obstruct (ewave) its waterplane holds the ripples' water at its hollow and
    // no source presses inside it (docs/ewave.md#hulls). The hollow is the
    // pressure head of its keel spheres, what they press on a free surface (hullHollow).
    world.add<Obstacle>(e, {Obstacle::Shape::Hull, o.ship.hull * 0.5f, hullHollow(sphere)});
    interaction::SphereSet set;
    set.hull = true;
    for (int k = 0; k < SHIP_SPHERES; ++k) {
        sphere.offset = glm::vec3(0.0f, draft - 0.5f * o.ship.hull.y, (float(k) + 0.5f) * o.ship.hull.z / SHIP_SPHERES - 0.5f * o.ship.hull.z);
        set.spheres.push_back(sphere);
    }
    world.add<interaction::SphereSet>(e, std::move(set));

    Ship ship;
    ship.def = o.ship;
    ship.speed = o.ship.speed;
    world.add<Ship>(e, std::move(ship));
    return e;
}

namespace {

// A hull's horizontal frame on the water plane and its motion in it.
struct HullFrame {
    glm::vec3 bow, starboard;  // unit, horizontal
    float heading;             // rad about +y, 0 along +z
    float forward, sideways;   // m/s along bow and starboard
};

// The pilot: the player's lever and rudder, or the heading to the next waypoint. Returns the
// speed the engine aims for (m/s).
float pilot(Ship& ship, const glm::vec3& position, float heading, const StepInput* input, float dt) {
    if (ship.def.player) {
        if (input && !input->keysMoveCamera) {
            using platform::Key;
            const int lever = int(input->isDown(Key::W)) - int(input->isDown(Key::S));
            ship.throttle += THROTTLE_RATE * dt * float(lever);
            if (lever == 0 && std::abs(ship.throttle) < 0.03f) ship.throttle = 0.0f;  // the lever's notch at stop
            ship.rudder = float(input->isDown(Key::D) - input->isDown(Key::A));
        }
        ship.throttle = std::clamp(ship.throttle, -0.5f, 1.0f);
        return ship.throttle * ship.speed;
    }
    if (!ship.def.waypoints.empty()) {
        glm::vec2 to = ship.def.waypoints[ship.nextWaypoint] - glm::vec2(position.x, position.z);
        if (glm::dot(to, to) < ARRIVE_RADIUS * ARRIVE_RADIUS) {
            ship.nextWaypoint = (ship.nextWaypoint + 1) % ship.def.waypoints.size();
            to = ship.def.waypoints[ship.nextWaypoint] - glm::vec2(position.x, position.z);
        }
        const float error = wrapAngle(std::atan2(to.x, to.y) - heading);  // + : turn toward +yaw (port)
        ship.rudder = std::clamp(-HEADING_GAIN * error / MAX_TURN, -1.0f, 1.0f);
    } else {
        ship.rudder = 0.0f;
    }
    return ship.speed;
}

// The hull model: engine, resistance, keel, rudder and bilge keels, as forces on the body,
// scaled by how much of the hull is in the water.
void hullForces(const Ship& ship, const ecs::Transform& t, const ecs::Motion& motion, Body& body, const HullFrame& f,
                float targetSpeed) {
    const float wet = std::clamp(body.submergedFraction / 0.2f, 0.0f, 1.0f);
    if (wet <= 0.0f) return;
    const float top = std::max(ship.speed, 0.5f);
    const float mass = motion.mass;
    const glm::vec3 stern = t.position + t.rotation * glm::vec3(0.0f, -0.25f * ship.def.hull.y, -0.5f * ship.def.hull.z);
    // Forward resistance m·u|u|/(top·COAST_TIME); the engine feeds that forward at the
    // target speed and closes the error in SPEED_TIME.
    const float resistance = mass * f.forward * std::abs(f.forward) / (top * COAST_TIME);
    const float maxThrust = mass * top / COAST_TIME;
    // The player's lever at zero idles the engine (the ship coasts); a scripted ship at
    // speed 0 holds its place (the paper's ship at rest).
    const bool idle = ship.def.player && ship.throttle == 0.0f;
    const float thrust = idle ? 0.0f
                              : std::clamp(mass * targetSpeed * std::abs(targetSpeed) / (top * COAST_TIME) +
                                               mass * (targetSpeed - f.forward) / SPEED_TIME,
                                           -0.5f * maxThrust, 1.5f * maxThrust);
    // The propeller works below the surface layer (under the keel): its jet is not the layer's,
    // so its reaction goes outside it; the hull's resistance, keel and rudder act on the layer.
    body.forces.push_back({f.bow * (thrust * wet), stern, false});
    body.forces.push_back({-f.bow * (resistance * wet), t.position, true});
    // The keel: sideways slip decays in SLIP_TIME.
    body.forces.push_back({-f.starboard * (mass * f.sideways / SLIP_TIME * wet), t.position, true});
    // The rudder: a sideways force at the stern whose moment brings the yaw rate to the
    // rudder's (which needs water flowing past it: it fades below half the top speed).
    const float yawInertia = mass * (ship.def.hull.z * ship.def.hull.z + ship.def.hull.x * ship.def.hull.x) / 12.0f;
    const float wantedYawRate = -ship.rudder * MAX_TURN * std::clamp(f.forward / (0.5f * top), -1.0f, 1.0f);
    const float moment = yawInertia * (wantedYawRate - body.angularVelocity.y) / YAW_TIME;
    // A force F·(bow × up) at the stern (arm L/2 behind the centre) turns about +y by F·L/2.
    body.forces.push_back({glm::cross(f.bow, glm::vec3(0, 1, 0)) * (moment / (0.5f * ship.def.hull.z) * wet), stern, true});
    // Bilge keels: a couple about the hull's long axis against the roll rate (vertical
    // forces ±F at the two sides, F·beam = moment).
    const glm::vec3 keel = t.rotation * glm::vec3(0, 0, 1), side = t.rotation * glm::vec3(1, 0, 0), deck = t.rotation * glm::vec3(0, 1, 0);
    const float rollInertia = mass * (ship.def.hull.x * ship.def.hull.x + ship.def.hull.y * ship.def.hull.y) / 12.0f;
    const float rollMoment = -rollInertia * glm::dot(body.angularVelocity, keel) / ROLL_TIME * wet;
    const glm::vec3 couple = deck * (rollMoment / ship.def.hull.x);
    body.forces.push_back({couple, t.position + side * (0.5f * ship.def.hull.x), true});
    body.forces.push_back({-couple, t.position - side * (0.5f * ship.def.hull.x), true});
}

} // namespace

void shipSystem(ecs::World& world, const ecs::Tick& tick) {
    auto& ships = world.pool<Ship>();
    const auto* input = world.resource<StepInput>();
    for (size_t i = 0; i < ships.size(); ++i) {
        Ship& ship = ships.components()[i];
        const ecs::Entity e = ships.entities()[i];
        const ecs::Transform& t = world.get<ecs::Transform>(e);
        const ecs::Motion& motion = world.get<ecs::Motion>(e);
        glm::vec3 bow = t.rotation * glm::vec3(0, 0, 1);
        bow.y = 0.0f;
        if (glm::dot(bow, bow) < 1e-6f) continue;  // standing on its end: no steering
        bow = glm::normalize(bow);
        const glm::vec3 starboard = glm::cross(bow, glm::vec3(0, 1, 0));
        // The hull moves through the water: its speed is the one relative to the waves' orbits
        // and the current it sails in, read two hull lengths ahead of the bow (the free stream:
        // under and near the hull the current is the one the hull itself drags and pushes, a
        // dipole of its resistance and its propeller's thrust, weaker as 1/r² away).
        glm::vec3 water = world.get<Body>(e).waveVelocity;
        if (const auto* layer = world.resource<currents::CurrentLayer>()) {
            const glm::vec3 ahead = t.position + bow * (2.0f * ship.def.hull.z);
            const glm::vec2 u = layer->flowAt({ahead.x, ahead.z});  // without the hulls' displacement flow
            water += glm::vec3(u.x, 0.0f, u.y);
        }
        const glm::vec3 through = motion.velocity - water;
        const HullFrame frame{bow, starboard, std::atan2(bow.x, bow.z), glm::dot(through, bow), glm::dot(through, starboard)};
        const float targetSpeed = pilot(ship, t.position, frame.heading, input, float(tick.dt));
        hullForces(ship, t, motion, world.get<Body>(e), frame, targetSpeed);
    }
}

} // namespace ob::game
