// The water's systems: the spectral ocean in the ocean phase, the ripple patch in the
// interaction phase. (What the renderer gets of them, and the GPU twins: view/water_view.h.)
#pragma once
#include "core/worker_task.h"
#include "ecs/schedule.h"
#include "interaction/ripple_def.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_def.h"
#include "ocean/sea_fade.h"

#include <memory>
#include <vector>

namespace ob::ocean {
class OceanFftCpu;
}
namespace ob::water {
class CompositeWater;
}

namespace ob::game {

/// The ocean resource: the simulation state. The CPU maps always exist: they are the water
/// physics queries (zero latency), whichever backend renders (view/water_view.h: OceanGpu).
struct OceanState {
    ocean::OceanDef def;                           ///< the sea now (after a live change: the one it fades to)
    ocean::GerstnerDef gerstner;                   ///< the [gerstner] of `def`
    std::vector<ocean::GerstnerWave> waves;        ///< explicit + spectrum-generated Gerstner waves (mid-fade: the blend)
    /// A live change of the sea (changeSea) is applied once, at the next ocean phase, whatever
    /// the number of keys set in the step: one new spectrum built, one fade started.
    bool changed = false;
    double changeTime = 0.0;                       ///< start of the step that set the change, s
    std::vector<ocean::GerstnerWave> changeWaves;  ///< the change's Gerstner waves (resolveWaves)
    std::unique_ptr<ocean::SeaFade> fade;          ///< the cross-fade running (kept after its end: null only before the first change)
    std::uint64_t seaVersion = 0;                  ///< counts the steps a fade changed h̃0, λ or the waves (the GPU twin follows)
    std::unique_ptr<ocean::OceanFftCpu> cpu;       ///< FFTW maps (the CPU backend, and the query's data)
    /// With the GPU backend or [sim] pipelined the query's maps of the next step are computed on
    /// another thread while this frame renders (the step times are known ahead); null otherwise.
    std::unique_ptr<ocean::OceanFftCpu> cpuNext;
    WorkerTask prefetch;                           ///< cpuNext->update(prefetchTime) in flight
    bool pipelined = false;                        ///< [sim] pipelined: cpuNext made at the first step (pipelineWater)
    double prefetchTime = -1.0;
    std::unique_ptr<water::CompositeWater> water;  ///< the WaterQuery: Gerstner + cascades + ripples
    double mapsTime = -1.0;                        ///< time of the CPU maps (s)
    ~OceanState();
};

/// Creates the ocean resource from the scene's [ocean] and [gerstner].
void addOcean(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner);
/// Ocean phase: the CPU maps at the end of this step (a live change's fade applied first).
void oceanSystem(ecs::World& world, const ecs::Tick& tick);
/// A live change of [ocean]/[gerstner] in the step starting at `now` s: from the next ocean
/// phase on the sea cross-fades (ocean/sea_fade.h) from what it is to `def` and `gerstner`
/// over ocean::SEA_FADE_SECONDS. Keys read once at start (resolution, patch size, cascades,
/// gravity, backend) keep their values.
/// `waves`: resolveWaves(gerstner, def), checked by the caller.
void changeSea(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner,
               std::vector<ocean::GerstnerWave> waves, double now);
/// [sim] pipelined: the ocean's maps of the next step computed on another thread while the frame
/// goes on (a second map buffer, OceanState::cpuNext, made at the first ocean step), the ripple patch's coarse levels
/// stepped on a worker (RipplePatch::setPipelined) and the foam's sweep on another (pipelineSplashFoam: call it
/// after addSplashFoam). The state is the same bits.
void pipelineWater(ecs::World& world);
/// Creates the ripple patch resource from the scene's [ripples] (nothing when disabled) and
/// adds it to the ocean's query; stepSeconds: the simulation step (s).
void addRipples(ecs::World& world, const interaction::RippleDef& def, float stepSeconds);
/// Interaction phase: every stamp source's spheres stamp the ripple patch (sim/stamp_sources.h;
/// Table 2), the obstacles' footprints are handed to it (sim/obstacles.h), then the solver's
/// step ([Kang2008] eq. 1–7, or the ewave step and its sources), obstructed where they are.
void interactionSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
