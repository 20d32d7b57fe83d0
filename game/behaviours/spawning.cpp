// The object types' table: the floating bodies of sim/objects.cpp and the behaviours.
#include "behaviours/spawning.h"

#include "behaviours/cannon.h"
#include "behaviours/fish.h"
#include "behaviours/ship.h"

#include <algorithm>
#include <memory>

namespace ob::game {

const std::vector<ObjectType>& objectTypes() {
    static const std::vector<ObjectType> TYPES = {
        {"sphere", spawnFloatingBody, {"velocity", "radius", "density"}},
        {"box", spawnFloatingBody, {"velocity", "size", "density"}},
        {"ship", [](ecs::World& w, const ObjectDef& o, uint64_t) { return spawnShip(w, o); },
         {"velocity", "density", "hull", "player", "yaw_deg", "speed", "waypoints"}},
        {"cannon", [](ecs::World& w, const ObjectDef& o, uint64_t) { return spawnCannon(w, o); },
         {"player", "yaw_deg", "elevation_deg", "muzzle_speed", "rate", "ball_radius", "ball_density", "sink_depth"}},
        {"fish_school", spawnFishSchool,
         {"radius", "size", "speed", "count", "shape", "depth", "jump_height", "jump_interval", "length", "draw"}},
    };
    return TYPES;
}

const ObjectType* findObjectType(std::string_view name) {
    for (const ObjectType& t : objectTypes())
        if (name == t.name) return &t;
    return nullptr;
}

bool objectTypeReads(const ObjectType& type, std::string_view key) {
    return std::find(std::begin(OBJECT_COMMON_KEYS), std::end(OBJECT_COMMON_KEYS), key) != std::end(OBJECT_COMMON_KEYS) ||
           std::find(type.keys.begin(), type.keys.end(), key) != type.keys.end();
}

ecs::Entity spawnObject(ecs::World& world, const ObjectDef& o, uint64_t seed) {
    const ObjectType* type = findObjectType(o.type);
    return type ? type->spawn(world, o, seed) : ecs::Entity::None;  // the scene loader admits only listed types
}

void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects, uint64_t seed) {
    world.setResource(std::make_unique<physics::PhysicsWorld>(def));
    world.setResource(std::make_unique<physics::PhysicsDef>(def));
    for (size_t i = 0; i < objects.size(); ++i) spawnObject(world, objects[i], seed * 1000003ull + i);
}

} // namespace ob::game
