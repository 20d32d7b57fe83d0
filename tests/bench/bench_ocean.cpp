// Spectral ocean benchmarks (docs/references.md#spectral-ocean, [Lee2007] §3.3): OceanFftCpu::update against FFTW alone
// on the same four packed N×N inverse transforms (eq. 9), and OceanFftGpu::update on OSMesa.
#include "core/log.h"
#include "gfx/gl.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/gpu/ocean_fft_gpu.h"
#include "ocean/gpu/ocean_textures.h"
#include "platform/platform.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <random>
#include <thread>
#include <vector>
#include <fftw3.h>

using namespace ob::ocean;

namespace {

constexpr double FRAME_SECONDS = 1.0 / 60.0;  // update() times advance one 60 Hz step per iteration

// Full update: synthesis (eq. 2, 6, 7), four packed FFTs, unpack and Jacobian. Args: N, threads.
void BM_OceanCpuUpdate(benchmark::State& state) {
    OceanDef def;
    def.resolution = int(state.range(0));
    OceanFftCpu fft(def, int(state.range(1)));
    double t = 0.0;
    fft.update(t);
    for (auto _ : state) {
        t += FRAME_SECONDS;
        fft.update(t);
    }
}
BENCHMARK(BM_OceanCpuUpdate)
    ->ArgNames({"N", "threads"})
    ->ArgsProduct({{64, 128, 256, 512, 1024}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// FFTW alone: the four in-place backward c2c N×N transforms of one update, no synthesis or
// unpack. Buffers are refreshed from a copy before each timed update (not timed), so FFTW sees
// finite, cache-warm input as it does after synthesis. threads = 2 mirrors OceanFftCpu::update:
// the caller and one std::thread started per update, transforms {0, 2} and {1, 3}.
void BM_FftwAlone(benchmark::State& state) {
    const int n = int(state.range(0));
    const int threads = int(state.range(1));
    OceanDef def;
    def.resolution = n;
    // Constructing OceanFftCpu loads (or measures) its FFTW wisdom, so the plan below is the
    // very plan it executes.
    const OceanFftCpu owner(def, 1);
    const size_t count = size_t(n) * size_t(n);
    fftwf_complex* buffers[OCEAN_PACKED_TRANSFORMS];
    for (auto& b : buffers) b = fftwf_alloc_complex(count);
    const fftwf_plan plan = fftwf_plan_dft_2d(n, n, buffers[0], buffers[0], FFTW_BACKWARD, FFTW_MEASURE);

    std::mt19937 rng(1);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    std::vector<float> source(2 * count * OCEAN_PACKED_TRANSFORMS);
    for (float& v : source) v = normal(rng);
    const auto refill = [&] {
        for (int k = 0; k < OCEAN_PACKED_TRANSFORMS; ++k)
            std::memcpy(buffers[k], source.data() + 2 * count * size_t(k), 2 * count * sizeof(float));
    };
    const auto run = [&](int k) { fftwf_execute_dft(plan, buffers[k], buffers[k]); };

    for (auto _ : state) {
        refill();
        const auto start = std::chrono::steady_clock::now();
        if (threads == 1) {
            for (int k = 0; k < OCEAN_PACKED_TRANSFORMS; ++k) run(k);
        } else {
            std::thread helper([&] {
                run(1);
                run(3);
            });
            run(0);
            run(2);
            helper.join();
        }
        state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    fftwf_destroy_plan(plan);
    for (auto* b : buffers) fftwf_free(b);
}
BENCHMARK(BM_FftwAlone)
    ->ArgNames({"N", "threads"})
    ->ArgsProduct({{64, 128, 256, 512, 1024}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();

// GPU backend: four compute dispatches into OceanTextures level 0, then glFinish (on llvmpipe
// the dispatches run on the CPU's cores). Arg: N.
void BM_OceanGpuUpdate(benchmark::State& state) {
    ob::setLogQuiet(true);
    const auto platform = ob::platform::createHeadlessPlatform({16, 16});
    OceanDef def;
    def.resolution = int(state.range(0));
    OceanFftGpu gpu(def);
    OceanTextures textures(def.resolution, 1);
    double t = 0.0;
    gpu.update(t, textures);  // warm-up: the driver compiles each shader at its first dispatch
    glFinish();
    for (auto _ : state) {
        t += FRAME_SECONDS;
        gpu.update(t, textures);
        glFinish();
    }
    state.SetLabel(ob::gfx::glRendererName());
}
BENCHMARK(BM_OceanGpuUpdate)
    ->ArgNames({"N"})
    ->Arg(64)->Arg(128)->Arg(256)->Arg(512)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The CPU backend's way to the renderer: OceanTextures::upload of the latest maps, then (mips
// = 1) the textures' mipmaps, as every frame does, glFinish included. Args: N, mips.
void BM_OceanTexturesUpload(benchmark::State& state) {
    ob::setLogQuiet(true);
    const auto platform = ob::platform::createHeadlessPlatform({16, 16});
    OceanDef def;
    def.resolution = int(state.range(0));
    OceanFftCpu cpu(def);
    OceanTextures textures(def.resolution, 1);
    cpu.update(0.0);
    textures.upload(cpu);  // warm-up: the driver allocates the storage at the first upload
    glFinish();
    for (auto _ : state) {
        textures.upload(cpu);
        if (state.range(1)) textures.generateMipmaps();
        glFinish();
    }
    state.SetLabel(ob::gfx::glRendererName());
}
BENCHMARK(BM_OceanTexturesUpload)
    ->ArgNames({"N", "mips"})
    ->ArgsProduct({{64, 128, 256, 512}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
