// The water's systems: the ocean and the ripple patch with its stamps.
#include "sim/water_systems.h"

#include "core/log.h"
#include "core/thread_cpu.h"
#include "currents/current_layer.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "sim/obstacles.h"
#include "sim/stamp_sources.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_fft_cpu.h"
#include "sim/splash_foam_system.h"
#include "water/composite_water.h"

namespace ob::game {

OceanState::~OceanState() = default;

void addOcean(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner) {
    auto state = std::make_unique<OceanState>();
    state->def = def;
    state->gerstner = gerstner;
    state->waves = ocean::resolveWaves(gerstner, def);
    state->cpu = std::make_unique<ocean::OceanFftCpu>(def);
    state->water = std::make_unique<water::CompositeWater>(state->waves, def.gravity, state->cpu.get());
    state->cpu->update(0.0);
    state->water->update(0.0);
    state->mapsTime = 0.0;
    world.setResource(std::move(state));
}

void pipelineWater(ecs::World& world) {
    if (OceanState* ocean = world.resource<OceanState>()) ocean->pipelined = true;
    if (auto* patch = world.resource<interaction::RipplePatch>()) patch->setPipelined(true);
    if (auto* layer = world.resource<currents::CurrentLayer>()) layer->setPipelined(true);  // beside the ripples' step
    pipelineSplashFoam(world);
}

void changeSea(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner,
               std::vector<ocean::GerstnerWave> waves, double now) {
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean) return;
    // Only the live keys change; the rest is what the maps were built with.
    ocean::OceanDef next = ocean->def;
    next.spectrum = def.spectrum;
    next.amplitude = def.amplitude;
    next.wind_speed = def.wind_speed;
    next.wind_direction = def.wind_direction;
    next.small_wave_cutoff = def.small_wave_cutoff;
    next.choppiness = def.choppiness;
    next.fetch = def.fetch;
    next.peak_enhancement = def.peak_enhancement;
    ocean->def = next;
    ocean->gerstner = gerstner;
    ocean->changed = true;
    ocean->changeTime = now;
    ocean->changeWaves = std::move(waves);
}

void oceanSystem(ecs::World& world, const ecs::Tick& tick) {
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean) return;
    // The state after this step is the state at its end time.
    ocean->mapsTime = tick.end;
    ocean->prefetch.join();
    // --- a live change: one fade from the sea as last computed (mid-fade: the blend); the
    // prefetched maps (made before the change) are thrown away
    if (ocean->changed) {
        ocean->fade = std::make_unique<ocean::SeaFade>(*ocean->cpu, ocean->waves, ocean->def, std::move(ocean->changeWaves),
                                                       ocean->changeTime);
        ocean->changed = false;
        ocean->prefetchTime = -1.0;
    }
    // --- the fade's blend at the maps' time; it runs on until both map buffers (cpu, cpuNext)
    // hold the new sea
    const bool fading = ocean->fade && tick.time <= ocean->fade->end() + 2.0 * tick.dt;
    const bool prefetched = ocean->cpuNext && ocean->prefetchTime == ocean->mapsTime;
    if (fading) {
        if (!prefetched) ocean->fade->apply(*ocean->cpu, ocean->mapsTime);  // a prefetched buffer took it before its update
        ocean->waves = ocean->fade->waves(ocean->mapsTime);
        ocean->water->setWaves(ocean->waves, ocean->def.gravity);
        ocean->water->measureWavenumbers();
        ++ocean->seaVersion;
    }
    // The velocity bands' maps (docs/velocity_bands.md) only while bodies may read the
    // water's velocity under the surface.
    const bool bands = world.pool<Body>().size() > 0;
    for (ocean::OceanFftCpu* fft : {ocean->cpu.get(), ocean->cpuNext.get()})
        if (fft) fft->setVelocityBands(bands);
    if (ocean->cpuNext && ocean->prefetchTime == ocean->mapsTime) {
        std::swap(ocean->cpu, ocean->cpuNext);
        ocean->water->setFft(ocean->cpu.get());
    } else {
        ocean->cpu->update(ocean->mapsTime);
    }
    ocean->water->update(ocean->mapsTime);
    if (ocean->pipelined && !ocean->cpuNext) {
        // The second buffer from the sea as the first step has it (a spectrum written since the
        // world was made, by a test or a tool, included): the next steps' maps are its maps.
        ocean->cpuNext = std::make_unique<ocean::OceanFftCpu>(ocean->def);
        for (int c = 0; c < ocean->def.cascades; ++c) ocean->cpuNext->spectrum(c) = ocean->cpu->spectrum(c);
        ocean->cpuNext->setMakeTexels(ocean->cpu->makesTexels());
    }
    if (ocean->cpuNext) {
        // The next step's end time as the schedule will compute it (step / rate + step length);
        // should the bits differ, the next step computes its maps itself.
        ocean->prefetchTime = double(tick.step + 1) / (1.0 / tick.dt) + tick.dt;
        if (fading) ocean->fade->apply(*ocean->cpuNext, ocean->prefetchTime);
        ocean->prefetch.start([fft = ocean->cpuNext.get(), t = ocean->prefetchTime] { fft->update(t); });
    }
}

void addRipples(ecs::World& world, const interaction::RippleDef& def, float stepSeconds) {
    if (!def.enabled) return;
    auto& patch = world.setResource(std::make_unique<interaction::RipplePatch>(def));
    // The query adds the ripple layer at the displaced position, as the renderer does.
    if (OceanState* ocean = world.resource<OceanState>()) {
        const float dt = stepSeconds;
        ocean->water->setRipple({[&patch](float x, float z) { return patch.heightAt({x, z}); },
                                 [&patch, dt](float x, float z) { return patch.velocityAt({x, z}, dt); }, {}, 0.5f * def.cell_size,
                                 [&patch](float x, float z) { return patch.horizontalVelocityAt({x, z}); },
                                 [&patch] { return patch.velocityWavenumber(); }});
    }
}

void interactionSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* patch = world.resource<interaction::RipplePatch>();
    const OceanState* ocean = world.resource<OceanState>();
    if (!patch || !ocean) return;
    // --- stamps, source, entity then sphere order (overlaps: the later sphere wins)
    // Heights only: the current layer has none (and, pipelined, is stepping on a worker now).
    water::WaterLayers surface;
    surface.currents = false;
    forEachSphere(world, SphereUse::Stamp, [&](const PlacedSphere& p) {
        // Table 2 measures contact against the whole surface (every layer), as rendered.
        const float height = ocean->water->sample(p.centre.x, p.centre.z, surface).height;
        return patch->stampSphere(*p.sphere, *p.contact, p.centre, p.velocity, p.stampMass, height);
    });
    // --- the bodies that cut the surface obstruct the step (fixed bodies, hulls; none: no change)
    patch->setObstacles(obstacleFootprints(world, ocean->water.get()));
    // --- the solver's step: eq. 1–2 (kang2008) or the exact per-mode step over dt (ewave)
    patch->step(float(tick.dt));
}

} // namespace ob::game
