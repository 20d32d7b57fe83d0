// The water's systems: the spectral ocean in the ocean phase, and what the render phase
// hands the renderer (textures on the GPU, Gerstner waves).
#pragma once
#include "ecs/schedule.h"
#include "gfx/renderer.h"
#include "interaction/ripple_def.h"
#include "ocean/ocean_def.h"

#include <future>
#include <memory>
#include <vector>

namespace ob::ocean {
class OceanFftCpu;
class OceanFftGpu;
class OceanTextures;
struct GerstnerDef;
struct GerstnerWave;
}
namespace ob::water {
class CompositeWater;
}

namespace ob::game {

/// The ocean resource: simulation state, and its GPU side once a context is attached.
/// The CPU maps always exist: they are the water physics queries (zero latency), whichever
/// backend renders.
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
    // GPU side (null in a pure simulation)
    std::unique_ptr<ocean::OceanTextures> textures;
    std::unique_ptr<ocean::OceanFftGpu> gpu;       ///< set when the GPU backend renders
    double uploadedTime = -1.0;                    ///< time of the maps in the textures (s)
    ~OceanState();
};

/// Creates the ocean resource from the scene's [ocean] and [gerstner].
void addOcean(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner);
/// Creates the textures and, per [ocean] and [ripples] backend, the GPU FFT and the GPU
/// ripple field (needs a current GL context).
void attachWaterGpu(ecs::World& world);
/// Ocean phase: the CPU maps at the end of this step.
void oceanSystem(ecs::World& world, const ecs::Tick& tick);
/// Creates the ripple patch resource from the scene's [ripples] (nothing when disabled) and
/// adds it to the ocean's query; stepSeconds: the simulation step (s).
void addRipples(ecs::World& world, const interaction::RippleDef& def, float stepSeconds);
/// Interaction phase: every SphereSet stamps the ripple patch (entity, then sphere order;
/// Table 2), then the solver's step (seed 001 eq. 1–7, or the ewave step and its sources).
void interactionSystem(ecs::World& world, const ecs::Tick& tick);
/// Render phase helper: brings the textures to `time` and describes the water layers.
gfx::WaterView prepareWaterView(ecs::World& world, double time);

} // namespace ob::game
