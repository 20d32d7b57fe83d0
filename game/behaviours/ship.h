// Ships: buoyant box hulls steered by thrust and a rudder at the stern, by the player
// (W/S throttle, A/D rudder) or along waypoints; six bounding spheres along the keel line
// make the wake ([Kang2008] §V-3: SR 7, SHR 0.2, AF 0.3).
#pragma once
#include "ecs/schedule.h"
#include "sim/objects.h"

#include <glm/vec3.hpp>
#include <vector>

namespace ob::game {

/// Bounding spheres along the hull ([Kang2008] fig. 15).
constexpr int SHIP_SPHERES = 6;

/// A ship: its [[objects]] settings as written, and the pilot's state.
struct Ship {
    ShipDef def;                       ///< the scene's settings (hull, player, waypoints, the speed it starts with)
    float speed = 5.0f;                ///< cruise (scripted) or top (player) speed now, m/s (starts at def.speed; set_speed changes it)
    size_t nextWaypoint = 0;           ///< index of def.waypoints steered to
    float throttle = 0.0f;             ///< player's lever: target speed = throttle · speed, [−0.5, 1]
    float rudder = 0.0f;               ///< [−1, 1], + turns to starboard (right)
};

/// The depth of a hull's hollow in the ewave ripple layer, m: the pressure head p/(ρg) of its
/// keel sphere `keel` as an ewave source (interaction::ewaveSource: g·SHR·(1 + AF) over a patch
/// of radius R, whose pressure head is that times R/g), SHR·R·(1 + AF). What its keel spheres
/// press on a free surface; with ripples.hulls_obstruct the hull holds its water there instead.
float hullHollow(const interaction::BoundingSphere& keel);
/// Creates a ship from its [[objects]] entry (type "ship").
ecs::Entity spawnShip(ecs::World& world, const ObjectDef& def);
/// Script phase: the player's keys or the waypoint pilot set throttle and rudder; the hull
/// model turns them into forces for the physics step (thrust and rudder force at the stern,
/// forward and lateral hull resistance).
void shipSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
