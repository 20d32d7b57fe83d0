// The world's stamp sources, and the bodies' one.
#include "sim/stamp_sources.h"

#include "ecs/components.h"
#include "interaction/sphere_set.h"

#include <algorithm>
#include <memory>

namespace ob::game {

namespace {

/// The resource: the sources in stamping order.
struct StampSources {
    std::vector<StampSource> list;
};

void eachBodySphere(ecs::World& world, SphereUse, const SphereVisitor& visit) {
    auto& sets = world.pool<interaction::SphereSet>();
    for (size_t i = 0; i < sets.size(); ++i) {
        const ecs::Entity e = sets.entities()[i];
        interaction::SphereSet& set = sets.components()[i];
        const ecs::Transform* transform = world.find<ecs::Transform>(e);
        if (!transform) continue;
        const ecs::Motion* motion = world.find<ecs::Motion>(e);
        set.contacts.resize(set.spheres.size());
        size_t bow = 0, stern = 0;
        for (size_t k = 0; k < set.spheres.size(); ++k) {
            if (set.spheres[k].offset.z > set.spheres[bow].offset.z) bow = k;
            if (set.spheres[k].offset.z < set.spheres[stern].offset.z) stern = k;
        }
        PlacedSphere p;
        p.owner = uint32_t(e);
        p.count = uint32_t(set.spheres.size());
        p.velocity = motion ? motion->velocity : glm::vec3(0.0f);
        p.stampMass = motion ? motion->mass : 1.0f;
        p.crossingMass = motion ? motion->mass / float(set.spheres.size()) : 0.0f;  // shared by its spheres
        p.hull = set.hull;
        for (size_t k = 0; k < set.spheres.size(); ++k) {
            p.index = uint32_t(k);
            p.sphere = &set.spheres[k];
            p.contact = &set.contacts[k];
            p.centre = transform->position + transform->rotation * set.spheres[k].offset;
            p.bow = set.hull && k == bow;
            p.stern = set.hull && k == stern;
            visit(p);
        }
    }
}

float largestBodyStamp(ecs::World& world) {
    float largest = 0.0f;
    for (const interaction::SphereSet& set : world.pool<interaction::SphereSet>().components()) {
        float sum = 0.0f;
        for (const interaction::BoundingSphere& s : set.spheres) sum += s.radius * s.heightRatio;
        largest = std::max(largest, sum);
    }
    return largest;
}

} // namespace

void addStampSource(ecs::World& world, const StampSource& source) {
    auto* sources = world.resource<StampSources>();
    if (!sources) sources = &world.setResource(std::make_unique<StampSources>());
    sources->list.push_back(source);
}

void forEachSphere(ecs::World& world, SphereUse use, const SphereVisitor& visit) {
    if (const auto* sources = world.resource<StampSources>())
        for (const StampSource& s : sources->list) s.forEach(world, use, visit);
}

float largestStamp(ecs::World& world) {
    float largest = 0.0f;
    if (const auto* sources = world.resource<StampSources>())
        for (const StampSource& s : sources->list) largest = std::max(largest, s.largestStamp(world));
    return largest;
}

StampSource bodySource() { return {"bodies", eachBodySphere, largestBodyStamp}; }

} // namespace ob::game
