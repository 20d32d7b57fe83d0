// Spawning by table (the behaviours and sim/objects' floating bodies): how each [[objects]]
// type enters the world. (The keys each type reads are its settings struct, sim/objects.h.)
#pragma once
#include "ecs/world.h"
#include "physics/physics_def.h"
#include "sim/objects.h"

#include <string>
#include <string_view>
#include <vector>

namespace ob::game {

/// How one type of object enters the world.
struct ObjectSpawner {
    ObjectType type;
    ecs::Entity (*spawn)(ecs::World&, const ObjectDef&, uint64_t seed);
};

/// The spawner of `type`.
const ObjectSpawner& objectSpawner(ObjectType type);

/// Creates the physics resource and every object of the scene (spawnObject, in order). `def`
/// is read in place from then on (PhysicsSettings): it must live as long as the world (the
/// scene resource's section).
void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects, uint64_t seed);
/// What `e` is, as the stats and messages print it: its [[objects]] type's word, "cannonball"
/// for a cannon's ball ("" for an entity that is no object).
std::string objectTypeName(ecs::World& world, ecs::Entity e);
/// Creates one object (any type) in a world that has the physics resource; `seed` feeds its
/// random choices (fish). Returns the object's entity.
ecs::Entity spawnObject(ecs::World& world, const ObjectDef& def, uint64_t seed);

} // namespace ob::game
