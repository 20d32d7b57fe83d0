// Spawning by table (the behaviours and sim/objects' floating bodies): each [[objects]] type, how it enters the world and the keys of
// ObjectDef it reads. A key its type does not read is a scene error naming the type.
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
    std::vector<std::string_view> keys;                          ///< what it reads besides OBJECT_COMMON_KEYS
};

/// The keys every type reads (the bounding sphere's: the body's, a ship's hull, a cannon's
/// balls, each fish).
inline constexpr std::string_view OBJECT_COMMON_KEYS[] = {"type",   "name",         "position",            "color",
                                                          "model",  "spheres",      "sphere_cells",        "sphere_height_ratio",
                                                          "sphere_af"};

/// The spawner of `type`.
const ObjectSpawner& objectSpawner(ObjectType type);
/// Whether an object of the spawner's type reads `key` (a key of ObjectDef).
bool objectTypeReads(const ObjectSpawner& type, std::string_view key);

/// Creates the physics resource and every object of the scene (spawnObject, in order).
void spawnObjects(ecs::World& world, const physics::PhysicsDef& def, const std::vector<ObjectDef>& objects, uint64_t seed);
/// Creates one object (any type) in a world that has the physics resource; `seed` feeds its
/// random choices (fish). Returns the object's entity.
ecs::Entity spawnObject(ecs::World& world, const ObjectDef& def, uint64_t seed);

} // namespace ob::game
