// Stamp sources (sim/stamp_sources.h): a new kind of object reaches the water through its
// source alone. A source no consumer knows (one sphere dropped through calm water) stamps the
// ripple patch, splashes as it crosses the surface, and counts in the soak's bound.
#include "interaction/ripple_patch.h"
#include "sim/splash_foam_system.h"
#include "sim/stamp_sources.h"
#include "splash/splash_particles.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <memory>

using namespace ob;

namespace {

const char* CALM_SCENE = R"(
[ocean]
amplitude = 0.0
resolution = 16
[gerstner]
count = 0
)";

// The new kind: a sphere falling at a steady 4 m/s from 1 m above the mean surface.
struct Dropper {
    glm::vec3 centre{0.0f, 1.0f, 0.0f};
    glm::vec3 velocity{0.0f, -4.0f, 0.0f};
    interaction::BoundingSphere sphere;
    interaction::SphereContact contact;
    int stamps = 0, visits = 0;
};

void eachDropperSphere(ecs::World& world, game::SphereUse use, const game::SphereVisitor& visit) {
    Dropper* d = world.resource<Dropper>();
    if (!d) return;
    game::PlacedSphere p;
    p.owner = 4242;  // no entity of the scene has it
    p.count = 1;
    p.sphere = &d->sphere;
    p.contact = &d->contact;
    p.centre = d->centre;
    p.velocity = d->velocity;
    p.stampMass = 500.0f;
    p.crossingMass = 500.0f;
    ++d->visits;
    if (visit(p) && use == game::SphereUse::Stamp) ++d->stamps;
}

float largestDropperStamp(ecs::World& world) {
    const Dropper* d = world.resource<Dropper>();
    return d ? d->sphere.radius * d->sphere.heightRatio : 0.0f;
}

float largestHeight(const interaction::RipplePatch& patch) {
    float largest = 0.0f;
    for (float h : patch.height()) largest = std::max(largest, std::fabs(h));
    return largest;
}

} // namespace

TEST_CASE("a stamp source no consumer names stamps the ripples, splashes and bounds the soak", "[stamp_source]") {
    game::Sandbox sandbox(game::parseScene(CALM_SCENE, "calm.toml"));
    ecs::World& world = sandbox.world();
    Dropper& d = world.setResource(std::make_unique<Dropper>());
    d.sphere.radius = 0.4f;
    d.sphere.direction = interaction::SphereDirection::Down;
    d.sphere.heightRatio = 1.5f;
    game::addStampSource(world, {"dropper", eachDropperSphere, largestDropperStamp});
    CHECK(game::largestStamp(world) == Approx(0.4f * 1.5f));  // the calm scene has no other source

    const auto* patch = world.resource<interaction::RipplePatch>();
    REQUIRE(patch);
    int mostDrops = 0;
    const float dt = 1.0f / 60.0f;
    for (int step = 0; step < 30; ++step) {  // 0.5 s: from 1 m above to 1 m below
        sandbox.step();
        d.centre += d.velocity * dt;
        if (const splash::SplashParticles* drops = game::splashParticles(world)) mostDrops = std::max(mostDrops, drops->size());
    }
    INFO("stamps " << d.stamps << ", visits " << d.visits << ", drops " << mostDrops << ", |h| " << largestHeight(*patch));
    CHECK(d.visits >= 2 * 30);          // both consumers walked it every step
    CHECK(d.stamps > 0);                // Table 2 stamped it while it crossed
    CHECK(d.stamps < 30);               // and not while it was in the air or deep under
    CHECK(largestHeight(*patch) > 1e-3f);  // the water moved
    CHECK(mostDrops > 0);               // its entry splashed
}
