// Fish schools ([Kang2008] §V-2): kinematic fish that swim below the surface and jump on
// ballistic arcs; one bounding sphere each, smaller than the body, SD +1 rising and −1
// falling, SHR 1.4, AF −0.3. A school is one entity with its fish in flat arrays, so a
// swarm of 100,000 costs a few arrays and only the fish near the surface query the water.
#pragma once
#include "ecs/schedule.h"
#include "interaction/sphere_stamp.h"
#include "sim/objects.h"
#include "sim/stamp_sources.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ob::game {

/// A school: its [[objects]] settings as written, what they place, and its fish (structure of
/// arrays, index = fish).
struct FishSchool {
    // --- settings
    FishSchoolDef def;            ///< the scene's settings (shape, radius, depth, jumps, length, draw)
    glm::vec3 color{0.6f};        ///< body colour (the object's `color`)
    std::string model;            ///< glTF fish (1 m long, nose +z), scaled by def.length; "" = built-in ellipsoid
    // --- placement and state
    glm::vec2 centre{0.0f};       ///< world [x, z] of the circle or region centre (the object's position), m
    glm::vec2 halfSize{10.0f};    ///< region half extents [x, z] (half def.size), m
    float speed = 3.0f;           ///< swimming speed now, m/s (starts at def.speed; set_speed changes it)
    interaction::BoundingSphere sphere;  ///< every fish's bounding sphere
    uint64_t rng = 1;             ///< state of the school's random sequence (jump timing)
    // --- per fish
    std::vector<glm::vec3> position;   ///< world centre, m
    std::vector<glm::vec3> velocity;   ///< m/s
    std::vector<float> lane;           ///< circle: radius of its lane, m; region: heading, rad
    std::vector<float> angle;          ///< circle: angle on its lane, rad
    std::vector<float> timer;          ///< swimming: s until the jump; jumping: s since it started
    std::vector<uint8_t> jumping;      ///< 1 while on a ballistic arc
    std::vector<interaction::SphereContact> contacts;  ///< Table 2 state per fish
    std::vector<uint8_t> stamped;      ///< 1 if the fish stamped the ripple field this step
    uint64_t jumps = 0;                ///< jumps started so far
    uint64_t stamps = 0;               ///< stamps so far
    size_t size() const { return position.size(); }
    /// Inside a rectangle of `halfSize` (else on a circle of def.radius).
    bool inRegion() const { return def.shape == SchoolShape::Region; }
};

/// Fish drawn per school at most (the rest still swim and stamp).
constexpr size_t MAX_DRAWN_FISH = 4096;

/// Creates a school from its [[objects]] entry (type "fish_school"); `seed` feeds its jumps.
/// A fish's mass per cubed length, kg/m³: Fulton's condition factor K = 100·W/L³ (W in g, L in
/// cm) is about 1 for most fish, so W = 10 kg·(L/1 m)³ (a 0.4 m fish 0.64 kg, a 0.8 m fish 5.1 kg).
constexpr float FISH_CONDITION = 10.0f;
/// The mass of a fish `length` metres long, kg (FISH_CONDITION·L³): what it carries through
/// the surface when it jumps or falls back (its splash).
float fishMass(float length);
ecs::Entity spawnFishSchool(ecs::World& world, const ObjectDef& def, uint64_t seed);
/// Script phase: every fish swims or flies its arc one step.
void fishSystem(ecs::World& world, const ecs::Tick& tick);
/// The fish as a stamp source (school then fish order; 1 kg each in eq. 6, as [Kang2008]'s sweep).
StampSource fishSource();
/// Appends the fish to draw (facing their velocity) to the opaque pass's list.
void appendFishDraws(ecs::World& world, std::vector<gfx::ObjectDraw>& draws);

} // namespace ob::game
