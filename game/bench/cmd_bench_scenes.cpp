// `oceanbox bench fields` ([Kang2008] Table 3) and `oceanbox bench frame`: scenes run headless
// through the sandbox, timed by its phase table.
#include "tools/app.h"
#include "bench/bench_report.h"
#include "bench/cmd_bench.h"
#include "core/clock.h"
#include "core/error.h"
#include "core/log.h"
#include "gfx/gl.h"
#include "bench/paper_tables.h"
#include "platform/platform.h"
#include "view/sandbox_view.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/sea_presets.h"
#include "ecs/schedule.h"
#include "bench/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <tuple>

namespace ob::game {

namespace {

// Runs warm-up + measured frames of a sandbox (rendered if a platform is attached).
void runFrames(Sandbox& sandbox, int frames, double stepHz, Progress& progress,
               const std::string& what, int point, int points) {
    FixedStepClock clock(1.0 / stepHz);
    for (int f = 0; f < frames; ++f) {
        if (f % 5 == 0) progress.show(what + ", frame " + std::to_string(f + 1) + "/" + std::to_string(frames), point, points);
        sandbox.frame(clock.now());  // presents the frame before it
    }
    sandbox.present();
    sandbox.schedule().finish();
}

double timingOf(const std::vector<std::pair<std::string, double>>& timings, const std::string& name) {
    for (const auto& [n, ms] : timings)
        if (n == name) return ms;
    return NAN;
}

bool isPowerOfTwo(long v) { return v > 0 && (v & (v - 1)) == 0; }

// The flags' ranges and values (exit 2 with the flag's name).
void checkFieldsArgs(const FieldsBenchArgs& a) {
    if (a.sizes.empty()) throw InputError("--sizes: give at least one field size");
    for (long s : a.sizes) {
        checkRange("--sizes", s, 16, 4096);
        if (!isPowerOfTwo(s)) throw InputError("--sizes: each size must be a power of two (ripples.resolution), got " + std::to_string(s));
    }
    if (a.scenes.empty()) throw InputError("--scenes: give at least one scene");
    checkRange("--frames", a.frames, 1, 1000000);
    checkRange("--warmup", a.warmup, 0, 1000000);
}

// The chart: our series against [Kang2008]'s Table 3.
void writeFieldsChart(const FieldsBenchArgs& a, const std::map<std::string, ChartSeries>& series) {
    Chart chart;
    chart.title = "Scenes: fps against ripple field size";
    chart.xLabel = "ripple field cells per side";
    chart.yLabel = "frames per second";
    chart.logX = true;
    chart.logY = true;
    for (const auto& [key, sr] : series) chart.series.push_back(sr);
    // The paper's curve for each scene it measured; for scenes it did not, its "all" scene.
    // Colours: a paper scene takes our scene's pair; the "all" stand-in the next pair.
    std::vector<std::pair<std::string, int>> paperScenes;
    for (size_t k = 0; k < a.scenes.size(); ++k)
        for (const PaperFieldFps& p : SEED001_TABLE3)
            if (a.scenes[k] == p.scene) {
                paperScenes.emplace_back(a.scenes[k], 2 * int(k));
                break;
            }
    if (paperScenes.empty()) paperScenes.emplace_back("all", 2 * int(a.scenes.size()));
    for (const auto& [s, colour] : paperScenes) {
        ChartSeries full{"[Kang2008] Table 3 " + s, {}, {}, true, colour};
        ChartSeries only{"[Kang2008] Table 3 " + s + ", spheres only", {}, {}, true, colour + 1};
        for (const PaperFieldFps& p : SEED001_TABLE3) {
            if (s != p.scene) continue;
            full.x.push_back(p.size);
            full.y.push_back(p.full);
            only.x.push_back(p.size);
            only.y.push_back(p.spheresOnly);
        }
        if (!a.noRender) chart.series.push_back(full);
        chart.series.push_back(only);
    }
    writeChart(a.output.chart, chart);
}

} // namespace

int benchFields(const FieldsBenchArgs& a) {
    checkFieldsArgs(a);
    const auto [w, h] = parseSize("--size", a.size);
    std::vector<std::string> paths;
    for (const std::string& s : a.scenes) {
        paths.push_back(resolveScene(s));
        loadScene(paths.back(), a.sets);  // bad scene files and overrides stop here, before any run
    }
    checkOutputs(a.output, paths);

    std::unique_ptr<platform::Platform> platform;
    if (!a.noRender) platform = platform::createHeadlessPlatform({w, h});
    const MachineInfo machine = machineInfo(!a.noRender);
    const bool quiet = true;
    setLogQuiet(quiet);

    BenchTable table(a.output.command, {"scene", "size", "render", "fps", "ms_frame"});
    table.setting("full", a.noRender ? "not run" : "a whole frame (every phase, rendered " + a.size + " headless), wall ms");
    table.setting("spheres_only", "the interaction phase alone (Table 2, stamps, eq. 1-2), nothing drawn");
    table.setting("frames", std::to_string(a.frames) + " measured after " + std::to_string(a.warmup) +
                                " warm-up; medians; one simulation step per frame");
    for (const std::string& s : a.sets) table.setting("set", s);
    table.setting("model", "ripples.model = " + a.model);

    Progress progress("fields");
    std::map<std::string, ChartSeries> series;  // by "scene, render"
    const int points = int(a.scenes.size() * a.sizes.size());
    int point = 0;
    for (size_t k = 0; k < a.scenes.size(); ++k) {
        for (long size : a.sizes) {
            ++point;
            std::vector<std::string> overrides = a.sets;
            overrides.push_back("ripples.resolution=" + std::to_string(size));
            overrides.push_back("ripples.model=" + a.model);
            overrides.push_back("ripples.levels=1");  // Table 3 times one field of each size (kang2008 has no levels)
            const SceneDef scene = loadScene(paths[k], overrides);
            const std::string what = a.scenes[k] + " " + std::to_string(size) + "²";
            const auto record = [&](const char* render, double ms) {
                table.addRow({a.scenes[k], std::to_string(size), render, cell(1000.0 / ms), cell(ms)});
                const bool full = std::string(render) == "full";
                ChartSeries& sr = series[a.scenes[k] + ", " + render];
                sr.label = "oceanbox " + a.scenes[k] + (full ? "" : ", spheres only");
                sr.colour = 2 * int(k) + (full ? 0 : 1);
                sr.x.push_back(double(size));
                sr.y.push_back(1000.0 / ms);
            };
            if (platform) {
                Sandbox sandbox(scene);
                sandbox.attachPlatform(*platform, false);
                runFrames(sandbox, a.warmup + a.frames, scene.sim.step_hz, progress, what + " rendered", point, points);
                record("full", timingOf(sandbox.timings(size_t(a.warmup)), "frame"));
            }
            Sandbox sandbox(scene);
            runFrames(sandbox, a.warmup + a.frames, scene.sim.step_hz, progress, what + " spheres only", point, points);
            record("spheres_only", timingOf(sandbox.timings(size_t(a.warmup)), "interaction"));
        }
    }
    progress.done();
    setLogQuiet(false);
    table.printMarkdown(stdout);
    if (!a.output.out.empty()) table.writeCsv(a.output.out, machine);
    if (!a.output.chart.empty()) writeFieldsChart(a, series);
    if (platform && gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

int benchFrame(const FrameBenchArgs& a) {
    const std::string path = resolveScene(a.scene);
    const SceneDef scene = loadScene(path, a.sets);
    checkRange("--frames", a.frames, 1, 1000000);
    checkRange("--warmup", a.warmup, 0, 1000000);
    int w = scene.window.width, h = scene.window.height;
    if (!a.size.empty()) std::tie(w, h) = parseSize("--size", a.size);
    checkOutputs(a.output);

    auto platform = platform::createHeadlessPlatform({w, h});
    const MachineInfo machine = machineInfo(true);
    setLogQuiet(true);
    Sandbox sandbox(scene);
    sandbox.attachPlatform(*platform, false);
    // --set render.target_fps=N: the internal scale follows the frame time, as in play.
    bool dynamic = false;
    for (const std::string& s : a.sets) dynamic = dynamic || s.rfind("render.target_fps", 0) == 0;
    if (dynamic) sandbox.enableDynamicResolution();
    Progress progress("frame");
    runFrames(sandbox, a.warmup + a.frames, scene.sim.step_hz, progress, a.scene, 1, 1);
    progress.done();
    setLogQuiet(false);
    const auto timings = sandbox.timings(size_t(a.warmup));

    BenchTable table(a.output.command, {"pass", "ms"});
    table.setting("scene", path);
    table.setting("size", std::to_string(w) + "x" + std::to_string(h) + " headless");
    table.setting("frames", std::to_string(a.frames) + " measured after " + std::to_string(a.warmup) +
                                " warm-up; medians; one simulation step per frame");
    table.setting("passes", "frame: wall ms frame to frame; main_cpu: the main thread's CPU ms per frame (CLOCK_THREAD_CPUTIME_ID: "
                            "the simulation it ran or waited on and the render's submission, not the rasteriser's threads); "
                            "main_cpu.PHASE: its part in a phase's systems (the render's includes the calling thread's share of the "
                            "driver: llvmpipe shades vertices there); "
                            "workers_cpu: the simulation workers' CPU ms per frame, summed (the pool, the pipelined steps); other "
                            "names: wall ms of a phase on the main thread; gpu.NAME: GPU ms of a timed span");
    for (const std::string& s : a.sets) table.setting("set", s);
    if (const auto* d = sandbox.world().resource<DynamicScale>(); dynamic && d && d->control) {
        const double frameMs = timings.empty() ? 0.0 : timings.front().second;
        table.setting("dynamic resolution", "settled at scale " + cell(d->control->scale()) + " after " +
                                                std::to_string(d->control->changes()) + " change(s), holding " +
                                                cell(frameMs > 0 ? 1000.0 / frameMs : 0.0) + " fps (target " +
                                                cell(scene.render.target_fps) + ")");
    }
    Chart chart;
    chart.title = "Frame of " + a.scene + " (" + std::to_string(w) + "x" + std::to_string(h) + ", " + machine.renderer + ")";
    chart.xLabel = "ms per frame (median)";
    ChartSeries bars{"ms", {}, {}, false};
    for (const auto& [name, ms] : timings) {
        table.addRow({name, cell(ms)});
        chart.categories.push_back(name);
        bars.x.push_back(double(bars.x.size()));
        bars.y.push_back(ms);
    }
    chart.series.push_back(bars);
    table.printMarkdown(stdout);
    if (!a.output.out.empty()) table.writeCsv(a.output.out, machine);
    if (!a.output.chart.empty()) writeChart(a.output.chart, chart);
    if (gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

// Measured frames of one run: wall ms frame start to frame start, and the CPU ms of the
// script phase (where the change's keys are applied) and the ocean phase (where the fade is
// built and blended, and the maps computed), per frame.
struct SeaRun {
    std::vector<double> frame, script, ocean;
};

// One world through warm-up, `before` frames, the preset requested, `after` frames.
static SeaRun seaRun(const SceneDef& scene, const SeaBenchArgs& a, SeaPreset preset, platform::Platform& platform, Progress& progress,
                     int run) {
    Sandbox sandbox(scene);
    sandbox.attachPlatform(platform, false);
    FixedStepClock clock(1.0 / scene.sim.step_hz);
    const int total = a.warmup + a.before + a.after;
    for (int f = 0; f < total; ++f) {
        if (f % 10 == 0) progress.show("run " + std::to_string(run + 1) + ", frame " + std::to_string(f + 1) + "/" + std::to_string(total), run + 1, a.runs);
        if (f == a.warmup + a.before) requestPreset(sandbox.world(), preset);
        sandbox.frame(clock.now());
    }
    sandbox.present();
    sandbox.schedule().finish();
    const ecs::FrameTimer& timer = sandbox.schedule().timer();
    const auto measured = [&](const std::vector<double>& samples) {
        const size_t skip = std::min(samples.size(), size_t(a.warmup));
        return std::vector<double>(samples.begin() + long(skip), samples.end());
    };
    return {measured(timer.frameSamples()), measured(timer.cpuSamples(ecs::Phase::Script)), measured(timer.cpuSamples(ecs::Phase::Ocean))};
}

int benchSea(const SeaBenchArgs& a) {
    const std::string path = resolveScene(a.scene);
    const SceneDef scene = loadScene(path, a.sets);
    checkRange("--before", a.before, 1, 1000000);
    checkRange("--after", a.after, 1, 1000000);
    checkRange("--warmup", a.warmup, 0, 1000000);
    checkRange("--runs", a.runs, 1, 1000);
    SeaPreset preset = SeaPreset::Storm;
    enumFromName(a.preset, preset);
    int w = scene.window.width, h = scene.window.height;
    if (!a.size.empty()) std::tie(w, h) = parseSize("--size", a.size);
    checkOutputs(a.output);

    auto platform = platform::createHeadlessPlatform({w, h});
    const MachineInfo machine = machineInfo(true);
    setLogQuiet(true);
    Progress progress("sea");
    BenchTable table(a.output.command, {"run", "median_ms", "max_before_ms", "max_change_ms", "change_frame_ms", "max_over_median",
                                        "script_change_ms", "ocean_median_ms", "ocean_max_change_ms"});
    std::vector<double> medians, maxBefore, maxChange, changeFrame, ratios, scriptChange, oceanMedian, oceanMax;
    // Phase CPU ms: the largest from the change on (the window as for the frames).
    const auto peak = [&](const std::vector<double>& v) {
        const auto from = v.begin() + std::min<long>(a.before - 1, long(v.size()));
        return from == v.end() ? 0.0 : *std::max_element(from, v.end());
    };
    for (int r = 0; r < a.runs; ++r) {
        const SeaRun run = seaRun(scene, a, preset, *platform, progress, r);
        const std::vector<double>& ms = run.frame;
        scriptChange.push_back(peak(run.script));
        oceanMedian.push_back(ecs::median(run.ocean));
        oceanMax.push_back(peak(run.ocean));
        // The frame that applies the change is the one after the request (its steps run first);
        // a sample spans a frame start to the next, so the window starts one sample early.
        const auto first = ms.begin() + std::min<long>(a.before - 1, long(ms.size()));
        const double median = ecs::median(ms);
        medians.push_back(median);
        maxBefore.push_back(*std::max_element(ms.begin(), first));
        maxChange.push_back(first == ms.end() ? 0.0 : *std::max_element(first, ms.end()));
        changeFrame.push_back(first == ms.end() ? 0.0 : *first);
        ratios.push_back(maxChange.back() / median);
        table.addRow({std::to_string(r + 1), cell(median), cell(maxBefore.back()), cell(maxChange.back()), cell(changeFrame.back()),
                      cell(ratios.back()), cell(scriptChange.back()), cell(oceanMedian.back()), cell(oceanMax.back())});
    }
    progress.done();
    setLogQuiet(false);
    table.addRow({"median", cell(ecs::median(medians)), cell(ecs::median(maxBefore)), cell(ecs::median(maxChange)),
                  cell(ecs::median(changeFrame)), cell(ecs::median(ratios)), cell(ecs::median(scriptChange)),
                  cell(ecs::median(oceanMedian)), cell(ecs::median(oceanMax))});
    table.setting("scene", path);
    table.setting("size", std::to_string(w) + "x" + std::to_string(h) + " headless");
    table.setting("change", "preset " + a.preset + " requested after " + std::to_string(a.before) + " measured frames; " +
                                std::to_string(a.after) + " frames from then on (the fade lasts 2 s)");
    table.setting("frames", std::to_string(a.warmup) + " warm-up; frame = wall ms frame start to frame start; one step per frame; "
                            "script, ocean: CPU ms of the phase (keys applied; fade built and blended, maps)");
    for (const std::string& s : a.sets) table.setting("set", s);
    table.printMarkdown(stdout);
    if (!a.output.out.empty()) table.writeCsv(a.output.out, machine);
    if (gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

} // namespace ob::game
