// The water's systems: the spectral ocean in the ocean phase, and what the render phase
// hands the renderer (textures on the GPU, Gerstner waves).
#pragma once
#include "ecs/schedule.h"
#include "gfx/renderer.h"
#include "ocean/ocean_def.h"

#include <memory>

namespace ob::ocean {
class OceanFftCpu;
class OceanFftGpu;
class OceanTextures;
}

namespace ob::game {

/// The ocean resource: simulation state, and its GPU side once a context is attached.
struct OceanState {
    ocean::OceanDef def;
    std::unique_ptr<ocean::OceanFftCpu> cpu;       ///< FFTW maps (the CPU backend, and WaterQuery's data)
    double mapsTime = -1.0;                        ///< time of the CPU maps (s)
    // GPU side (null in a pure simulation)
    std::unique_ptr<ocean::OceanTextures> textures;
    std::unique_ptr<ocean::OceanFftGpu> gpu;       ///< set when the GPU backend renders
    double uploadedTime = -1.0;                    ///< time of the maps in the textures (s)
    ~OceanState();
};

/// Creates the ocean resource from the scene's [ocean].
void addOcean(ecs::World& world, const ocean::OceanDef& def);
/// Creates the textures and, per [ocean] backend, the GPU FFT (needs a current GL context).
void attachOceanGpu(ecs::World& world);
/// Ocean phase: the CPU maps at the end of this step.
void oceanSystem(ecs::World& world, const ecs::Tick& tick);
/// Render phase helper: brings the textures to `time` and describes the water layers.
gfx::WaterView prepareWaterView(ecs::World& world, double time);

} // namespace ob::game
