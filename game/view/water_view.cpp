// The water on the GPU and the renderer's view of it.
#include "view/water_view.h"

#include "core/log.h"
#include "foam/foam_map.h"
#include "foam/foam_whitecaps.h"
#include "gfx/gl.h"
#include "interaction/gpu/attach_gpu.h"
#include "interaction/ripple_patch.h"
#include "ocean/gpu/ocean_fft_gpu.h"
#include "ocean/gpu/ocean_textures.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_fft_cpu.h"
#include "sim/obstacles.h"
#include "sim/splash_foam_system.h"
#include "sim/water_systems.h"

namespace ob::game {

OceanGpu::~OceanGpu() = default;

void attachWaterGpu(ecs::World& world) {
    // The ripple patch: on the GPU when asked, or by auto where this machine measured its GPU twin
    // faster (interaction::gpuStepsFaster: at 256² on an H200 the CPU's step, 0.1 ms, beat the
    // GPU's stamps, step and read-back stall, 2.3 ms); on a software rasteriser the CPU, as the
    // ocean. The same switch for every model: its moveToGpu warns, and leaves it on the CPU, where
    // its GPU twin cannot run it. Levels: each on its own twin.
    if (auto* patch = world.resource<interaction::RipplePatch>()) {
        const Backend backend = patch->def().backend;
        const bool gpu = backend == Backend::Gpu ||
                         (backend == Backend::Auto && !gfx::isSoftwareRenderer() && interaction::gpuStepsFaster(patch->def()));
        if (gpu) interaction::attachGpu(*patch);
        logInfo("ripples: %s, %s backend, %d² cells of %g m", enumName(patch->def().model), patch->solver().backendName(),
                patch->def().resolution, double(patch->def().cell_size));
    }
    OceanState* ocean = world.resource<OceanState>();
    if (!ocean) return;
    OceanGpu& side = world.setResource(std::make_unique<OceanGpu>());
    side.textures = std::make_unique<ocean::OceanTextures>(ocean->def.resolution, ocean->def.cascades);
    // auto: the GPU where there is one; on a software rasteriser FFTW is faster.
    // Every platform's context is GL 4.5 core (compute shaders, fp64), or it fails to open.
    const bool gpu = ocean->def.backend == Backend::Gpu || (ocean->def.backend == Backend::Auto && !gfx::isSoftwareRenderer());
    if (gpu) {
        side.gpu = std::make_unique<ocean::OceanFftGpu>(ocean->def);
        if (!ocean->cpuNext) ocean->cpuNext = std::make_unique<ocean::OceanFftCpu>(ocean->def);
    }
    // The CPU backend's maps come with their texels, made where they are updated (a worker, pipelined).
    if (!gpu) ocean->cpu->setMakeTexels(true);
    logInfo("ocean: %s backend, %d² × %d cascade(s)", gpu ? "gpu (compute shaders)" : "cpu (FFTW)", ocean->def.resolution,
            ocean->def.cascades);
}

// Factor on the CPU maps' displacement extremes when the GPU renders another time.
constexpr float FFT_BOUND_SLACK = 1.1f;

// The far sea's whitecaps (shaders/common_foam.glsl) from the CPU maps, once per sea: J − 1 adds
// over the cascades to first order (their bands do not overlap, so their σ add in quadrature),
// and density ½ lies at the J that leaves the wind's whitecap share of the sea below it.
void readWhitecaps(OceanGpu& side, const OceanState& ocean) {
    if (side.whitecapVersion == ocean.seaVersion + 1) return;
    side.whitecapVersion = ocean.seaVersion + 1;
    const ocean::OceanFftCpu& fft = *ocean.cpu;
    const int n = fft.resolution();
    foam::JacobianStats sum;
    double variance = 0.0;
    for (int c = 0; c < ocean.def.cascades; ++c) {
        const foam::JacobianStats s = foam::jacobianStats(
            std::span(fft.channel(c, ocean::OceanChannel::Jacobian), size_t(n) * size_t(n)), n, float(fft.patchSize(c)));
        sum.mean += s.mean - 1.0;
        variance += s.sigma * s.sigma;
    }
    sum.sigma = std::sqrt(variance);
    const double j = foam::instantWhitecapJacobian(sum, ocean.def.wind_speed);
    side.whitecapSigma = std::isfinite(j) ? float(sum.sigma) : 0.0f;
    side.whitecapJacobian = std::isfinite(j) ? float(j) : 0.0f;
}

// The ocean's maps into the textures, once a step (CPU) or once a frame (GPU).
static void uploadOceanMaps(OceanGpu& gpuSide, const OceanState& ocean, double time) {
    // The GPU backend synthesises at the render time; the CPU one uploads its latest step.
    const double wanted = gpuSide.gpu ? time : ocean.mapsTime;
    // A live change's fade: the GPU synthesises from the CPU's blended h̃0 and λ (at the step's
    // end, within a step of the render time).
    if (gpuSide.gpu && gpuSide.seaVersion != ocean.seaVersion) {
        for (int c = 0; c < ocean.def.cascades; ++c) gpuSide.gpu->setSpectrum(c, ocean.cpu->spectrum(c));
        gpuSide.gpu->setLambda(ocean.cpu->lambda());
        gpuSide.seaVersion = ocean.seaVersion;
        gpuSide.uploadedTime = -1.0;
    }
    if (wanted >= 0.0 && wanted != gpuSide.uploadedTime) {
        if (gpuSide.gpu) {
            gpuSide.gpu->update(time, *gpuSide.textures);
            gpuSide.textures->generateMipmaps();
        } else if (const ocean::OceanTexels* texels = ocean.cpu->texels()) {
            gpuSide.textures->upload(*texels);  // interleaved and filtered beside the maps' update
        } else {
            gpuSide.textures->upload(*ocean.cpu);
            gpuSide.textures->generateMipmaps();
        }
        gpuSide.uploadedTime = wanted;
    }
}

gfx::WaterView prepareWaterView(ecs::World& world, double time) {
    gfx::WaterView view;
    view.hulls = hullClips(world);
    if (auto* patch = world.resource<interaction::RipplePatch>()) {
        view.ripples = patch->height().data();
        view.rippleCells = patch->def().resolution;
        view.rippleOrigin = patch->origin();
        view.rippleCellSize = patch->def().cell_size;
        for (int L = 1; L < patch->levelCount(); ++L) {  // the composite (docs/ewave.md#levels), its cubic in time on the GPU
            const interaction::LevelDraw d = patch->levelDraw(L);
            view.rippleLevels.push_back({{d.h0.data(), d.h1.data(), d.v0.data(), d.v1.data()}, d.version, d.weights, d.extremes, d.origin, d.cellSize});
        }
        view.rippleFadeCells = patch->fadeCells();
    }
    if (const foam::FoamMap* foam = foamMap(world)) {
        view.foam = foam->coverage().data();
        view.foamCells = foam->grid().n;
        view.foamOrigin = foam->grid().origin();
        view.foamCellSize = foam->grid().cell;
    }
    const OceanState* ocean = world.resource<OceanState>();
    OceanGpu* side = world.resource<OceanGpu>();
    if (!ocean || !side) return view;
    uploadOceanMaps(*side, *ocean, time);
    view.windAngle = std::atan2(ocean->def.wind_direction.y, ocean->def.wind_direction.x);
    const foam::FoamMap* foam = foamMap(world);
    if (ocean->mapsTime >= 0.0 && (!foam || foam->def().whitecap_from_wind)) {
        readWhitecaps(*side, *ocean);
        view.whitecapJacobian = side->whitecapJacobian;
        view.whitecapSigma = side->whitecapSigma;
    }
    view.displacement = &side->textures->displacement();
    view.slopes = &side->textures->slopes();
    view.cascades = ocean->def.cascades;
    view.resolution = ocean->def.resolution;
    for (int c = 0; c < ocean->def.cascades; ++c) view.cascadeSize[size_t(c)] = float(ocean::cascadePatchSize(ocean->def, c));
    // The cascades' mean square slopes: summed again when a spectrum key changes (a live sea).
    const ocean::OceanDef& d = ocean->def;
    const std::array<float, 6> sea{d.wind_speed, d.amplitude, d.small_wave_cutoff, d.fetch, d.peak_enhancement, float(d.spectrum)};
    if (sea != side->slopeSea) {
        for (int c = 0; c < d.cascades; ++c) side->slopeVariance[size_t(c)] = float(ocean::cascadeSlopeVariance(d, c));
        side->slopeSea = sea;
    }
    view.cascadeSlopeVariance = side->slopeVariance;
    view.seaSlopeVariance = float(ocean::coxMunkSlopeVariance(d.wind_speed));
    view.windSpeed = d.wind_speed;
    view.lambda = ocean->cpu->lambda();  // mid-fade: the blend
    view.gravity = ocean->def.gravity;
    // How far the grid must reach: the extremes of the CPU maps (at the step's end). The GPU
    // synthesises at the render time, up to a few steps from those maps; the extremes of the
    // whole tile change by far less than a tenth in that time, so a tenth more covers it.
    const ocean::DisplacementBounds fft = ocean->cpu->displacementBounds();
    view.fftBounds = {fft.up, fft.down, fft.horizontal};
    if (side->gpu && ocean->mapsTime != time) {
        view.fftBounds.up *= FFT_BOUND_SLACK;
        view.fftBounds.down *= FFT_BOUND_SLACK;
        view.fftBounds.horizontal *= FFT_BOUND_SLACK;
    }
    for (const ocean::GerstnerWave& w : ocean->waves) view.gerstner.emplace_back(w.kx, w.kz, w.amplitude, w.phase);
    return view;
}

} // namespace ob::game
