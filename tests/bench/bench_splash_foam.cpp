// Splash particles and the foam map: one step of N live drops (flight, landing scan, water
// queries) and one foam update at N² cells per flow kind, by worker count; the foam sources;
// the renderer drawing N drops and the foam map (OSMesa).
#include "core/log.h"
#include "core/parallel.h"
#include "foam/foam_map.h"
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_fft_cpu.h"
#include "platform/platform.h"
#include "splash/splash_particles.h"
#include "water/composite_water.h"
#include "water/water_query.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <vector>

namespace {

constexpr float DT = 1.0f / 60.0f;

// One step of N airborne drops over a sea far below (none lands, so N stays). Args: drops,
// workers, queried (0: the ceiling is under every drop, no water query; 1: every descending
// drop reads the water, the worst case).
void BM_SplashStep(benchmark::State& state) {
    const int n = int(state.range(0));
    ob::setWorkerCount(int(state.range(1)));
    const bool queried = state.range(2) != 0;
    ob::splash::SplashDef def;
    def.max_particles = n;
    def.max_life = 1e6f;
    ob::splash::SplashParticles particles(def, 1);
    ob::splash::Impact impact;
    impact.velocity = glm::vec3(0.0f, -30.0f, 0.0f);
    impact.radius = 1.0f;
    impact.mass = 1e9f;  // far more drops than n: the cap fills it
    particles.emitImpact(impact);
    const ob::water::FlatWater sea(-1e9f);
    const float ceiling = queried ? 3.4e38f : -2e9f;
    for (int s = 0; s < 120; ++s) particles.step(DT, sea, ceiling);  // 2 s: every drop descends
    for (auto _ : state) {
        particles.step(DT, sea, ceiling);
        benchmark::DoNotOptimize(particles.y().data());
    }
    if (particles.size() != n) state.SkipWithError("drops were lost");
    state.SetItemsProcessed(state.iterations() * n);
    ob::setWorkerCount(0);
}
BENCHMARK(BM_SplashStep)
    ->ArgNames({"drops", "workers", "queried"})
    ->ArgsProduct({{10000, 100000, 1000000}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One FoamMap::step at N² cells. Args: N, flow (0 still: decay only; 1 uniform; 2 per-cell
// field; 3 per cell from a 32² velocity grid's nodes), workers. The map is refilled (not timed) now and then so it never turns subnormal.
void BM_FoamStep(benchmark::State& state) {
    const int n = int(state.range(0));
    const int flow = int(state.range(1));
    ob::setWorkerCount(int(state.range(2)));
    ob::foam::FoamDef def;
    def.resolution = n;
    def.whitecap_from_wind = false;  // the given threshold: the same work every run
    ob::foam::FoamMap map(def, 64.0f);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> start(map.coverage().size());
    for (float& f : start) f = u(rng);
    const auto refill = [&] { std::copy(start.begin(), start.end(), map.coverage().begin()); };
    refill();
    if (flow == 1) map.flow().setUniform(glm::vec2(0.8f, -0.3f));
    if (flow == 2) {
        std::span<float> ux = map.flow().velocityX(), uz = map.flow().velocityZ();
        for (size_t c = 0; c < ux.size(); ++c) {
            ux[c] = 0.8f + 0.3f * std::sin(float(c % size_t(n)) * 0.1f);
            uz[c] = -0.3f + 0.3f * std::cos(float(c / size_t(n)) * 0.1f);
        }
    }
    if (flow == 3) {  // the same field on the default 32² velocity grid (what the sandbox uses)
        const int m = map.flow().nodesPerSide(), stride = map.flow().stride();
        std::vector<glm::vec2> nodes(size_t(m) * size_t(m));
        for (int l = 0; l < m; ++l)
            for (int k = 0; k < m; ++k)
                nodes[size_t(l) * size_t(m) + size_t(k)] = glm::vec2(0.8f + 0.3f * std::sin(float(k * stride) * 0.1f),
                                                                     -0.3f + 0.3f * std::cos(float(l * stride) * 0.1f));
        map.flow().setNodes(nodes);
    }
    map.step(DT);  // warm-up: starts the pool's workers
    int steps = 0;
    for (auto _ : state) {
        if (++steps == 600) {
            state.PauseTiming();
            refill();
            steps = 0;
            state.ResumeTiming();
        }
        map.step(DT);
        benchmark::DoNotOptimize(map.coverage().data());
    }
    state.SetItemsProcessed(state.iterations() * int64_t(n) * n);
    ob::setWorkerCount(0);
}
BENCHMARK(BM_FoamStep)
    ->ArgNames({"N", "flow", "workers"})
    ->ArgsProduct({{256, 512, 1024}, {0, 1, 2, 3}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The default scene's kind of sea: two 256² cascades of 250 m and 95 m in a 16 m/s wind.
ob::ocean::OceanDef defaultSceneSea() {
    ob::ocean::OceanDef od;
    od.resolution = 256;
    od.patch_size = 250.0f;
    od.wind_speed = 16.0f;
    od.wind_direction = {1.0f, 0.6f};
    od.choppiness = 1.2f;
    od.cascades = 2;
    return od;
}

// Its 8 Gerstner waves.
std::vector<ob::ocean::GerstnerWave> defaultSceneSwell(const ob::ocean::OceanDef& od) {
    ob::ocean::GerstnerDef gd;
    gd.count = 8;
    gd.seed = 7;
    return ob::ocean::resolveWaves(gd, od);
}

// The foam's velocity over the default scene's sea (8 Gerstner waves, two 256² cascades of
// 250 m and 95 m) at the (F + 1)² nodes of the velocity grid of a map 102.4 m across:
// CompositeWater::horizontalVelocityBatch (rest points by Newton, then the particles'
// velocities). Args: N, F, workers.
void BM_FoamVelocity(benchmark::State& state) {
    const int n = int(state.range(0));
    ob::setWorkerCount(int(state.range(2)));
    const ob::ocean::OceanDef od = defaultSceneSea();
    const std::vector<ob::ocean::GerstnerWave> waves = defaultSceneSwell(od);
    ob::ocean::OceanFftCpu fft(od, 1);
    ob::water::CompositeWater water(waves, od.gravity, &fft);
    ob::water::primeAt(&fft, water, 10.0);
    ob::foam::FoamDef def;
    def.resolution = n;
    def.flow_resolution = int(state.range(1));
    ob::foam::FoamMap map(def, 102.4f, glm::vec2(3.0f, -7.0f));
    const std::vector<glm::vec2> nodes = map.flow().nodePositions();
    std::vector<glm::vec2> velocity(nodes.size());
    water.horizontalVelocityBatch(nodes, velocity);
    for (auto _ : state) {
        water.horizontalVelocityBatch(nodes, velocity);
        benchmark::DoNotOptimize(velocity.data());
    }
    ob::setWorkerCount(0);
}
BENCHMARK(BM_FoamVelocity)
    ->ArgNames({"N", "F", "workers"})
    ->ArgsProduct({{512}, {16, 32, 64}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The foam sources at N² cells: 0 whitecaps from a 256² Jacobian tile, 1 steep ripples from a
// 256² patch, 2 a ship's 6 hull spheres of the wake. Args: N, source, workers.
void BM_FoamSources(benchmark::State& state) {
    const int n = int(state.range(0));
    const int source = int(state.range(1));
    ob::setWorkerCount(int(state.range(2)));
    ob::foam::FoamDef def;
    def.resolution = n;
    def.whitecap_from_wind = false;  // the given threshold: the same work every run
    ob::foam::FoamMap map(def, 64.0f);
    std::vector<float> jacobian(256 * 256);
    for (size_t c = 0; c < jacobian.size(); ++c) jacobian[c] = std::sin(float(c) * 0.01f);
    ob::interaction::RippleDef rd;
    ob::interaction::RipplePatch patch(rd);
    // Steep ripples over the whole patch, whichever the model (the default's height).
    for (int z = 0; z < patch.rows(); ++z)
        for (int x = 0; x < patch.cols(); ++x)
            patch.solver().addHeight(x, z, 0.05 * std::sin(double(z * patch.cols() + x) * 0.3));
    for (auto _ : state) {
        if (source == 0) map.addSources({jacobian, 256, 100.0f}, DT);
        if (source == 1) map.addSources({.ripples = &patch}, DT);  // the ripples alone
        if (source == 2)
            for (int s = 0; s < 6; ++s) map.addWake(glm::vec3(float(s) * 1.5f, 0.0f, 0.0f), glm::vec3(6.0f, 0.0f, 0.0f), 1.75f, DT);
        benchmark::DoNotOptimize(map.coverage().data());
    }
    ob::setWorkerCount(0);
}
BENCHMARK(BM_FoamSources)
    ->ArgNames({"N", "source", "workers"})
    ->ArgsProduct({{256, 512}, {0, 1, 2}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The whole per-step foam update of the default and ship scenes, as the sandbox makes it: a 512²
// map over 102.4 m on the default scene's sea (8 Gerstner waves, two 256² cascades), a 256²
// ripple patch of 0.2 m cells with steep ripples, a ship's 6 hull spheres' wake; whitecaps
// from the first cascade's Jacobian, steep ripples, the velocity grid (32² intervals), the
// step. The ocean advances by one step between updates (not timed). Args: workers.
struct FoamScene {
    ob::ocean::OceanDef od;
    std::vector<ob::ocean::GerstnerWave> waves;
    std::unique_ptr<ob::ocean::OceanFftCpu> fft;
    std::unique_ptr<ob::water::CompositeWater> water;
    std::unique_ptr<ob::interaction::RipplePatch> patch;
    std::unique_ptr<ob::foam::FoamMap> map;
    double t = 10.0;
    FoamScene() : od(defaultSceneSea()), waves(defaultSceneSwell(od)) {
        fft = std::make_unique<ob::ocean::OceanFftCpu>(od, 1);
        water = std::make_unique<ob::water::CompositeWater>(waves, od.gravity, fft.get());
        ob::water::primeAt(fft.get(), *water, t);
        ob::interaction::RippleDef rd;
        rd.model = ob::interaction::rippleModel("kang2008");  // its field is written directly here
        rd.resolution = 256;
        rd.cell_size = 0.2f;
        patch = std::make_unique<ob::interaction::RipplePatch>(rd);
        std::span<float> h = patch->solverAs<ob::interaction::Kang2008Solver>()->field().current();
        for (int z = 0; z < 256; ++z)
            for (int x = 0; x < 256; ++x) h[size_t(z) * 256 + size_t(x)] = 0.05f * std::sin(float(x) * 0.9f) * std::cos(float(z) * 0.7f);
        ob::foam::FoamDef def;
        def.resolution = 512;
        def.whitecap_from_wind = false;
        const glm::vec2 centre = patch->origin() + glm::vec2(0.5f * 256.0f * 0.2f);
        map = std::make_unique<ob::foam::FoamMap>(def, 102.4f, centre);
    }
    void advance() {
        t += DT;
        fft->update(t);
        water->update(t);
    }
    void wake() {
        for (int s = 0; s < 6; ++s) map->addWake(glm::vec3(float(s) * 1.5f, 0.0f, 0.0f), glm::vec3(6.0f, 0.0f, 0.0f), 1.75f, DT);
    }
};

void BM_FoamUpdateCalls(benchmark::State& state) {
    ob::setWorkerCount(int(state.range(0)));
    FoamScene scene;
    ob::foam::FoamMap& map = *scene.map;
    const int n = scene.fft->resolution();
    std::vector<glm::vec2> nodes, velocity;
    const auto update = [&] {
        scene.wake();
        map.addSources({std::span(scene.fft->channel(0, ob::ocean::OceanChannel::Jacobian), size_t(n) * size_t(n)), n,
                        float(scene.fft->patchSize(0))},
                       DT);
        map.addSources({.ripples = scene.patch.get()}, DT);  // the ripples alone
        nodes = map.flow().nodePositions();
        velocity.resize(nodes.size());
        scene.water->horizontalVelocityBatch(nodes, velocity);
        map.flow().setNodes(velocity);
        map.step(DT);
    };
    update();  // warm-up: starts the pool's workers
    for (auto _ : state) {
        state.PauseTiming();
        scene.advance();
        state.ResumeTiming();
        update();
        benchmark::DoNotOptimize(map.coverage().data());
    }
    ob::setWorkerCount(0);
}
BENCHMARK(BM_FoamUpdateCalls)->ArgNames({"workers"})->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same update in one call, FoamMap::update (one sweep; a K-th of the velocity grid's node
// rows evaluated a step, K = flow_refresh_steps). Args: workers, K.
void BM_FoamUpdate(benchmark::State& state) {
    ob::setWorkerCount(int(state.range(0)));
    FoamScene scene;
    ob::foam::FoamMap& map = *scene.map;
    ob::foam::FoamDef def = map.def();
    def.flow_refresh_steps = int(state.range(1));
    map.setDef(def);
    const int n = scene.fft->resolution();
    const auto update = [&] {
        scene.wake();
        ob::foam::FoamInputs in;
        in.jacobian = std::span(scene.fft->channel(0, ob::ocean::OceanChannel::Jacobian), size_t(n) * size_t(n));
        in.jacobianN = n;
        in.jacobianTile = float(scene.fft->patchSize(0));
        in.ripples = scene.patch.get();
        in.water = scene.water.get();
        map.update(in, DT);
    };
    update();  // warm-up: starts the pool's workers, evaluates every node once
    for (auto _ : state) {
        state.PauseTiming();
        scene.advance();
        state.ResumeTiming();
        update();
        benchmark::DoNotOptimize(map.coverage().data());
    }
    ob::setWorkerCount(0);
}
BENCHMARK(BM_FoamUpdate)
    ->ArgNames({"workers", "K"})
    ->ArgsProduct({{1, 2}, {1, 2, 4, 8}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A whole frame (render + glFinish) of a 320×180 or 640×360 view over flat water with a crown
// of N drops 25 m ahead of a camera 6 m up (r = 4 mm: sprites of ~0.6 px, most drawn at the
// 1.5 px minimum), optionally a 256² foam map. Args: drops, reflections (0/1: the reflection
// pass mirrors every drop), foam (0/1), height (180 or 360 px; 16:9).
void BM_SplashFoamDraw(benchmark::State& state) {
    ob::setLogQuiet(true);
    const int count = int(state.range(0));
    const glm::ivec2 size(int(state.range(3)) * 16 / 9, int(state.range(3)));
    const auto platform = ob::platform::createHeadlessPlatform(size);
    ob::gfx::RenderDef def;
    def.reflections = state.range(1) != 0;
    ob::gfx::Renderer renderer(def);
    ob::gfx::CameraView camera;
    camera.position = glm::vec3(0.0f, 6.0f, 0.0f);
    camera.view = glm::lookAtRH(camera.position, glm::vec3(0.0f, 0.0f, -25.0f), glm::vec3(0, 1, 0));
    camera.projection = glm::perspectiveRH_NO(glm::radians(60.0f), float(size.x) / float(size.y), 0.1f, 2000.0f);
    std::vector<ob::gfx::SplashDrop> drops;
    for (int i = 0; i < count; ++i) {
        const float a = 6.2831853f * float(i) / float(count), t = float((i * 7919) % 1000) / 1000.0f;
        drops.emplace_back(glm::vec3((1.0f + t) * std::cos(a), 2.0f * t, -25.0f + (1.0f + t) * std::sin(a)), 0.004f);
    }
    std::vector<float> foam(256 * 256, 0.0f);
    for (int j = 96; j < 160; ++j)
        for (int i = 96; i < 160; ++i) foam[size_t(j * 256 + i)] = 0.6f;
    ob::gfx::WaterView water;
    if (state.range(2) != 0) {
        water.foam = foam.data();
        water.foamCells = 256;
        water.foamOrigin = glm::vec2(-6.4f, -31.4f);
        water.foamCellSize = 0.05f;
    }
    const auto body = [&] {
        renderer.render(camera, water, {}, 0.0, size, drops);
        glFinish();
    };
    body();  // warm-up: the driver compiles each shader at its first draw
    for (auto _ : state) body();
    state.SetLabel(ob::gfx::glRendererName());
}
BENCHMARK(BM_SplashFoamDraw)
    ->ArgNames({"drops", "reflections", "foam", "height"})
    ->ArgsProduct({{0, 1000, 10000, 100000}, {0, 1}, {0, 1}, {180}})
    ->Args({0, 1, 1, 360})
    ->Args({10000, 1, 1, 360})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
