// Ocean simulation and its hand-over to the renderer.
#include "water_systems.h"

#include "core/log.h"
#include "gfx/gl.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/ocean_fft_gpu.h"
#include "ocean/ocean_textures.h"

namespace ob::game {

OceanState::~OceanState() = default;

void addOcean(ecs::World& world, const ocean::OceanDef& def) {
    auto state = std::make_unique<OceanState>();
    state->def = def;
    if (def.backend != "gpu") state->cpu = std::make_unique<ocean::OceanFftCpu>(def);
    world.setResource(std::move(state));
}

void attachOceanGpu(ecs::World& world) {
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean) return;
    ocean->textures = std::make_unique<ocean::OceanTextures>(ocean->def.resolution, ocean->def.cascades);
    // auto: the GPU where there is one; on a software rasteriser FFTW is faster.
    bool gpu = ocean->def.backend == "gpu" || (ocean->def.backend == "auto" && !gfx::isSoftwareRenderer());
    if (gpu && !ocean::OceanFftGpu::available()) {
        logWarn("ocean: compute shaders unavailable, using the CPU backend");
        gpu = false;
    }
    if (gpu) ocean->gpu = std::make_unique<ocean::OceanFftGpu>(ocean->def);
    if (!gpu && !ocean->cpu) ocean->cpu = std::make_unique<ocean::OceanFftCpu>(ocean->def);
    logInfo("ocean: %s backend, %d² × %d cascade(s)", gpu ? "gpu (compute shaders)" : "cpu (FFTW)", ocean->def.resolution,
            ocean->def.cascades);
}

void oceanSystem(ecs::World& world, const ecs::Tick& tick) {
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean || !ocean->cpu) return;
    // The state after this step is the state at its end time.
    ocean->mapsTime = tick.time + tick.dt;
    ocean->cpu->update(ocean->mapsTime);
}

gfx::WaterView prepareWaterView(ecs::World& world, double time) {
    gfx::WaterView view;
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean || !ocean->textures) return view;
    // The GPU backend synthesises at the render time; the CPU one uploads its latest step.
    double wanted = ocean->gpu ? time : ocean->mapsTime;
    if (wanted >= 0.0 && wanted != ocean->uploadedTime) {
        if (ocean->gpu) ocean->gpu->update(time, *ocean->textures);
        else ocean->textures->upload(*ocean->cpu);
        ocean->textures->generateMipmaps();
        ocean->uploadedTime = wanted;
    }
    view.displacement = &ocean->textures->displacement();
    view.slopes = &ocean->textures->slopes();
    view.cascades = ocean->def.cascades;
    view.resolution = ocean->def.resolution;
    for (int c = 0; c < ocean->def.cascades; ++c) view.cascadeSize[size_t(c)] = float(ocean::cascadePatchSize(ocean->def, c));
    view.lambda = -ocean->def.choppiness;
    view.gravity = ocean->def.gravity;
    return view;
}

} // namespace ob::game
