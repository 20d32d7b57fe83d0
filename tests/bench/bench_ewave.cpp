// Dispersive ripple field benchmarks (docs/references.md#dispersive-ripples): one ewave step per field size and worker
// count, its float FFTW transforms alone (the floor of a step; the four real ones of the step
// before the packed pairs, and the double ones it used before the float ones), and
// 100,000 bounding spheres of SR 20 stamping into ewave (planStamp + the biweight source) to
// compare with BM_StepSphere's kang2008 stamps.
#include "core/log.h"
#include "core/parallel.h"
#include "core/thread_choice.h"
#include "gfx/gl.h"
#include "interaction/ewave/gpu/ewave_gpu.h"
#include "platform/platform.h"
#include "interaction/ewave/ewave_field.h"
#include "interaction/ripple_patch.h"
#include "interaction/sphere_stamp.h"
#include "core/fftw_wisdom.h"

#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <random>
#include <vector>

using namespace ob::interaction;

namespace {

// Fills a field's height and velocity with noise, the same for every benchmark.
void fillNoise(EWaveField& field) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> noise(-0.1, 0.1);
    for (double& v : field.editHeight()) v = noise(rng);
    for (double& v : field.editVelocity()) v = noise(rng);
}

// One step of an N×N absorbing field (0.25 m cells, 60 Hz, the default damping) holding noise.
// Args: N, workers (the transforms split over 2 workers as given, not as measured at start-up),
// velocity (1: the horizontal velocity made as every scene makes it; 0: the step without it,
// keepHorizontalVelocity(false), the cost it is measured against).
// Waves decay by 0.5 % a step at most: no refill needed for the run.
void BM_EWaveStep(benchmark::State& state) {
    const int n = int(state.range(0));
    ob::setWorkerCount(int(state.range(1)));
    ob::setThreadMeasuring(false);
    EWaveField field(n, n, 0.25f, RippleBoundary::Absorbing, 32);  // 0.25 m cells
    field.keepHorizontalVelocity(state.range(2) != 0);
    field.setDamping(3.0f, 1e-3f);                                 // the default damping
    fillNoise(field);
    field.step(1.0f / 60.0f);  // coefficients and sponge built outside the timing
    for (auto _ : state) field.step(1.0f / 60.0f);
    ob::setThreadMeasuring(true);
    ob::setWorkerCount(0);
}
BENCHMARK(BM_EWaveStep)
    ->ArgsProduct({{256, 512, 1024}, {1, 2}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The horizontal surface velocity derived from a state as it is (EWaveField::deriveHorizontal:
// one forward transform and the packed inverse one), what the GPU twin's read-back costs on the CPU on top
// of BM_EWaveStep's field (whose step makes it itself). Args: N, workers.
void BM_EWaveDeriveHorizontal(benchmark::State& state) {
    const int n = int(state.range(0));
    ob::setWorkerCount(int(state.range(1)));
    ob::setThreadMeasuring(false);
    EWaveField field(n, n, 0.25f, RippleBoundary::Absorbing, 32);
    field.setDamping(3.0f, 1e-3f);
    fillNoise(field);
    field.step(1.0f / 60.0f);
    for (auto _ : state) field.deriveHorizontal();
    ob::setThreadMeasuring(true);
    ob::setWorkerCount(0);
}
BENCHMARK(BM_EWaveDeriveHorizontal)
    ->ArgsProduct({{256, 512}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The GPU twin's step on OSMesa (llvmpipe here: the dispatches run on the CPU's cores), the
// same field as BM_EWaveStep, glFinish included. Args: N, read (1: h and v read back into the
// CPU field after the step, as the sandbox does).
void BM_EWaveGpuStep(benchmark::State& state) {
    ob::setLogQuiet(true);
    const auto platform = ob::platform::createHeadlessPlatform({16, 16});
    const int n = int(state.range(0));
    EWaveField field(n, n, 0.25f, RippleBoundary::Absorbing, 32);  // 0.25 m cells
    field.setDamping(3.0f, 1e-3f);                                 // the default damping
    fillNoise(field);
    EWaveGpu gpu(field);
    gpu.upload(field);
    const auto body = [&] {
        gpu.step(1.0f / 60.0f);
        if (state.range(1)) gpu.download(field.editHeight(), field.editVelocity());
        glFinish();
    };
    body();  // warm-up: the driver compiles each shader at its first dispatch
    for (auto _ : state) body();
    state.SetLabel(ob::gfx::glRendererName());
}
BENCHMARK(BM_EWaveGpuStep)
    ->ArgNames({"N", "read"})
    ->ArgsProduct({{256, 512, 1024}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The step's transforms alone: r2c of h and v, and the packed inverse ones (one complex transform
// in place per pair of real fields: the change (h, v), the velocity (ux, uz)); float, the shared
// wisdom's plans, split over the workers as the step splits them. Args: N, workers, packed (0: the
// four real c2r transforms the step ran before, for comparison).
void BM_EWaveFftwAlone(benchmark::State& state) {
    const int n = int(state.range(0));
    const bool packed = state.range(2) != 0;
    ob::setWorkerCount(int(state.range(1)));
    const size_t cells = size_t(n) * size_t(n), modes = size_t(n) * size_t(n / 2 + 1);
    float* real[2] = {fftwf_alloc_real(cells), fftwf_alloc_real(cells)};
    fftwf_complex* spec[2] = {fftwf_alloc_complex(modes), fftwf_alloc_complex(modes)};
    fftwf_complex* full[2] = {fftwf_alloc_complex(cells), fftwf_alloc_complex(cells)};
    fftwf_plan fwd = ob::ocean::planWithWisdom([&](unsigned f) { return fftwf_plan_dft_r2c_2d(n, n, real[0], spec[0], f); });
    fftwf_plan bwd = ob::ocean::planWithWisdom([&](unsigned f) { return fftwf_plan_dft_c2r_2d(n, n, spec[0], real[0], f); });
    fftwf_plan pair = ob::ocean::planWithWisdom([&](unsigned f) { return fftwf_plan_dft_2d(n, n, full[0], full[0], FFTW_BACKWARD, f); });
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> noise(-0.1f, 0.1f);
    for (float* r : real)
        for (size_t i = 0; i < cells; ++i) r[i] = noise(rng);
    for (fftwf_complex* c : full)
        for (size_t i = 0; i < cells; ++i) c[i][0] = noise(rng), c[i][1] = noise(rng);
    for (auto _ : state) {
        ob::parallelFor(0, 2, 1, [&](int b, int e) {
            for (int t = b; t < e; ++t) fftwf_execute_dft_r2c(fwd, real[t], spec[t]);
        });
        ob::parallelFor(0, 2, 1, [&](int b, int e) {
            for (int t = b; t < e; ++t) {
                if (!packed) {  // a state field's and a velocity field's (c2r destroys its input: the values do not matter)
                    for (int k = 0; k < 2; ++k) fftwf_execute_dft_c2r(bwd, spec[t], real[t]);
                } else {
                    fftwf_execute_dft(pair, full[t], full[t]);
                }
            }
        });
    }
    {
        std::lock_guard<std::mutex> lock(ob::ocean::fftwPlannerMutex());
        for (fftwf_plan p : {fwd, bwd, pair}) fftwf_destroy_plan(p);
    }
    for (int t = 0; t < 2; ++t) {
        fftwf_free(real[t]);
        fftwf_free(spec[t]);
        fftwf_free(full[t]);
    }
    ob::setWorkerCount(0);
}
BENCHMARK(BM_EWaveFftwAlone)
    ->ArgNames({"N", "workers", "packed"})
    ->ArgsProduct({{256, 512, 1024}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Four real transforms in double precision (r2c of h and v, c2r of both), what the step ran
// before its transforms went to float. Args: N, workers.
void BM_EWaveFftwDouble(benchmark::State& state) {
    const int n = int(state.range(0));
    ob::setWorkerCount(int(state.range(1)));
    const size_t cells = size_t(n) * size_t(n), modes = size_t(n) * size_t(n / 2 + 1);
    double* real[2] = {fftw_alloc_real(cells), fftw_alloc_real(cells)};
    fftw_complex* spec[2] = {fftw_alloc_complex(modes), fftw_alloc_complex(modes)};
    fftw_plan fwd = ob::ocean::planWithWisdomDouble([&](unsigned f) { return fftw_plan_dft_r2c_2d(n, n, real[0], spec[0], f); });
    fftw_plan bwd = ob::ocean::planWithWisdomDouble([&](unsigned f) { return fftw_plan_dft_c2r_2d(n, n, spec[0], real[0], f); });
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> noise(-0.1, 0.1);
    for (double* r : real)
        for (size_t i = 0; i < cells; ++i) r[i] = noise(rng);
    for (auto _ : state) {
        ob::parallelFor(0, 2, 1, [&](int b, int e) {
            for (int t = b; t < e; ++t) fftw_execute_dft_r2c(fwd, real[t], spec[t]);
        });
        ob::parallelFor(0, 2, 1, [&](int b, int e) {
            for (int t = b; t < e; ++t) fftw_execute_dft_c2r(bwd, spec[t], real[t]);
        });
    }
    {
        std::lock_guard<std::mutex> lock(ob::ocean::fftwPlannerMutex());
        fftw_destroy_plan(fwd);
        fftw_destroy_plan(bwd);
    }
    for (int t = 0; t < 2; ++t) {
        fftw_free(real[t]);
        fftw_free(spec[t]);
    }
    ob::setWorkerCount(0);
}
BENCHMARK(BM_EWaveFftwDouble)
    ->ArgsProduct({{256, 512, 1024}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Spheres stamping a 128² ewave field (cell 0.25 m), every one in contact: Table 2 (planStamp)
// and the source, as RipplePatch does, for BM_StepSphere's spheres. Args: count, SR (cells).
void BM_EWaveStamp(benchmark::State& state) {
    const int count = int(state.range(0));
    const float sr = float(state.range(1));
    const int n = 128;
    const float cell = 0.25f;
    EWaveField field(n, n, cell, RippleBoundary::Fixed);
    BoundingSphere def;
    def.radius = sr * cell;
    def.direction = SphereDirection::Down;
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> pos(int(sr) + 1, n - int(sr) - 2);
    std::vector<SphereMotion> motions(static_cast<size_t>(count));
    for (SphereMotion& m : motions) {
        m.gridX = float(pos(rng));
        m.gridZ = float(pos(rng));
        m.centreY = 0.0f;
        m.surfaceY = 0.0f;
    }
    std::vector<SphereContact> contacts(static_cast<size_t>(count));
    for (auto _ : state) {
        for (size_t i = 0; i < motions.size(); ++i) {
            RippleStamp st;
            if (planStamp(n, n, cell, def, contacts[i], motions[i], [&](int x, int z) { return field.heightAt(x, z); }, st)) {
                const EWaveSource s = ewaveSource(st, motions[i].gridX, motions[i].gridZ, cell, 9.81f);
                field.addSource(s.gx, s.gz, s.radiusCells, s.accel, 1.0f / 60.0f);
            }
        }
        benchmark::DoNotOptimize(field.velocityState().data());
    }
}
BENCHMARK(BM_EWaveStamp)->Args({100000, 20})->Args({1000, 5})->Args({1000, 7})->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

// Nested levels (docs/ewave.md#levels): a RipplePatch of N² with `levels` levels (0.25 m, 1 m,
// 4 m), a 1 m sphere at 5 m/s stamped each frame, the patch following it; one iteration is 48
// frames (every level's stride divides it: 12 steps of level 1, 3 of level 2), so the time per
// iteration over 48 is a frame's mean cost. Args: N, levels. Compare levels 2 and 3 to 1.
void BM_EWaveLevels(benchmark::State& state) {
    RippleDef def;
    def.model = rippleModel("ewave");
    def.backend = ob::Backend::Cpu;
    def.resolution = int(state.range(0));
    def.cell_size = 0.25f;
    def.levels = int(state.range(1));
    RipplePatch patch(def);
    BoundingSphere sphere;
    sphere.radius = 1.0f;
    sphere.direction = SphereDirection::Down;
    SphereContact contact;
    const float dt = 1.0f / 60.0f;
    glm::vec2 ship(0.0f);
    auto frame = [&] {
        ship.x += 5.0f * dt;
        patch.centerOn(ship);
        patch.stampSphere(sphere, contact, glm::vec3(ship.x, 0.0f, ship.y), glm::vec3(5.0f, 0.0f, 0.0f), 1000.0f, 0.0f);
        patch.step(dt);
    };
    for (int i = 0; i < 48; ++i) frame();  // coefficients, sponges and the first steps outside the timing
    for (auto _ : state)
        for (int i = 0; i < 48; ++i) frame();
}
BENCHMARK(BM_EWaveLevels)->ArgsProduct({{256, 512}, {1, 2, 3}})->Unit(benchmark::kMillisecond)->UseRealTime();
