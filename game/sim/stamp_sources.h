// Stamp sources: whatever disturbs the water through Table 2's bounding spheres (bodies and
// their hulls, cannonballs, fish). The ripple system stamps their spheres, the splash and foam
// system watches them cross the surface, the soak bounds the ripples by them: all three walk
// the world's list of sources, so a new kind of object joins by adding its source
// (world/sandbox.cpp) and no consumer names a type.
#pragma once
#include "ecs/world.h"
#include "interaction/sphere_stamp.h"

#include <cstdint>
#include <functional>
#include <vector>
#include <glm/vec3.hpp>

namespace ob::game {

/// One bounding sphere of a source, placed for this step.
struct PlacedSphere {
    uint32_t owner = 0;         ///< the entity it belongs to (with `index`, a key that lasts while the entity does)
    uint32_t index = 0;         ///< its place among its owner's spheres
    uint32_t count = 0;         ///< how many spheres its owner has
    const interaction::BoundingSphere* sphere = nullptr;
    interaction::SphereContact* contact = nullptr;  ///< its Table 2 state
    glm::vec3 centre{0.0f};     ///< world, m
    glm::vec3 velocity{0.0f};   ///< m/s
    float stampMass = 1.0f;     ///< kg that eq. 6 weighs its stamp by (a body's mass; 1 for a fish, as [Kang2008]'s sweep)
    float crossingMass = 0.0f;  ///< kg it carries through the surface (splash crowns): a body's share, a fish's own
    bool underwater = false;    ///< known to be under the surface without a query (a swimming fish)
    bool hull = false;          ///< a hull's sphere: its stern and bow make foam while wetted
    bool bow = false;           ///< a hull's foremost sphere: bow spray, the bow wave's foam
    bool stern = false;         ///< a hull's aftmost sphere: wake foam and the turbulent wake behind it
};

/// What a consumer does with a sphere; for SphereUse::Stamp it returns whether it stamped.
using SphereVisitor = std::function<bool(const PlacedSphere&)>;

/// Why a consumer walks the spheres: for stamping, a source leaves out the spheres that
/// cannot stamp this step, as cheaply as it knows how (a school's fish out of contact deep
/// under, or off the patch, need no water query).
enum class SphereUse : uint8_t { Stamp, Crossing };

/// One kind of source.
struct StampSource {
    const char* name;
    /// Visits its spheres, entity then sphere order.
    void (*forEach)(ecs::World& world, SphereUse use, const SphereVisitor& visit);
    /// The tallest stamp one of its objects can raise, m: radius·SHR summed over an object's
    /// spheres (overlapping spheres chain through eq. 5's base); spheres yet to be spawned
    /// (a cannon's balls) count from the start.
    float (*largestStamp)(ecs::World& world);
};

/// Adds a source to the world's list (the order sources are added is the order they stamp).
void addStampSource(ecs::World& world, const StampSource& source);
/// Visits every source's spheres, in the list's order.
void forEachSphere(ecs::World& world, SphereUse use, const SphereVisitor& visit);
/// The largest of the sources' largestStamp.
float largestStamp(ecs::World& world);

/// The bodies' SphereSets: floating spheres and boxes, ships' hulls, cannonballs.
StampSource bodySource();

} // namespace ob::game
