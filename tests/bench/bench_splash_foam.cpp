// Splash particles and the foam map: one step of N live drops (flight, landing scan, water
// queries) and one foam update at N² cells per flow kind, by worker count; the foam sources.
#include "core/parallel.h"
#include "foam/foam_map.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"
#include "water/water_query.h"

#include <benchmark/benchmark.h>

#include <cmath>
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
// field), workers. The map is refilled (not timed) now and then so it never turns subnormal.
void BM_FoamStep(benchmark::State& state) {
    const int n = int(state.range(0));
    const int flow = int(state.range(1));
    ob::setWorkerCount(int(state.range(2)));
    ob::foam::FoamDef def;
    def.resolution = n;
    ob::foam::FoamMap map(def, 64.0f);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> start(map.coverage().size());
    for (float& f : start) f = u(rng);
    const auto refill = [&] { std::copy(start.begin(), start.end(), map.coverage().begin()); };
    refill();
    if (flow == 1) map.setUniformVelocity(glm::vec2(0.8f, -0.3f));
    if (flow == 2) {
        std::span<float> ux = map.velocityX(), uz = map.velocityZ();
        for (size_t c = 0; c < ux.size(); ++c) {
            ux[c] = 0.8f + 0.3f * std::sin(float(c % size_t(n)) * 0.1f);
            uz[c] = -0.3f + 0.3f * std::cos(float(c / size_t(n)) * 0.1f);
        }
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
    ->ArgsProduct({{256, 512, 1024}, {0, 1, 2}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The foam sources at N² cells (one thread): 0 whitecaps from a 256² Jacobian tile, 1 steep
// ripples from a 256² patch, 2 a ship's 6 hull spheres of the wake.
void BM_FoamSources(benchmark::State& state) {
    const int n = int(state.range(0));
    const int source = int(state.range(1));
    ob::foam::FoamDef def;
    def.resolution = n;
    ob::foam::FoamMap map(def, 64.0f);
    std::vector<float> jacobian(256 * 256);
    for (size_t c = 0; c < jacobian.size(); ++c) jacobian[c] = std::sin(float(c) * 0.01f);
    ob::interaction::RippleDef rd;
    ob::interaction::RipplePatch patch(rd);
    for (size_t c = 0; c < patch.field().current().size(); ++c) patch.field().current()[c] = 0.05f * std::sin(float(c) * 0.3f);
    for (auto _ : state) {
        if (source == 0) map.addWhitecaps(jacobian, 256, 100.0f, DT);
        if (source == 1) map.addRipples(patch, DT);
        if (source == 2)
            for (int s = 0; s < 6; ++s) map.addWake(glm::vec3(float(s) * 1.5f, 0.0f, 0.0f), glm::vec3(6.0f, 0.0f, 0.0f), 1.75f, DT);
        benchmark::DoNotOptimize(map.coverage().data());
    }
}
BENCHMARK(BM_FoamSources)
    ->ArgNames({"N", "source"})
    ->ArgsProduct({{256, 512}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
