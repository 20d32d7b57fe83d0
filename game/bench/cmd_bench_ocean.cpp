// `oceanbox bench ocean`: [Lee2007] Tables 1–3 on this machine. Per spectrum size N and backend:
// a scene's whole frame (sim + render), the spectral ocean update alone (sim), its inverse FFT
// stage alone, and FFTW alone on the same transforms with the same threads (the reference).
#include "tools/app.h"
#include "bench/bench_report.h"
#include "bench/cmd_bench.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/schema.h"
#include "core/log.h"
#include "gfx/gl.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/gpu/ocean_fft_gpu.h"
#include "ocean/gpu/ocean_textures.h"
#include "bench/paper_tables.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "bench/svg_chart.h"

#include <barrier>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <thread>
#include <fftw3.h>

namespace ob::game {

namespace {

using Clock = std::chrono::steady_clock;
using Millis = std::chrono::duration<double, std::milli>;
constexpr double STEP_SECONDS = 1.0 / 60.0;  // each update advances one 60 Hz step

struct OceanPoint {
    double simRenderMs = NAN, simMs = NAN, fftMs = NAN;
};

// A scene's frame, rendered headless: wall ms frame to frame.
double simRenderMs(const SceneDef& scene, platform::Platform& platform, int warmup, int frames) {
    Sandbox sandbox(scene);
    sandbox.attachPlatform(platform, false);
    FixedStepClock clock(1.0 / scene.sim.step_hz);
    for (int f = 0; f < warmup + frames; ++f) {
        sandbox.frame(clock.now());
        platform.present();
    }
    sandbox.schedule().finish();
    for (const auto& [name, ms] : sandbox.timings(size_t(warmup)))
        if (name == "frame") return ms;
    return NAN;
}

// OceanFftCpu::update (synthesis, FFTs, unpack) and its FFT stage.
OceanPoint cpuOcean(const ocean::OceanDef& def, int warmup, int frames) {
    ocean::OceanFftCpu fft(def);
    std::vector<double> sim, transforms;
    double t = 0.0;
    for (int f = 0; f < warmup + frames; ++f) {
        t += STEP_SECONDS;
        const auto t0 = Clock::now();
        fft.update(t);
        const double ms = Millis(Clock::now() - t0).count();
        if (f < warmup) continue;
        sim.push_back(ms);
        transforms.push_back(fft.lastStageMs().transforms);
    }
    return {NAN, medianOf(sim), medianOf(transforms)};
}

// OceanFftGpu::update into the textures, finished (glFinish); then, profiled, its FFT dispatches.
OceanPoint gpuOcean(const ocean::OceanDef& def, int warmup, int frames) {
    ocean::OceanFftGpu gpu(def);
    ocean::OceanTextures textures(def.resolution, def.cascades);
    std::vector<double> sim, transforms;
    double t = 0.0;
    for (int f = 0; f < warmup + frames; ++f) {
        t += STEP_SECONDS;
        const auto t0 = Clock::now();
        gpu.update(t, textures);
        glFinish();
        if (f >= warmup) sim.push_back(Millis(Clock::now() - t0).count());
    }
    gpu.setProfiling(true);
    for (int f = 0; f < frames; ++f) {
        t += STEP_SECONDS;
        gpu.update(t, textures);
        transforms.push_back(gpu.lastTransformMs());
    }
    glFinish();
    return {NAN, medianOf(sim), medianOf(transforms)};
}

// FFTW alone: the C·4 in-place backward N×N c2c transforms of one update, split over the
// threads OceanFftCpu::update uses (transform k on worker k mod threads). Timed as that stage
// is, from a barrier that releases every worker to the barrier after the last transform
// (thread start and join untimed). Buffers refilled from noise before each run (untimed).
double fftwAloneMs(const ocean::OceanDef& def, int warmup, int frames) {
    const ocean::OceanFftCpu owner(def);  // loads the FFTW wisdom the ocean plans with
    const int threads = owner.threadCount();
    const int n = def.resolution, count = def.cascades * ocean::OCEAN_PACKED_TRANSFORMS;
    const size_t cells = size_t(n) * size_t(n);
    std::vector<fftwf_complex*> buffers(static_cast<size_t>(count));
    for (auto& b : buffers) b = fftwf_alloc_complex(cells);
    const fftwf_plan plan = fftwf_plan_dft_2d(n, n, buffers[0], buffers[0], FFTW_BACKWARD, FFTW_MEASURE);
    std::mt19937 rng(1);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    std::vector<float> source(2 * cells);
    for (float& v : source) v = normal(rng);
    std::vector<double> samples;
    for (int f = 0; f < warmup + frames; ++f) {
        for (auto* b : buffers) std::memcpy(b, source.data(), 2 * cells * sizeof(float));
        std::barrier sync(threads);
        Clock::time_point t0, t1;
        const auto work = [&](int w) {
            sync.arrive_and_wait();
            if (w == 0) t0 = Clock::now();
            for (int k = w; k < count; k += threads) fftwf_execute_dft(plan, buffers[size_t(k)], buffers[size_t(k)]);
            sync.arrive_and_wait();
            if (w == 0) t1 = Clock::now();
        };
        std::vector<std::thread> helpers;
        for (int w = 1; w < threads; ++w) helpers.emplace_back(work, w);
        work(0);
        for (auto& h : helpers) h.join();
        if (f >= warmup) samples.push_back(Millis(t1 - t0).count());
    }
    fftwf_destroy_plan(plan);
    for (auto* b : buffers) fftwf_free(b);
    return medianOf(samples);
}

// The flags' ranges and values (exit 2 with the flag's name).
void checkOceanArgs(const OceanBenchArgs& a) {
    if (a.sizes.empty()) throw InputError("--sizes: give at least one spectrum size");
    for (long s : a.sizes) {
        checkRange("--sizes", s, 16, ocean::OceanFftGpu::MAX_RESOLUTION);
        if (s & (s - 1)) throw InputError("--sizes: each size must be a power of two (ocean.resolution), got " + std::to_string(s));
    }
    oceanBackends(a);
    checkRange("--frames", a.frames, 1, 1000000);
    checkRange("--warmup", a.warmup, 0, 1000000);
}

// The chart: our series against [Lee2007]'s Tables 1–3.
void writeOceanChart(const OceanBenchArgs& a, const std::map<std::string, ChartSeries>& series) {
    Chart chart;
    chart.title = "Spectral ocean: fps against spectrum size";
    chart.xLabel = "spectrum N (N² modes)";
    chart.yLabel = "frames (or updates, transforms) per second";
    chart.logX = true;
    chart.logY = true;
    for (const auto& [key, sr] : series) chart.series.push_back(sr);
    struct Column {
        const char* label;
        double PaperOceanFps::*value;
        bool render;
        int colour;
    };
    const Column columns[] = {{"[Lee2007] T1 sim + render CPU", &PaperOceanFps::simRenderCpu, true, 0},
                              {"[Lee2007] T2 sim CPU", &PaperOceanFps::simCpu, false, 1},
                              {"[Lee2007] T3 FFTW (P4 3 GHz)", &PaperOceanFps::fftCpuFftw, false, 3},
                              {"[Lee2007] T1 sim + render GPU", &PaperOceanFps::simRenderGpu, true, 4},
                              {"[Lee2007] T2 sim GPU", &PaperOceanFps::simGpu, false, 5},
                              {"[Lee2007] T3 FFT GPU", &PaperOceanFps::fftGpu, false, 6}};
    for (const Column& c : columns) {
        if (c.render && a.noRender) continue;
        ChartSeries paper{c.label, {}, {}, true, c.colour};
        for (const PaperOceanFps& p : SEED000_TABLES) {
            paper.x.push_back(p.size);
            paper.y.push_back(p.*c.value);
        }
        chart.series.push_back(paper);
    }
    writeChart(a.output.chart, chart);
}

} // namespace

std::vector<Backend> oceanBackends(const OceanBenchArgs& a) {
    if (a.backendWords.empty()) throw InputError("--backend: give cpu, gpu or both");
    std::vector<Backend> backends;
    for (const std::string& word : a.backendWords) {
        Backend b = Backend::Auto;
        if (!enumFromName(word, b) || b == Backend::Auto) throw InputError("--backend: expected cpu or gpu, got '" + word + "'");
        backends.push_back(b);
    }
    return backends;
}

int benchOcean(const OceanBenchArgs& a) {
    checkOceanArgs(a);
    const auto [w, h] = parseSize("--size", a.size);
    const std::string path = a.scene.empty() ? defaultScenePath() : resolveScene(a.scene);
    loadScene(path, a.sets);
    checkOutputs(a.output, {path});

    // One headless context serves the GPU backend and the rendered frames.
    auto platform = platform::createHeadlessPlatform({w, h});
    const MachineInfo machine = machineInfo(true);
    setLogQuiet(true);

    BenchTable table(a.output.command, {"size", "backend", "fps_sim_render", "fps_sim", "ms_fft", "ms_fftw"});
    table.setting("fps_sim_render", a.noRender ? "not run" : path + " with one cascade of N², rendered " + a.size + " headless");
    table.setting("fps_sim", "the ocean update alone (cpu: OceanFftCpu::update; gpu: OceanFftGpu::update + glFinish)");
    table.setting("ms_fft", "its inverse FFT stage alone (cpu: FFTW execute; gpu: the row and column dispatches)");
    table.setting("ms_fftw", "FFTW alone: 4 packed N² c2c backward transforms, same threads and barriers as the cpu backend");
    table.setting("frames", std::to_string(a.frames) + " measured after " + std::to_string(a.warmup) + " warm-up; medians");
    for (const std::string& s : a.sets) table.setting("set", s);

    Progress progress("ocean");
    std::map<std::string, ChartSeries> series;
    // Colours pair each of our series with the paper's column it answers.
    const std::map<std::string, int> colours{{"cpu0", 0}, {"cpu1", 1}, {"cpu2", 2}, {"fftw", 3},
                                             {"gpu0", 4}, {"gpu1", 5}, {"gpu2", 6}};
    const auto add = [&](const std::string& key, const std::string& label, double x, double y) {
        ChartSeries& sr = series[key];
        sr.label = label;
        sr.colour = colours.at(key);
        sr.x.push_back(x);
        sr.y.push_back(y);
    };
    const int points = int(a.sizes.size() * a.backendWords.size());
    int point = 0;
    for (long size : a.sizes) {
        double fftw = NAN;
        for (const Backend b : oceanBackends(a)) {
            const std::string backend = enumName(b);  // the row's and the chart's word
            ++point;
            const std::string what = "N " + std::to_string(size) + " " + backend;
            std::vector<std::string> overrides = a.sets;
            overrides.push_back("ocean.resolution=" + std::to_string(size));
            overrides.push_back("ocean.backend=" + backend);
            overrides.push_back("ocean.cascades=1");
            const SceneDef scene = loadScene(path, overrides);
            progress.show(what + ": sim", point, points);
            OceanPoint p = b == Backend::Cpu ? cpuOcean(scene.ocean, a.warmup, a.frames) : gpuOcean(scene.ocean, a.warmup, a.frames);
            if (!a.noRender) {
                progress.show(what + ": sim + render", point, points);
                p.simRenderMs = simRenderMs(scene, *platform, a.warmup, a.frames);
            }
            if (std::isnan(fftw)) {
                progress.show(what + ": FFTW alone", point, points);
                fftw = fftwAloneMs(scene.ocean, a.warmup, a.frames);
                add("fftw", "FFTW alone", double(size), 1000.0 / fftw);
            }
            table.addRow({std::to_string(size), backend, cell(1000.0 / p.simRenderMs), cell(1000.0 / p.simMs), cell(p.fftMs), cell(fftw)});
            if (!a.noRender) add(backend + "0", "oceanbox " + backend + " sim + render", double(size), 1000.0 / p.simRenderMs);
            add(backend + "1", "oceanbox " + backend + " sim", double(size), 1000.0 / p.simMs);
            add(backend + "2", "oceanbox " + backend + " FFT", double(size), 1000.0 / p.fftMs);
        }
    }
    progress.done();
    setLogQuiet(false);
    table.printMarkdown(stdout);
    if (!a.output.out.empty()) table.writeCsv(a.output.out, machine);
    if (!a.output.chart.empty()) writeOceanChart(a, series);
    if (gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

} // namespace ob::game
