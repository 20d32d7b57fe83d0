// Cannons and cannonballs ([Kang2008] §V-1): a cannon aims (yaw, elevation) and fires Bullet
// spheres; each ball carries the paper's bounding sphere (SR 5 cells, SHR 1, AF 0), splashes,
// sinks, and is removed below its cannon's sink depth.
#pragma once
#include <string>
#include "ecs/schedule.h"
#include "interaction/sphere_stamp.h"
#include "sim/objects.h"
#include "sim/stamp_sources.h"

namespace ob::game {

/// A cannon: its [[objects]] settings as written, and the state they start (its entity's
/// Transform is the barrel's pivot and aim).
struct Cannon {
    CannonDef def;                ///< the scene's settings (muzzle speed, rate, balls, the start aim)
    float yawDeg = 0.0f;          ///< aim azimuth now, deg about +y, 0 faces +z (starts at def.yaw_deg)
    float elevationDeg = 30.0f;   ///< barrel above the horizon now, deg (starts at def.elevation_deg)
    interaction::BoundingSphere ballSphere;  ///< every ball's bounding sphere
    std::string ballModel;        ///< every ball's model (the project's cannonball; "" = built-in sphere)
    double cooldown = 0.0;        ///< s until the next automatic shot
    bool fireRequested = false;   ///< fire this step (events, keys)
    int shots = 0;                ///< balls fired so far
};

/// Marks a cannonball entity (a Body with a SphereSet).
struct Cannonball {
    float sinkDepth = 15.0f;  ///< removed below −sinkDepth, m
};

/// Length of a cannon's barrel (m): balls leave from the pivot plus this along the aim.
constexpr float CANNON_BARREL = 2.0f;

/// Creates a cannon (and its pillar) from its [[objects]] entry (type "cannon").
ecs::Entity spawnCannon(ecs::World& world, const ObjectDef& def);
/// The barrel's elevation range, deg: its key's (CannonDef's elevation_deg).
Limits cannonElevationLimits();
/// `deg` kept within the barrel's elevation range.
float clampElevationDeg(float deg);
/// Unit aim direction for an azimuth and elevation (deg).
glm::vec3 cannonAim(float yawDeg, float elevationDeg);
/// Script phase: sunk balls are removed, cannons aim (player), then fire when asked or due.
void cannonSystem(ecs::World& world, const ecs::Tick& tick);
/// The cannons as a stamp source: their balls, once fired, are bodies (bodySource); a cannon
/// counts its ball's stamp from the start.
StampSource cannonSource();

} // namespace ob::game
