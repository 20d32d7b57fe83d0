// Splashes and foam in the sandbox (laws: docs/splash_foam.md).
#include "sim/splash_foam_system.h"

#include "core/hash.h"
#include "ecs/components.h"
#include "behaviours/fish.h"
#include "foam/foam_map.h"
#include "interaction/ripple_patch.h"
#include "interaction/sphere_set.h"
#include "ocean/ocean_fft_cpu.h"
#include "splash/splash_particles.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <memory>
#include <numbers>
#include <unordered_map>
#include <vector>

namespace ob::game {

namespace {

/// The resource: drops, foam, and one crossing tracker per bounding sphere and per fish.
struct SplashFoamState {
    std::unique_ptr<splash::SplashParticles> particles;  ///< null when [splash] is off
    std::unique_ptr<foam::FoamMap> foam;                 ///< null when [foam] is off or there are no ripples
    foam::FoamDef foamDef;                               ///< created with the ripple patch on the first step
    /// Per entity: its spheres' (SphereSet) or fish's (FishSchool) trackers, in their order.
    struct Trackers {
        std::vector<splash::SurfaceCrossing> spheres;
        uint64_t seen = 0;  ///< the last step its entity was met (others are removed: ids are reused)
    };
    std::unordered_map<uint32_t, Trackers> crossings;
    std::vector<glm::vec2> flowNodes, flowVelocity;  ///< the foam's velocity grid (world x, z; m/s)
};

// A sphere of water-like density's mass (fish: no Motion), kg.
float sphereMass(float radius) { return splash::WATER_DENSITY * 4.0f / 3.0f * std::numbers::pi_v<float> * radius * radius * radius; }

} // namespace

void addSplashFoam(ecs::World& world, const splash::SplashDef& splash, const foam::FoamDef& foam, uint64_t seed) {
    if (!splash.enabled && !foam.enabled) return;
    auto state = std::make_unique<SplashFoamState>();
    if (splash.enabled) state->particles = std::make_unique<splash::SplashParticles>(splash, seed);
    state->foamDef = foam;
    world.setResource(std::move(state));
}

void splashFoamSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* state = world.resource<SplashFoamState>();
    const OceanState* ocean = world.resource<OceanState>();
    if (!state || !ocean || !ocean->water) return;
    const water::WaterQuery& water = *ocean->water;
    auto* patch = world.resource<interaction::RipplePatch>();
    const float dt = float(tick.dt);
    if (!state->foam && state->foamDef.enabled && patch) {
        const float patchSide = float(patch->def().resolution) * patch->def().cell_size;
        const float extent = state->foamDef.extent_m > 0.0f ? state->foamDef.extent_m : patchSide;
        state->foam = std::make_unique<foam::FoamMap>(state->foamDef, extent, patch->origin() + glm::vec2(0.5f * patchSide));
    }
    splash::SplashParticles* drops = state->particles.get();
    foam::FoamMap* foam = state->foam.get();
    if (foam && patch) foam->centerOn(patch->origin() + glm::vec2(0.5f * float(patch->def().resolution) * patch->def().cell_size));

    const auto trackersOf = [&](uint32_t entity, size_t count) -> std::vector<splash::SurfaceCrossing>& {
        SplashFoamState::Trackers& t = state->crossings[entity];
        t.seen = tick.step + 1;
        t.spheres.resize(count);
        return t.spheres;
    };

    // --- bodies (cannonballs, dropped bodies, hulls): a crossing of a sphere emits its splash
    auto& sets = world.pool<interaction::SphereSet>();
    for (size_t i = 0; i < sets.size(); ++i) {
        const ecs::Entity e = sets.entities()[i];
        const interaction::SphereSet& set = sets.components()[i];
        const ecs::Transform* transform = world.find<ecs::Transform>(e);
        if (!transform) continue;
        const ecs::Motion* motion = world.find<ecs::Motion>(e);
        const glm::vec3 velocity = motion ? motion->velocity : glm::vec3(0.0f);
        const float mass = motion ? motion->mass / float(set.spheres.size()) : 0.0f;  // shared by its spheres
        std::vector<splash::SurfaceCrossing>& trackers = trackersOf(uint32_t(e), set.spheres.size());
        size_t bow = 0;
        for (size_t k = 0; k < set.spheres.size(); ++k)
            if (set.spheres[k].offset.z > set.spheres[bow].offset.z) bow = k;
        for (size_t k = 0; k < set.spheres.size(); ++k) {
            const interaction::BoundingSphere& s = set.spheres[k];
            const glm::vec3 centre = transform->position + transform->rotation * s.offset;
            const water::WaterSample surface = water.sample(centre.x, centre.z);
            const splash::Crossing crossing = trackers[k].update(centre.y, s.radius, surface.height);
            if (drops && crossing != splash::Crossing::None) {
                splash::Impact impact;
                impact.centre = centre;
                impact.velocity = velocity;
                impact.radius = s.radius;
                impact.mass = mass;
                impact.surfaceHeight = surface.height;
                impact.surfaceNormal = surface.normal;
                impact.surfaceVelocity = surface.verticalVelocity;
                impact.kind = crossing;
                drops->emitImpact(impact);
            }
            // Hull spheres in the water: bow spray from the foremost, wake foam from all.
            const bool wetted = centre.y - s.radius <= surface.height;
            if (!set.hull || !wetted) continue;
            if (drops && k == bow) drops->emitBowSpray(glm::vec3(centre.x, surface.height, centre.z), velocity, s.radius, dt);
            if (foam) foam->addWake(centre, velocity, s.radius, dt);
        }
    }

    // --- fish: leaving the water throws a plume, falling back a crown
    auto& schools = world.pool<FishSchool>();
    for (size_t i = 0; i < schools.size() && drops; ++i) {
        const FishSchool& school = schools.components()[i];
        std::vector<splash::SurfaceCrossing>& trackers = trackersOf(uint32_t(schools.entities()[i]), school.size());
        const float radius = school.sphere.radius;
        for (size_t f = 0; f < school.size(); ++f) {
            // A swimming fish is under water: its tracker learns that without a query (a fish
            // that ends its jump this step still reports its entry, then reads the water).
            splash::Crossing crossing;
            water::WaterSample surface;
            if (!school.jumping[f]) {
                crossing = trackers[f].update(school.position[f].y, radius, 3.4e38f);
                if (crossing == splash::Crossing::None) continue;
                surface = water.sample(school.position[f].x, school.position[f].z);
            } else {
                surface = water.sample(school.position[f].x, school.position[f].z);
                crossing = trackers[f].update(school.position[f].y, radius, surface.height);
            }
            if (crossing == splash::Crossing::None) continue;
            splash::Impact impact;
            impact.centre = school.position[f];
            impact.velocity = school.velocity[f];
            impact.radius = radius;
            impact.mass = sphereMass(radius);
            impact.surfaceHeight = surface.height;
            impact.surfaceNormal = surface.normal;
            impact.surfaceVelocity = surface.verticalVelocity;
            impact.kind = crossing;
            drops->emitImpact(impact);
        }
    }

    std::erase_if(state->crossings, [&](const auto& entry) { return entry.second.seen != tick.step + 1; });

    // --- flight and landings: rain back on the ripples and the foam
    if (drops) {
        drops->step(dt, water);
        if (patch) splash::stampLandings(*patch, drops->landings(), drops->def().ripple_energy);
        if (foam) foam->addLandings(drops->landings());
    }

    // --- foam: whitecaps (first cascade's Jacobian), steep ripples, then transport with the
    // surface's horizontal velocity (the particles' orbital motion, Gerstner and cascades, on
    // the map's coarse velocity grid) and decay
    if (foam) {
        const ocean::OceanFftCpu& fft = *ocean->cpu;
        const int n = fft.resolution();
        foam->addWhitecaps(std::span(fft.channel(0, ocean::OceanChannel::Jacobian), size_t(n) * size_t(n)), n,
                           float(fft.patchSize(0)), dt);
        if (patch) foam->addRipples(*patch, dt);
        state->flowNodes = foam->flowNodePositions();
        state->flowVelocity.resize(state->flowNodes.size());
        ocean->water->horizontalVelocityBatch(state->flowNodes, state->flowVelocity);
        foam->setVelocityNodes(state->flowVelocity);
        foam->step(dt);
    }
}

const splash::SplashParticles* splashParticles(ecs::World& world) {
    const auto* state = world.resource<SplashFoamState>();
    return state ? state->particles.get() : nullptr;
}

const foam::FoamMap* foamMap(ecs::World& world) {
    const auto* state = world.resource<SplashFoamState>();
    return state ? state->foam.get() : nullptr;
}

void hashSplashFoam(ecs::World& world, StateHasher& h) {
    const auto* state = world.resource<SplashFoamState>();
    if (!state) return;
    if (state->particles) state->particles->hash(h);
    if (state->foam) state->foam->hash(h);
}

} // namespace ob::game
