// Ripple layer benchmarks (docs/references.md#ripple-layer, [Kang2008]): the eq. 1–2 step per field size, boundary and
// worker count, bounding-sphere stamping (Table 2, eq. 3–7) of many spheres in contact, one by
// one and batched, and the Table 5 fish swarm.
#include "core/log.h"
#include "core/parallel.h"
#include "gfx/gl.h"
#include "interaction/kang2008/gpu/ripple_gpu.h"
#include "platform/platform.h"
#include "sim/fish_swarm.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/kang2008/footprint_stamp.h"
#include "interaction/sphere_stamp.h"
#include "interaction/kang2008/stamp_batch.h"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

using namespace ob::interaction;

namespace {

constexpr float DAMPING = 0.95f;   // RippleDef default DF
constexpr float CELL_SIZE = 0.25f; // RippleDef default, m per cell
constexpr int STAMP_FIELD = 128;   // [Kang2008]'s larger field
// Waves decay by about sqrt(DF) per step (faster in the sponge); the field is refilled (not
// timed) this often so it never reaches subnormal floats, which would time the FPU, not the kernel.
constexpr int REFILL_STEPS = 128;

// One step(DF) of an N×N field holding noise. Args: N, absorbing (0 fixed, 1 absorbing), workers.
void BM_RippleStep(benchmark::State& state) {
    const int n = int(state.range(0));
    const auto boundary = state.range(1) ? RippleBoundary::Absorbing : RippleBoundary::Fixed;
    ob::setWorkerCount(int(state.range(2)));
    RippleField field(n, n, boundary);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
    std::vector<float> cur(field.current().size()), prev(field.previous().size());
    for (float& v : cur) v = noise(rng);
    for (float& v : prev) v = noise(rng);
    const auto refill = [&] {
        std::copy(cur.begin(), cur.end(), field.current().begin());
        std::copy(prev.begin(), prev.end(), field.previous().begin());
    };
    refill();
    field.step(DAMPING);  // warm-up: starts the pool's workers
    int steps = 0;
    for (auto _ : state) {
        if (++steps == REFILL_STEPS) {
            state.PauseTiming();
            refill();
            steps = 0;
            state.ResumeTiming();
        }
        field.step(DAMPING);
    }
    benchmark::DoNotOptimize(field.currentAt(n / 2, n / 2));
    state.SetItemsProcessed(state.iterations() * int64_t(n) * n);
    ob::setWorkerCount(0);
}
BENCHMARK(BM_RippleStep)
    ->ArgNames({"N", "absorbing", "workers"})
    ->ArgsProduct({{128, 256, 512, 1024, 2048}, {0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The GPU twin of the step on OSMesa (llvmpipe here: the dispatches run on the CPU's cores),
// glFinish included. Args: N; what (0 = step, 1 = step and read Vh(t) back, 2 = 50 stamps).
void BM_RippleGpu(benchmark::State& state) {
    ob::setLogQuiet(true);
    const auto platform = ob::platform::createHeadlessPlatform({16, 16});
    const int n = int(state.range(0));
    RippleFieldGpu gpu(n, n, RippleBoundary::Fixed);
    std::mt19937 rng(61);
    std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
    std::vector<float> h(size_t(n) * size_t(n));
    for (float& v : h) v = noise(rng);
    gpu.upload(h, h);
    std::vector<RippleStamp> stamps;
    for (int k = 0; k < 50; ++k) stamps.push_back({(37 * k) % n, (53 * k) % n, 5.0f, 0.0f, -0.1f, 0.0f});
    std::vector<float> heights;
    const auto body = [&] {
        if (state.range(1) == 2) gpu.stamp(stamps);
        else gpu.step(DAMPING);
        if (state.range(1) == 1) gpu.readCurrent(heights);
        glFinish();
    };
    body();  // warm-up: the driver compiles each shader at its first dispatch
    for (auto _ : state) body();
    state.SetLabel(ob::gfx::glRendererName());
}
BENCHMARK(BM_RippleGpu)
    ->ArgNames({"N", "what"})
    ->ArgsProduct({{128, 512, 1024}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Spheres of SR cells at random cells of a 128² field, every one in contact and crossing its
// fixHeight, so Table 2 stamps each of them every step. Centres keep the whole footprint inside
// the interior (no clipping: the most cells).
struct SphereCrowd {
    RippleField field{STAMP_FIELD, STAMP_FIELD, RippleBoundary::Absorbing};
    BoundingSphere def;
    std::vector<SphereContact> contacts;
    std::vector<SphereMotion> motions;

    SphereCrowd(int count, int radiusCells) : contacts(size_t(count)), motions(size_t(count)) {
        def.radius = float(radiusCells) * CELL_SIZE;
        def.direction = SphereDirection::Down;
        def.heightRatio = 1.0f;
        def.accelerationFactor = 0.0f;
        std::mt19937 rng(1);
        std::uniform_int_distribution<int> cell(radiusCells + 1, STAMP_FIELD - 2 - radiusCells);
        for (size_t i = 0; i < motions.size(); ++i) {
            motions[i].gridX = float(cell(rng));
            motions[i].gridZ = float(cell(rng));
            motions[i].centreY = 0.0f;   // centre on the surface: bottom <= fixHeight <= top
            motions[i].surfaceY = 0.0f;
            contacts[i].phase = ContactPhase::Contact;
            contacts[i].fixHeight = 0.0f;
        }
    }
};

// stepSphere per sphere: Table 2 (updateContact), footprint from the cache, eq. 5 and 7.
// Args: spheres, SR in cells.
void BM_StepSphere(benchmark::State& state) {
    SphereCrowd crowd(int(state.range(0)), int(state.range(1)));
    FootprintCache cache;
    for (auto _ : state) {
        int stamped = 0;
        for (size_t i = 0; i < crowd.motions.size(); ++i)
            stamped += stepSphere(crowd.field, cache, CELL_SIZE, crowd.def, crowd.contacts[i], crowd.motions[i]);
        benchmark::DoNotOptimize(stamped);
    }
    const auto cells = int64_t(makeFootprint(float(state.range(1))).ph.size());
    state.counters["cells_per_sphere"] = double(cells);
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// stampFootprint alone (eq. 5 and 7 over a precomputed footprint), same spheres.
void BM_StampFootprint(benchmark::State& state) {
    SphereCrowd crowd(int(state.range(0)), int(state.range(1)));
    const FootprintProfile footprint = makeFootprint(float(state.range(1)));
    for (auto _ : state) {
        for (const SphereMotion& m : crowd.motions)
            stampFootprint(crowd.field, footprint, int(m.gridX), int(m.gridZ), 0.0f, -CELL_SIZE, 0.0f);
        benchmark::ClobberMemory();
    }
    state.counters["cells_per_sphere"] = double(footprint.ph.size());
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// queueSphere per sphere into a StampBatch, then one apply: the same spheres and result as
// BM_StepSphere. Args: spheres, SR in cells, workers.
void BM_QueueSphere(benchmark::State& state) {
    SphereCrowd crowd(int(state.range(0)), int(state.range(1)));
    ob::setWorkerCount(int(state.range(2)));
    FootprintCache cache;
    StampBatch batch(STAMP_FIELD, STAMP_FIELD);
    for (auto _ : state) {
        int stamped = 0;
        for (size_t i = 0; i < crowd.motions.size(); ++i)
            stamped += queueSphere(batch, crowd.field, cache, CELL_SIZE, crowd.def, crowd.contacts[i], crowd.motions[i]);
        batch.apply(crowd.field);
        benchmark::DoNotOptimize(stamped);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    ob::setWorkerCount(0);
}

// StampBatch::push per sphere, then one apply: the same stamps and result as BM_StampFootprint.
// Args: spheres, SR in cells, workers.
void BM_StampBatch(benchmark::State& state) {
    SphereCrowd crowd(int(state.range(0)), int(state.range(1)));
    ob::setWorkerCount(int(state.range(2)));
    const FootprintProfile footprint = makeFootprint(float(state.range(1)));
    StampBatch batch(STAMP_FIELD, STAMP_FIELD);
    for (auto _ : state) {
        for (const SphereMotion& m : crowd.motions)
            batch.push(footprint, int(m.gridX), int(m.gridZ), 0.0f, -CELL_SIZE, 0.0f);
        batch.apply(crowd.field);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    ob::setWorkerCount(0);
}

// One FishSwarm step (Table 5: fish of SR 20 on jump arcs over 128² cells, DF 0.93): Table 2,
// stamps, moves and eq. 1–2. Args: fish, batched (1) or sequential stepSphere (0).
void BM_FishSwarm(benchmark::State& state) {
    ob::game::FishSwarmDef def;
    def.count = int(state.range(0));
    def.mode = state.range(1) ? ob::game::StampMode::Batched : ob::game::StampMode::Sequential;
    ob::game::FishSwarm swarm(def);
    for (int i = 0; i < 30; ++i) swarm.step();  // the batch grows to its size
    int64_t stamps = 0;
    for (auto _ : state) {
        swarm.step();
        stamps += swarm.lastStamps();
    }
    state.counters["stamps_per_step"] = double(stamps) / double(std::max<int64_t>(1, state.iterations()));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(BM_StepSphere)
    ->ArgNames({"spheres", "SR"})
    ->Args({100000, 20})->Args({1000, 5})->Args({1000, 7})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_StampFootprint)
    ->ArgNames({"spheres", "SR"})
    ->Args({100000, 20})->Args({1000, 5})->Args({1000, 7})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();


BENCHMARK(BM_QueueSphere)
    ->ArgNames({"spheres", "SR", "workers"})
    ->Args({100000, 20, 1})->Args({100000, 20, 2})->Args({1000, 5, 2})->Args({1000, 7, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_StampBatch)
    ->ArgNames({"spheres", "SR", "workers"})
    ->Args({100000, 20, 1})->Args({100000, 20, 2})->Args({1000, 5, 2})->Args({1000, 7, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_FishSwarm)
    ->ArgNames({"fish", "batched"})
    ->Args({1, 1})->Args({1000, 1})->Args({10000, 1})->Args({100000, 1})->Args({100000, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
