// The water's systems: the ocean, the ripple patch and its stamps, and the hand-over to the
// renderer.
#include "sim/water_systems.h"

#include "world/camera.h"
#include "core/log.h"
#include "foam/foam_map.h"
#include "ecs/components.h"
#include "gfx/gl.h"
#include "interaction/ewave_gpu.h"
#include "interaction/ripple_patch.h"
#include "interaction/sphere_set.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/ocean_fft_gpu.h"
#include "ocean/ocean_textures.h"
#include "sim/splash_foam_system.h"
#include "water/composite_water.h"

namespace ob::game {

OceanState::~OceanState() = default;

void addOcean(ecs::World& world, const ocean::OceanDef& def, const ocean::GerstnerDef& gerstner) {
    auto state = std::make_unique<OceanState>();
    state->def = def;
    state->waves = ocean::resolveWaves(gerstner, def);
    state->cpu = std::make_unique<ocean::OceanFftCpu>(def);
    state->water = std::make_unique<water::CompositeWater>(state->waves, def.gravity, state->cpu.get());
    state->cpu->update(0.0);
    state->water->update(0.0);
    state->mapsTime = 0.0;
    world.setResource(std::move(state));
}

void attachWaterGpu(ecs::World& world) {
    // The ripple patch: auto means the GPU where there is one (software rendering: the CPU).
    if (auto* patch = world.resource<interaction::RipplePatch>()) {
        const std::string& backend = patch->def().backend;
        // Auto: the CPU up to 1024² even beside a GPU, where its step (0.1 ms at 256², 0.3 ms at
        // 1024²) costs less than the GPU's stamps, step and read-back stall (2.3 ms and 4.3 ms
        // on an H200 in the default scene).
        // The same switch for both models: kang2008 RippleFieldGpu, ewave EWaveGpu.
        const bool gpu = backend == "gpu" || (backend == "auto" && !gfx::isSoftwareRenderer() && patch->def().resolution >= 2048);
        if (gpu && !patch->useGpu())
            logWarn("ripples: the ewave GPU field runs up to %d² cells; %d² runs on the CPU (FFTW)",
                    interaction::EWaveGpu::MAX_RESOLUTION, patch->def().resolution);
        logInfo("ripples: %s, %s backend, %d² cells of %g m", patch->def().model.c_str(),
                patch->onGpu() ? (patch->isEWave() ? "gpu (compute shaders, float FFT)" : "gpu (compute shaders)")
                                : (patch->isEWave() ? "cpu (FFTW)" : "cpu"), patch->def().resolution,
                double(patch->def().cell_size));
    }
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean) return;
    ocean->textures = std::make_unique<ocean::OceanTextures>(ocean->def.resolution, ocean->def.cascades);
    // auto: the GPU where there is one; on a software rasteriser FFTW is faster.
    bool gpu = ocean->def.backend == "gpu" || (ocean->def.backend == "auto" && !gfx::isSoftwareRenderer());
    if (gpu && !ocean::OceanFftGpu::available()) {
        logWarn("ocean: compute shaders unavailable, using the CPU backend");
        gpu = false;
    }
    if (gpu) {
        ocean->gpu = std::make_unique<ocean::OceanFftGpu>(ocean->def);
        ocean->cpuNext = std::make_unique<ocean::OceanFftCpu>(ocean->def);
    }
    logInfo("ocean: %s backend, %d² × %d cascade(s)", gpu ? "gpu (compute shaders)" : "cpu (FFTW)", ocean->def.resolution,
            ocean->def.cascades);
}

void oceanSystem(ecs::World& world, const ecs::Tick& tick) {
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean) return;
    // The state after this step is the state at its end time.
    ocean->mapsTime = tick.end;
    if (ocean->prefetch.valid()) ocean->prefetch.get();
    if (ocean->cpuNext && ocean->prefetchTime == ocean->mapsTime) {
        std::swap(ocean->cpu, ocean->cpuNext);
        ocean->water->setFft(ocean->cpu.get());
    } else {
        ocean->cpu->update(ocean->mapsTime);
    }
    ocean->water->update(ocean->mapsTime);
    if (ocean->cpuNext) {
        // The next step's end time as the schedule will compute it (step / rate + step length);
        // should the bits differ, the next step computes its maps itself.
        ocean->prefetchTime = double(tick.step + 1) / (1.0 / tick.dt) + tick.dt;
        ocean->prefetch = std::async(std::launch::async, [fft = ocean->cpuNext.get(), t = ocean->prefetchTime] { fft->update(t); });
    }
}

void addRipples(ecs::World& world, const interaction::RippleDef& def, float stepSeconds) {
    if (!def.enabled) return;
    auto& patch = world.setResource(std::make_unique<interaction::RipplePatch>(def));
    // The query adds the ripple layer at the displaced position, as the renderer does.
    if (OceanState* ocean = world.resource<OceanState>()) {
        const float dt = stepSeconds;
        ocean->water->setRipple({[&patch](float x, float z) { return patch.heightAt({x, z}); },
                                 [&patch, dt](float x, float z) { return patch.velocityAt({x, z}, dt); }, {}, 0.5f * def.cell_size});
    }
}

void interactionSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* patch = world.resource<interaction::RipplePatch>();
    const OceanState* ocean = world.resource<OceanState>();
    if (!patch || !ocean) return;
    if (patch->def().follow != "fixed") {
        auto& rigs = world.pool<CameraRig>();
        if (rigs.size() > 0) {
            glm::vec3 at = patch->def().follow == "target" ? rigs.components()[0].focus
                                                           : world.get<ecs::Transform>(rigs.entities()[0]).position;
            patch->centerOn(glm::vec2(at.x, at.z));
        }
    }
    // --- stamps, in entity then sphere order (overlaps: the later sphere wins)
    auto& sets = world.pool<interaction::SphereSet>();
    for (size_t i = 0; i < sets.size(); ++i) {
        ecs::Entity e = sets.entities()[i];
        interaction::SphereSet& set = sets.components()[i];
        const ecs::Transform* transform = world.find<ecs::Transform>(e);
        if (!transform) continue;
        const ecs::Motion* motion = world.find<ecs::Motion>(e);
        glm::vec3 velocity = motion ? motion->velocity : glm::vec3(0.0f);
        float mass = motion ? motion->mass : 1.0f;
        set.contacts.resize(set.spheres.size());
        for (size_t k = 0; k < set.spheres.size(); ++k) {
            glm::vec3 centre = transform->position + transform->rotation * set.spheres[k].offset;
            // Table 2 measures contact against the whole surface (every layer), as rendered.
            float surface = ocean->water->sample(centre.x, centre.z).height;
            patch->stampSphere(set.spheres[k], set.contacts[k], centre, velocity, mass, surface);
        }
    }
    // --- the solver's step: eq. 1–2 (kang2008) or the exact per-mode step over dt (ewave)
    patch->step(float(tick.dt));
}

// Factor on the CPU maps' displacement extremes when the GPU renders another time.
constexpr float FFT_BOUND_SLACK = 1.1f;

gfx::WaterView prepareWaterView(ecs::World& world, double time) {
    gfx::WaterView view;
    if (auto* patch = world.resource<interaction::RipplePatch>()) {
        view.ripples = patch->height().data();
        view.rippleCells = patch->def().resolution;
        view.rippleOrigin = patch->origin();
        view.rippleCellSize = patch->def().cell_size;
    }
    if (const foam::FoamMap* foam = foamMap(world)) {
        view.foam = foam->coverage().data();
        view.foamCells = foam->resolution();
        view.foamOrigin = foam->origin();
        view.foamCellSize = foam->cellSize();
    }
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
    // How far the grid must reach: the extremes of the CPU maps (at the step's end). The GPU
    // synthesises at the render time, up to a few steps from those maps; the extremes of the
    // whole tile change by far less than a tenth in that time, so a tenth more covers it.
    view.fftBounds = ocean->cpu->displacementBounds();
    if (ocean->gpu && ocean->mapsTime != time) {
        view.fftBounds.up *= FFT_BOUND_SLACK;
        view.fftBounds.down *= FFT_BOUND_SLACK;
        view.fftBounds.horizontal *= FFT_BOUND_SLACK;
    }
    for (const ocean::GerstnerWave& w : ocean->waves) view.gerstner.emplace_back(w.kx, w.kz, w.amplitude, w.phase);
    return view;
}

} // namespace ob::game
