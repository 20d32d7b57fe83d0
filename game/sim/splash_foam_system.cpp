// Splashes and foam in the sandbox (laws: docs/splash_foam.md).
#include "sim/splash_foam_system.h"

#include "core/hash.h"
#include "ecs/components.h"
#include "foam/foam_map.h"
#include "interaction/ripple_patch.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/spectrum.h"
#include "splash/splash_particles.h"
#include "water/composite_water.h"
#include "sim/stamp_sources.h"
#include "sim/water_systems.h"

#include <array>
#include <map>
#include <memory>
#include <numbers>
#include <unordered_map>
#include <vector>

namespace ob::game {

namespace {

/// The resource: drops, foam, and one crossing tracker per bounding sphere of every source.
struct SplashFoamState {
    std::unique_ptr<splash::SplashParticles> particles;  ///< null when [splash] is off
    std::unique_ptr<foam::FoamMap> foam;                 ///< null when [foam] is off or there are no ripples
    foam::FoamDef foamDef;                               ///< created with the ripple patch on the first step
    /// Per source entity: its spheres' trackers, in their order.
    struct Trackers {
        std::vector<splash::SurfaceCrossing> spheres;
        uint64_t seen = 0;  ///< the last step its entity was met (others are removed: ids are reused)
    };
    std::unordered_map<uint32_t, Trackers> crossings;
    /// Per hull entity: its stern's track, the turbulent wake behind it (law (e)).
    struct SternTrack {
        std::vector<glm::vec2> points;  ///< world x, z, oldest first
        std::vector<float> ages;        ///< s since the stern was there
        glm::vec2 now{0.0f};            ///< where the stern is this step
        float radius = 0.0f;            ///< the stern sphere's
        uint64_t seen = 0;              ///< the last step its stern was wetted and under way
    };
    std::map<uint32_t, SternTrack> sterns;  // ordered: the foam adds in the same order every run
    float bowSpeed = 3.0f;  ///< [splash] bow_speed: the bow wave breaks above it
    std::vector<glm::vec2> crests;  ///< the breaking crests of this step (scratch of sprayFromCrests)
    /// The sea's surface Stokes drift (ocean::stokesDrift), summed again when a spectrum key changes.
    glm::vec2 stokes{0.0f};
    std::array<float, 11> stokesSea{};
    /// [sim] pipelined: the foam's sweep (FoamMap::sweep, on copies of its inputs) runs on a worker
    /// from the end of its step until something reads or moves the map (join).
    bool pipelined = false;
    WorkerTask sweep;             ///< the sweep in flight
    /// Waits for the sweep in flight, if any.
    void join() { sweep.join(); }
};

// A stern's track keeps a point every this many metres (or two foam cells, if larger) for
// WAKE_TRACK_LIFE turbulence times (the rate has fallen to e^(−4), 2%).
constexpr float WAKE_TRACK_SPACING = 0.5f;
constexpr float WAKE_TRACK_LIFE = 4.0f;

// Creates the foam map on the first step with a ripple patch, and keeps it centred on it.
foam::FoamMap* placeFoam(SplashFoamState& state, const interaction::RipplePatch* patch) {
    if (!patch) return state.foam.get();
    const float patchSide = float(patch->def().resolution) * patch->def().cell_size;
    if (!state.foam && state.foamDef.enabled) {
        const float extent = state.foamDef.extent_m > 0.0f ? state.foamDef.extent_m : patchSide;
        state.foam = std::make_unique<foam::FoamMap>(state.foamDef, extent, patch->origin() + glm::vec2(0.5f * patchSide));
    }
    if (state.foam) state.foam->centerOn(patch->origin() + glm::vec2(0.5f * patchSide));
    return state.foam.get();
}

// Every source's spheres: a crossing of the surface splashes; a hull's wetted stern lays wake
// foam (and records its track), its bow sprays and breaks its bow wave.
void emitFromSources(ecs::World& world, SplashFoamState& state, const water::WaterQuery& water, uint64_t step, float dt) {
    splash::SplashParticles* drops = state.particles.get();
    foam::FoamMap* foam = state.foam.get();
    forEachSphere(world, SphereUse::Crossing, [&](const PlacedSphere& p) {
        if (!drops && !p.hull) return false;  // nothing to splash, no wake to lay
        SplashFoamState::Trackers& t = state.crossings[p.owner];
        t.seen = step + 1;
        t.spheres.resize(p.count);
        splash::SurfaceCrossing& tracker = t.spheres[p.index];
        const float radius = p.sphere->radius;
        // A sphere known to be under water (a swimming fish) tells its tracker so without a
        // query; it reads the water only when that is a crossing (the end of a jump).
        splash::Crossing crossing = splash::Crossing::None;
        water::WaterSample surface;
        if (p.underwater) {
            crossing = tracker.update(p.centre.y, radius, 3.4e38f);
            if (crossing == splash::Crossing::None) return false;
            surface = water.sample(p.centre.x, p.centre.z);
        } else {
            surface = water.sample(p.centre.x, p.centre.z);
            crossing = tracker.update(p.centre.y, radius, surface.height);
        }
        if (drops && crossing != splash::Crossing::None) {
            // The sea the body meets: its slope and vertical velocity without the ripple layer,
            // which under a crossing sphere is the sphere's own stamp (a kang2008 stamp moves the
            // heights under it by up to its radius in a step: ∂h/∂t of 12–17 m/s under a fish
            // leaving at 3 m/s, five times its speed), not water that hits it.
            const water::WaterSample sea = water.sample(p.centre.x, p.centre.z, {.ripples = false});
            splash::Impact impact;
            impact.centre = p.centre;
            impact.velocity = p.velocity;
            impact.radius = radius;
            impact.mass = p.crossingMass;
            impact.surfaceHeight = surface.height;
            impact.surfaceNormal = sea.normal;
            impact.surfaceVelocity = sea.verticalVelocity;
            impact.kind = crossing;
            drops->emitImpact(impact);
        }
        const bool wetted = p.centre.y - radius <= surface.height;
        if (!p.hull || !wetted) return false;
        if (drops && p.bow) drops->emitBowSpray(glm::vec3(p.centre.x, surface.height, p.centre.z), p.velocity, radius, dt);
        if (!foam) return false;
        // Foam where the flow breaks: the stern's white water and the turbulent wake behind it,
        // the bow wave's arms when it breaks; the water along the hull's sides stays clear.
        const float speed = std::sqrt(p.velocity.x * p.velocity.x + p.velocity.z * p.velocity.z);
        if (p.stern) {
            foam->addWake(p.centre, p.velocity, radius, dt);
            if (speed > 0.0f) {
                SplashFoamState::SternTrack& track = state.sterns[p.owner];
                track.now = glm::vec2(p.centre.x, p.centre.z);
                track.radius = radius;
                track.seen = step + 1;
            }
        }
        if (p.bow && speed > state.bowSpeed) foam->addBowWave(p.centre, p.velocity, radius, speed / state.bowSpeed - 1.0f, dt);
        return false;
    });
    std::erase_if(state.crossings, [&](const auto& entry) { return entry.second.seen != step + 1; });
}

// The turbulent wake (law (e)): every segment of each stern's track adds foam by its age; the
// track gains a point where the stern has moved a spacing on, and ages. A hull that stops or
// leaves the water keeps its track until it has aged out.
void layWakeTrails(SplashFoamState& state, foam::FoamMap& foam, uint64_t step, float dt) {
    const float life = WAKE_TRACK_LIFE * foam.def().wake_turbulence_s;
    const float spacing = std::max(WAKE_TRACK_SPACING, 2.0f * foam.grid().cell);
    for (auto& [owner, track] : state.sterns) {
        for (float& age : track.ages) age += dt;
        const bool moving = track.seen == step + 1;
        if (moving && (track.points.empty() || glm::length(track.now - track.points.back()) >= spacing)) {
            track.points.push_back(track.now);
            track.ages.push_back(0.0f);
        }
        size_t old = 0;  // points whose next one has aged out
        while (old + 1 < track.ages.size() && track.ages[old + 1] > life) ++old;
        track.points.erase(track.points.begin(), track.points.begin() + std::ptrdiff_t(old));
        track.ages.erase(track.ages.begin(), track.ages.begin() + std::ptrdiff_t(old));
        for (size_t k = 0; k + 1 < track.points.size(); ++k)
            foam.addWakeTrail(track.points[k], track.points[k + 1], 0.5f * (track.ages[k] + track.ages[k + 1]), track.radius, dt);
        if (moving && !track.points.empty())  // from the newest point to the stern
            foam.addWakeTrail(track.points.back(), track.now, 0.5f * track.ages.back(), track.radius, dt);
    }
    std::erase_if(state.sterns, [&](const auto& entry) { return entry.second.ages.empty() || entry.second.ages.back() > life; });
}

// Foam: whitecaps (first cascade's Jacobian), steep ripples, then transport with the
// surface's horizontal velocity (the particles' orbital motion, Gerstner and cascades, on the
// map's coarse velocity grid) and decay, in one sweep.
void stepFoam(SplashFoamState& state, foam::FoamMap& foam, const OceanState& ocean, const interaction::RipplePatch* patch, float dt) {
    const ocean::OceanDef& d = ocean.def;
    const std::array<float, 11> sea{d.wind_speed, d.wind_direction.x, d.wind_direction.y, d.amplitude, d.small_wave_cutoff,
                                    d.fetch, d.peak_enhancement, float(d.spectrum), d.gravity, d.patch_size,
                                    float(d.resolution * 8 + d.cascades)};
    if (sea != state.stokesSea) {
        const std::array<double, 2> u = ocean::stokesDrift(d);
        state.stokes = glm::vec2(float(u[0]), float(u[1]));
        state.stokesSea = sea;
    }
    const ocean::OceanFftCpu& fft = *ocean.cpu;
    const int n = fft.resolution();
    foam::FoamInputs in;
    in.jacobian = std::span(fft.channel(0, ocean::OceanChannel::Jacobian), size_t(n) * size_t(n));
    in.jacobianN = n;
    in.jacobianTile = float(fft.patchSize(0));
    in.windSpeed = ocean.def.wind_speed;
    in.windDirection = ocean.def.wind_direction;
    in.stokesDrift = state.stokes;
    in.gravity = ocean.def.gravity;
    in.ripples = patch;
    in.water = ocean.water.get();
    if (!state.pipelined) return foam.update(in, dt);
    // Pipelined: what reads the water here, then the sweep on a worker, on copies of the Jacobian
    // (the ocean phase that follows swaps the maps and starts the next ones in the buffer this one
    // was read from) and of the ripple heights (the next step's ripples move on before its foam).
    foam.prepare(in, dt, true);
    state.sweep.start([&foam] { foam.sweep(); });
}

// Wind spray (splash_particles.h): the points of the first cascade's tile that break now (J
// below the whitecaps' threshold J_b), displaced to X + λ·D (the swell's Gerstner shift left
// out), in the copy of the tile round the foam map's centre, and inside the map's square.
void sprayFromCrests(splash::SplashParticles& drops, const foam::FoamMap& foam, const OceanState& ocean,
                     std::vector<glm::vec2>& crests, float dt) {
    const glm::vec2 wind = ocean.def.wind_speed * glm::normalize(ocean.def.wind_direction);
    const foam::WhitecapLaw& law = foam.whitecaps();
    if (ocean.def.wind_speed <= drops.def().spray_wind || law.rate <= 0.0f) return;
    const ocean::OceanFftCpu& fft = *ocean.cpu;
    const int n = fft.resolution();
    const float tile = float(fft.patchSize(0)), cell = tile / float(n), lambda = -ocean.def.choppiness;
    const float* jacobian = fft.channel(0, ocean::OceanChannel::Jacobian);
    const float* dx = fft.channel(0, ocean::OceanChannel::DispX);
    const float* dz = fft.channel(0, ocean::OceanChannel::DispZ);
    const ScrollingGrid& grid = foam.grid();
    const float side = float(grid.n) * grid.cell;
    const glm::vec2 lo = grid.origin(), centre = lo + glm::vec2(0.5f * side);
    const glm::vec2 first = centre - glm::vec2(0.5f * tile);  // the copy of the tile round the centre starts here
    crests.clear();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const size_t k = size_t(j) * size_t(n) + size_t(i);
            if (jacobian[k] >= law.j0) continue;
            glm::vec2 p = cell * glm::vec2(float(i), float(j)) + lambda * glm::vec2(dx[k], dz[k]);
            p -= tile * glm::floor((p - first) / tile);  // into that copy
            if (p.x >= lo.x && p.y >= lo.y && p.x < lo.x + side && p.y < lo.y + side) crests.push_back(p);
        }
    drops.emitWindSpray(crests, cell * cell, wind, dt, *ocean.water);
}

} // namespace

void addSplashFoam(ecs::World& world, const splash::SplashDef& splash, const foam::FoamDef& foam, uint64_t seed) {
    if (!splash.enabled && !foam.enabled) return;
    auto state = std::make_unique<SplashFoamState>();
    if (splash.enabled) state->particles = std::make_unique<splash::SplashParticles>(splash, seed);
    state->bowSpeed = splash.bow_speed;
    state->foamDef = foam;
    world.setResource(std::move(state));
}

void pipelineSplashFoam(ecs::World& world) {
    if (auto* state = world.resource<SplashFoamState>()) state->pipelined = true;
}

uint64_t foamSweepsOnWorker(ecs::World& world) {
    const auto* state = world.resource<SplashFoamState>();
    return state ? state->sweep.started() : 0;
}

void splashFoamSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* state = world.resource<SplashFoamState>();
    const OceanState* ocean = world.resource<OceanState>();
    if (!state || !ocean || !ocean->water) return;
    state->join();
    auto* patch = world.resource<interaction::RipplePatch>();
    const float dt = float(tick.dt);
    foam::FoamMap* foam = placeFoam(*state, patch);
    emitFromSources(world, *state, *ocean->water, tick.step, dt);
    if (foam) layWakeTrails(*state, *foam, tick.step, dt);
    // --- flight and landings: rain back on the ripples and the foam
    if (splash::SplashParticles* drops = state->particles.get()) {
        drops->step(dt, *ocean->water);
        if (patch) splash::stampLandings(*patch, drops->landings(), drops->def().ripple_energy);
        if (foam) foam->addLandings(drops->landings());
    }
    if (foam) stepFoam(*state, *foam, *ocean, patch, dt);
    if (foam && state->particles) sprayFromCrests(*state->particles, *foam, *ocean, state->crests, dt);
}

const splash::SplashParticles* splashParticles(ecs::World& world) {
    const auto* state = world.resource<SplashFoamState>();
    return state ? state->particles.get() : nullptr;
}

const foam::FoamMap* foamMap(ecs::World& world) {
    auto* state = world.resource<SplashFoamState>();
    if (!state) return nullptr;
    state->join();
    return state->foam.get();
}

void hashSplashFoam(ecs::World& world, StateHasher& h) {
    auto* state = world.resource<SplashFoamState>();
    if (!state) return;
    state->join();
    if (state->particles) state->particles->hash(h);
    if (state->foam) state->foam->hash(h);
}

} // namespace ob::game
