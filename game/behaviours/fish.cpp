// Fish schools: swimming on a circle or in a region, ballistic jumps, Table 2 stamps.
#include "behaviours/fish.h"

#include "core/random.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace ob::game {

namespace {

// Time until a fish's next jump: uniform in [0.5, 1.5] × the mean interval.
float nextJumpDelay(FishSchool& s) { return s.def.jump_interval * float(0.5 + uniform01(s.rng)); }

// The paper's fish sphere ([Kang2008] §V-2): smaller than the body (radius 0.35 × length),
// SHR 1.4, AF −0.3, SD from the motion (+1 rising, −1 falling).
interaction::BoundingSphere paperFishSphere(float length) {
    interaction::BoundingSphere s;
    s.radius = 0.35f * length;
    s.direction = interaction::SphereDirection::Auto;
    s.heightRatio = 1.4f;
    s.accelerationFactor = -0.3f;
    return s;
}

} // namespace

float fishMass(float length) { return FISH_CONDITION * length * length * length; }

ecs::Entity spawnFishSchool(ecs::World& world, const ObjectDef& o, uint64_t seed) {
    FishSchool s;
    s.def = o.school;
    s.color = o.color;
    s.model = o.model;
    s.centre = glm::vec2(o.position.x, o.position.z);
    s.halfSize = 0.5f * glm::vec2(o.school.size.x, o.school.size.z);
    s.speed = o.school.speed;
    s.sphere = boundingSphereFor(o, paperFishSphere(o.school.length), rippleCellSize(world));
    s.sphere.direction = interaction::SphereDirection::Auto;  // SD follows the vertical motion in either case
    s.rng = seed * 0x2545F4914F6CDD1Dull + 0x9E3779B97F4A7C15ull;

    const size_t n = size_t(o.school.count);
    s.position.resize(n);
    s.velocity.resize(n);
    s.lane.resize(n);
    s.angle.resize(n);
    s.timer.resize(n);
    s.jumping.assign(n, 0);
    s.contacts.assign(n, {});
    s.stamped.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (s.inRegion()) {
            s.position[i] = glm::vec3(s.centre.x + s.halfSize.x * float(2.0 * uniform01(s.rng) - 1.0), -s.def.depth,
                                      s.centre.y + s.halfSize.y * float(2.0 * uniform01(s.rng) - 1.0));
            s.lane[i] = float(2.0 * M_PI * uniform01(s.rng));
        } else {
            // Spread evenly round the circle, on lanes within ±15% of its radius.
            s.angle[i] = float(2.0 * M_PI * (double(i) + 0.5 * uniform01(s.rng)) / double(n));
            s.lane[i] = s.def.radius * float(0.85 + 0.3 * uniform01(s.rng));
            s.position[i] = glm::vec3(s.centre.x + s.lane[i] * std::cos(s.angle[i]), -s.def.depth, s.centre.y + s.lane[i] * std::sin(s.angle[i]));
        }
        s.timer[i] = s.def.jump_interval * float(1.5 * uniform01(s.rng));  // staggered first jumps
    }
    ecs::Entity e = world.create();
    world.add<ecs::Transform>(e, {glm::vec3(s.centre.x, 0.0f, s.centre.y)});
    world.add<ObjectTag>(e, {ObjectType::FishSchool, o.name});
    world.add<FishSchool>(e, std::move(s));
    return e;
}

void fishSystem(ecs::World& world, const ecs::Tick& tick) {
    const float g = physicsDef(world).gravity;
    const float dt = float(tick.dt);
    for (FishSchool& s : world.pool<FishSchool>().components()) {
        // Take-off speed from the swimming depth to the apex, and the arc's duration.
        const float v0 = std::sqrt(2.0f * g * (s.def.depth + s.def.jump_height));
        const float arcTime = 2.0f * v0 / g;
        for (size_t i = 0; i < s.size(); ++i) {
            glm::vec3& p = s.position[i];
            glm::vec3& v = s.velocity[i];
            // --- along the circle or the region
            if (s.inRegion()) {
                glm::vec2 dir(std::sin(s.lane[i]), std::cos(s.lane[i]));
                p.x += dir.x * s.speed * dt;
                p.z += dir.y * s.speed * dt;
                if (std::abs(p.x - s.centre.x) > s.halfSize.x) {
                    s.lane[i] = -s.lane[i];  // reflect off a side at ±x
                    p.x = std::clamp(p.x, s.centre.x - s.halfSize.x, s.centre.x + s.halfSize.x);
                }
                if (std::abs(p.z - s.centre.y) > s.halfSize.y) {
                    s.lane[i] = float(M_PI) - s.lane[i];  // reflect off a side at ±z
                    p.z = std::clamp(p.z, s.centre.y - s.halfSize.y, s.centre.y + s.halfSize.y);
                }
                v.x = s.speed * std::sin(s.lane[i]);
                v.z = s.speed * std::cos(s.lane[i]);
            } else {
                s.angle[i] += s.speed / s.lane[i] * dt;
                const float c = std::cos(s.angle[i]), sn = std::sin(s.angle[i]);
                p.x = s.centre.x + s.lane[i] * c;
                p.z = s.centre.y + s.lane[i] * sn;
                v.x = -s.speed * sn;
                v.z = s.speed * c;
            }
            // --- vertical: swim at depth, or fly the ballistic arc
            if (!s.jumping[i]) {
                s.timer[i] -= dt;
                if (s.timer[i] <= 0.0f) {
                    s.jumping[i] = 1;
                    s.timer[i] = 0.0f;
                    ++s.jumps;
                }
            }
            if (s.jumping[i]) {
                s.timer[i] += dt;
                const float tau = s.timer[i];
                if (tau >= arcTime) {
                    s.jumping[i] = 0;
                    s.timer[i] = nextJumpDelay(s);
                } else {
                    p.y = -s.def.depth + v0 * tau - 0.5f * g * tau * tau;
                    v.y = v0 - g * tau;
                    continue;
                }
            }
            p.y = -s.def.depth;
            v.y = 0.0f;
        }
    }
}

namespace {

// Every fish, school then fish order. To stamp, only the fish that can: a swimming fish that
// is not in contact is deep under, Table 2 leaves it Free and it needs no water query, and a
// fish off the patch has nothing to stamp (this is what keeps a large swarm cheap).
void eachFishSphere(ecs::World& world, SphereUse use, const SphereVisitor& visit) {
    const auto* patch = world.resource<interaction::RipplePatch>();
    if (use == SphereUse::Stamp && !patch) return;
    auto& schools = world.pool<FishSchool>();
    for (size_t k = 0; k < schools.size(); ++k) {
        FishSchool& s = schools.components()[k];
        PlacedSphere p;
        p.owner = uint32_t(schools.entities()[k]);
        p.count = uint32_t(s.size());
        p.sphere = &s.sphere;
        p.crossingMass = fishMass(s.def.length);  // the body's, not its bounding sphere's (94 kg for a 0.8 m fish)
        for (size_t i = 0; i < s.size(); ++i) {
            p.index = uint32_t(i);
            p.contact = &s.contacts[i];
            p.centre = s.position[i];
            p.velocity = s.velocity[i];
            p.underwater = !s.jumping[i];
            if (use == SphereUse::Crossing) {
                visit(p);
                continue;
            }
            s.stamped[i] = 0;
            if (!s.jumping[i] && s.contacts[i].phase == interaction::ContactPhase::Free) continue;
            const float reach = s.sphere.radius / patch->def().cell_size + 1.0f;  // footprint radius, cells
            const float cells = float(patch->def().resolution);
            const glm::vec2 g = patch->toGrid(glm::vec2(p.centre.x, p.centre.z));
            if (g.x < -reach || g.y < -reach || g.x > cells + reach || g.y > cells + reach) continue;
            if (visit(p)) {
                s.stamped[i] = 1;
                ++s.stamps;
            }
        }
    }
}

float largestFishStamp(ecs::World& world) {
    float largest = 0.0f;
    for (const FishSchool& s : world.pool<FishSchool>().components()) largest = std::max(largest, s.sphere.radius * s.sphere.heightRatio);
    return largest;
}

} // namespace

StampSource fishSource() { return {"fish", eachFishSphere, largestFishStamp}; }

void appendFishDraws(ecs::World& world, std::vector<gfx::ObjectDraw>& draws) {
    for (const FishSchool& s : world.pool<FishSchool>().components()) {
        if (!s.def.draw) continue;
        // A model is 1 m long; the built-in unit sphere becomes an ellipsoid body.
        const glm::vec3 scale = s.model.empty() ? s.def.length * glm::vec3(0.09f, 0.12f, 0.5f) : glm::vec3(s.def.length);
        const size_t n = std::min(s.size(), MAX_DRAWN_FISH);
        for (size_t i = 0; i < n; ++i) {
            glm::vec3 v = s.velocity[i];
            if (glm::dot(v, v) < 1e-8f) v = glm::vec3(0, 0, 1);
            // The body's +z along the velocity (quatLookAt points −z at its argument).
            const glm::vec3 up = std::abs(glm::normalize(v).y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
            const glm::quat q = glm::quatLookAtRH(-glm::normalize(v), up);
            glm::mat4 model = glm::translate(glm::mat4(1.0f), s.position[i]) * glm::mat4_cast(q) * glm::scale(glm::mat4(1.0f), scale);
            draws.push_back({gfx::MeshKind::Sphere, model, s.color, s.model});
        }
    }
}

} // namespace ob::game
