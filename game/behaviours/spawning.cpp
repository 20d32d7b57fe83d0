// The object types' table: the floating bodies of sim/objects.cpp and the behaviours.
#include "behaviours/spawning.h"

#include "behaviours/cannon.h"
#include "behaviours/fish.h"
#include "behaviours/ship.h"

#include <algorithm>
#include <cassert>
#include <memory>

namespace ob::game {

const ObjectSpawner& objectSpawner(ObjectType type) {
    static const ObjectSpawner SPAWNERS[] = {
        {ObjectType::Sphere, spawnFloatingBody, {"velocity", "radius", "density"}},
        {ObjectType::Box, spawnFloatingBody, {"velocity", "size", "density"}},
        {ObjectType::Ship, [](ecs::World& w, const ObjectDef& o, uint64_t) { return spawnShip(w, o); },
         {"velocity", "density", "hull", "player", "yaw_deg", "speed", "waypoints"}},
        {ObjectType::Cannon, [](ecs::World& w, const ObjectDef& o, uint64_t) { return spawnCannon(w, o); },
         {"player", "yaw_deg", "elevation_deg", "muzzle_speed", "rate", "ball_radius", "ball_density", "sink_depth"}},
        {ObjectType::FishSchool, spawnFishSchool,
         {"radius", "size", "speed", "count", "shape", "depth", "jump_height", "jump_interval", "length", "draw"}},
    };
    static_assert(std::size(SPAWNERS) == enumNames<ObjectType>.size(), "one spawner per object type");
    assert(SPAWNERS[size_t(type)].type == type);
    return SPAWNERS[size_t(type)];
}

bool objectTypeReads(const ObjectSpawner& type, std::string_view key) {
    return std::find(std::begin(OBJECT_COMMON_KEYS), std::end(OBJECT_COMMON_KEYS), key) != std::end(OBJECT_COMMON_KEYS) ||
           std::find(type.keys.begin(), type.keys.end(), key) != type.keys.end();
}

ecs::Entity spawnObject(ecs::World& world, const ObjectDef& o, uint64_t seed) {
    return objectSpawner(o.type).spawn(world, o, seed);
}

void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects, uint64_t seed) {
    world.setResource(std::make_unique<physics::PhysicsWorld>(def));
    world.setResource(std::make_unique<physics::PhysicsDef>(def));
    for (size_t i = 0; i < objects.size(); ++i) spawnObject(world, objects[i], seed * 1000003ull + i);
}

} // namespace ob::game
