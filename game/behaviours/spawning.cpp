// The object types' table: the floating bodies of sim/objects.cpp and the behaviours.
#include "behaviours/spawning.h"

#include "behaviours/cannon.h"
#include "behaviours/fish.h"
#include "behaviours/ship.h"

#include <cassert>
#include <memory>

namespace ob::game {

const ObjectSpawner& objectSpawner(ObjectType type) {
    static const ObjectSpawner SPAWNERS[] = {
        {ObjectType::Sphere, spawnFloatingBody},
        {ObjectType::Box, spawnFloatingBody},
        {ObjectType::Ship, [](ecs::World& w, const ObjectDef& o, uint64_t) { return spawnShip(w, o); }},
        {ObjectType::Cannon, [](ecs::World& w, const ObjectDef& o, uint64_t) { return spawnCannon(w, o); }},
        {ObjectType::FishSchool, spawnFishSchool},
    };
    static_assert(std::size(SPAWNERS) == enumNames<ObjectType>.size(), "one spawner per object type");
    assert(SPAWNERS[size_t(type)].type == type);
    return SPAWNERS[size_t(type)];
}

ecs::Entity spawnObject(ecs::World& world, const ObjectDef& o, uint64_t seed) {
    return objectSpawner(o.type).spawn(world, o, seed);
}

std::string objectTypeName(ecs::World& world, ecs::Entity e) {
    if (world.has<Cannonball>(e)) return "cannonball";
    const ObjectTag* tag = world.find<ObjectTag>(e);
    return tag ? enumName(tag->type) : "";
}

void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects, uint64_t seed) {
    world.setResource(std::make_unique<physics::PhysicsWorld>(def));
    world.setResource(std::make_unique<PhysicsSettings>(PhysicsSettings{&def}));
    for (size_t i = 0; i < objects.size(); ++i) spawnObject(world, objects[i], seed * 1000003ull + i);
}

} // namespace ob::game
