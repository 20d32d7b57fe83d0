// The water's systems: the spectral ocean in the ocean phase, the ripple patch in the
// interaction phase. (What the renderer gets of them, and the GPU twins: view/water_view.h.)
#pragma once
#include "ecs/schedule.h"
#include "interaction/ripple_def.h"
#include "ocean/ocean_def.h"

#include <future>
#include <memory>
#include <vector>

namespace ob::ocean {
class OceanFftCpu;
struct GerstnerDef;
struct GerstnerWave;
}
namespace ob::water {
class CompositeWater;
}

namespace ob::game {

/// The ocean resource: the simulation state. The CPU maps always exist: they are the water
/// physics queries (zero latency), whichever backend renders (view/water_view.h: OceanGpu).
struct OceanState {
    ocean::OceanDef def;
    std::vector<ocean::GerstnerWave> waves;        ///< explicit + spectrum-generated Gerstner waves
    std::unique_ptr<ocean::OceanFftCpu> cpu;       ///< FFTW maps (the CPU backend, and the query's data)
    /// With the GPU backend the query's maps of the next step are computed on another thread
    /// while this frame renders (the step times are known ahead); null otherwise.
    std::unique_ptr<ocean::OceanFftCpu> cpuNext;
    std::future<void> prefetch;                    ///< cpuNext->update(prefetchTime) in flight
    double prefetchTime = -1.0;
    std::unique_ptr<water::CompositeWater> water;  ///< the WaterQuery: Gerstner + cascades + ripples
    double mapsTime = -1.0;                        ///< time of the CPU maps (s)
    ~OceanState();
};

/// Creates the ocean resource from the scene's [ocean] and [gerstner].
void addOcean(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner);
/// Ocean phase: the CPU maps at the end of this step.
void oceanSystem(ecs::World& world, const ecs::Tick& tick);
/// Creates the ripple patch resource from the scene's [ripples] (nothing when disabled) and
/// adds it to the ocean's query; stepSeconds: the simulation step (s).
void addRipples(ecs::World& world, const interaction::RippleDef& def, float stepSeconds);
/// Interaction phase: every stamp source's spheres stamp the ripple patch (sim/stamp_sources.h;
/// Table 2), then the solver's step (seed 001 eq. 1–7, or the ewave step and its sources).
void interactionSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
