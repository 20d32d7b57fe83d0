// `oceanbox bench`: the subcommands' flags, and the spheres bench ([Kang2008] Table 5).
#include "bench/cmd_bench.h"
#include "cli/cli_checks.h"
#include "core/file_identity.h"
#include "cli/commands.h"

#include "core/file_write.h"
#include "bench/bench_report.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/log.h"
#include "sim/fish_swarm.h"
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "bench/paper_tables.h"
#include "platform/platform.h"
#include "world/scene.h"
#include "bench/svg_chart.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <regex>

namespace ob::game {

std::pair<int, int> parseSize(const std::string& flag, const std::string& text) {
    std::smatch m;
    static const std::regex WXH(R"((\d{1,5})x(\d{1,5}))");
    if (!std::regex_match(text, m, WXH) || std::stoi(m[1]) < 16 || std::stoi(m[2]) < 16 || std::stoi(m[1]) > 8192 ||
        std::stoi(m[2]) > 8192)
        throw InputError(flag + " '" + text + "': expected WxH with 16 <= W, H <= 8192, e.g. 800x600");
    return {std::stoi(m[1]), std::stoi(m[2])};
}

std::string resolveScene(const std::string& nameOrPath) {
    namespace fs = std::filesystem;
    const bool path = nameOrPath.find('/') != std::string::npos || fs::path(nameOrPath).extension() == ".toml";
    const std::string file = path ? nameOrPath : (fs::path(defaultScenePath()).parent_path() / (nameOrPath + ".toml")).string();
    if (!fs::is_regular_file(file))
        throw InputError("scene '" + nameOrPath + "': no scene file " + file +
                         (path ? "" : " (give a scene name from config/scenes/ or a path to a .toml file)"));
    return file;
}

void checkOutputs(const BenchOutput& o, const std::vector<std::string>& scenes) {
    if (!o.out.empty()) checkWritable(o.out, "CSV");
    if (!o.chart.empty()) checkWritable(o.chart, "chart");
    std::vector<NamedPath> inputs;
    for (const std::string& scene : scenes) inputs.push_back({"the scene file", scene});
    checkOutputsApart(inputs, {{"--out", o.out}, {"--chart", o.chart}});
}

void checkRange(const char* flag, long v, long lo, long hi) {
    if (v < lo || v > hi)
        throw InputError(std::string(flag) + ": must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                         std::to_string(v));
}

namespace {

void addOutputFlags(CLI::App* cmd, BenchOutput& o) {
    cmd->add_option("--out", o.out, "write the table as CSV (machine and settings in # lines)")->check(NON_EMPTY_PATH);
    cmd->add_option("--chart", o.chart, "write an SVG chart, with the paper's numbers where it has them")->check(NON_EMPTY_PATH);
}

using Ms = std::chrono::duration<double, std::milli>;

// The ripple field seen from above one side, as the swarm bench draws it: water surface only
// (flat sea, no FFT or Gerstner layers), sky behind.
gfx::CameraView swarmCamera(float extent, glm::ivec2 size) {
    gfx::CameraView v;
    const glm::vec3 target(0.5f * extent, 0.0f, 0.5f * extent);
    v.position = target + glm::vec3(0.0f, 0.55f * extent, -0.85f * extent);
    v.view = glm::lookAtRH(v.position, target, glm::vec3(0, 1, 0));
    v.projection = glm::perspectiveRH_NO(glm::radians(60.0f), float(size.x) / float(size.y), 0.1f, v.farM);
    return v;
}

// The flags' ranges and values (exit 2 with the flag's name).
void checkSpheresArgs(const SpheresBenchArgs& a) {
    if (a.counts.empty()) throw InputError("--counts: give at least one count");
    for (long c : a.counts) checkRange("--counts", c, 1, 10000000);
    checkRange("--field", a.field, 3, 8192);
    if (!(a.radiusCells > 0.0f && a.radiusCells <= 1000.0f))
        throw InputError("--radius-cells: must be in (0, 1000], got " + std::to_string(a.radiusCells));
    checkRange("--frames", a.frames, 1, 1000000);
    checkRange("--warmup", a.warmup, 0, 1000000);
    if (a.seed < 0) throw InputError("--seed: must be >= 0");
    checkRange("--workers", a.workers, 0, 256);
}

// The chart: our fps against [Kang2008]'s Table 5.
void writeSpheresChart(const SpheresBenchArgs& a, const ChartSeries& ours) {
    Chart chart;
    char title[128];
    std::snprintf(title, sizeof title, "Jumping fish: fps against spheres (SR %g, %d² field)", double(a.radiusCells), a.field);
    chart.title = title;
    chart.xLabel = "fish (one bounding sphere each)";
    chart.yLabel = "frames per second";
    chart.logX = true;
    chart.logY = true;
    chart.series.push_back(ours);
    ChartSeries paper{"[Kang2008] Table 5 (2.6 GHz CPU, 2008)", {}, {}, true, 1};
    for (const PaperSwarmFps& p : SEED001_TABLE5) {
        paper.x.push_back(p.count);
        paper.y.push_back(p.fps);
    }
    chart.series.push_back(paper);
    writeChart(a.output.chart, chart);
}

} // namespace

// The spheres table: its columns and the settings every row shares.
static BenchTable spheresTable(const SpheresBenchArgs& a, const FishSwarmDef& base) {
    std::vector<std::string> columns{"count", "fps", "ms_frame", "ms_stamp", "ms_step"};
    if (a.render) columns.push_back("ms_render");
    BenchTable table(a.output.command, columns);
    char buf[256];
    std::snprintf(buf, sizeof buf, "%d² cells of %g m, fixed boundary, SR %g, SHR %g, AF %g, DF %g, %g Hz", a.field,
                  double(base.cell_size), double(a.radiusCells), double(base.height_ratio),
                  double(base.acceleration_factor), double(base.damping), double(base.step_hz));
    table.setting("field", buf);
    table.setting("stamping", a.stamping + ", " + std::to_string(workerCount()) + " worker(s)");
    table.setting("frames", std::to_string(a.frames) + " measured after " + std::to_string(a.warmup) +
                                " warm-up; medians; one simulation step per frame");
    table.setting("render", a.render ? "water surface with the ripple layer, " + a.size + " headless (fish not drawn)"
                                     : "none (fish not drawn)");
    return table;
}

int benchSpheres(const SpheresBenchArgs& a) {
    checkSpheresArgs(a);
    const auto [w, h] = parseSize("--size", a.size);
    checkOutputs(a.output);
    setWorkerCount(a.workers);

    // --- optional rendering: the water surface with the ripple layer, headless
    std::unique_ptr<platform::Platform> platform;
    std::unique_ptr<gfx::Renderer> renderer;
    if (a.render) {
        platform = platform::createHeadlessPlatform({w, h});
        renderer = std::make_unique<gfx::Renderer>(gfx::RenderDef{});
    }
    const MachineInfo machine = machineInfo(a.render);

    FishSwarmDef base;
    base.field = a.field;
    base.radius_cells = a.radiusCells;
    base.seed = uint64_t(a.seed);
    base.mode = a.stamping == "sequential" ? StampMode::Sequential : StampMode::Batched;
    BenchTable table = spheresTable(a, base);

    Progress progress("spheres");
    ChartSeries ours{a.render ? "oceanbox (rendered)" : "oceanbox (no rendering)", {}, {}, false, 0};
    for (size_t k = 0; k < a.counts.size(); ++k) {
        FishSwarmDef def = base;
        def.count = int(a.counts[k]);
        FishSwarm swarm(def);
        std::vector<double> frame, stamp, step, render;
        const int total = a.warmup + a.frames;
        for (int f = 0; f < total; ++f) {
            if (f % 10 == 0)
                progress.show(std::to_string(def.count) + " fish, frame " + std::to_string(f + 1) + "/" + std::to_string(total),
                              int(k + 1), int(a.counts.size()));
            const auto t0 = std::chrono::steady_clock::now();
            swarm.step();
            double renderMs = 0.0;
            if (renderer) {
                const auto r0 = std::chrono::steady_clock::now();
                gfx::WaterView water;
                water.ripples = swarm.field().current().data();
                water.rippleCells = def.field;
                water.rippleOrigin = glm::vec2(0.0f);
                water.rippleCellSize = def.cell_size;
                const glm::ivec2 fb = platform->framebufferSize();
                renderer->render(swarmCamera(float(def.field) * def.cell_size, fb), water, {}, double(f) / def.step_hz, fb);
                platform->present();
                renderMs = Ms(std::chrono::steady_clock::now() - r0).count();
            }
            if (f < a.warmup) continue;
            frame.push_back(Ms(std::chrono::steady_clock::now() - t0).count());
            stamp.push_back(swarm.lastTimings().stamp);
            step.push_back(swarm.lastTimings().step);
            render.push_back(renderMs);
        }
        const double frameMs = medianOf(frame);
        std::vector<std::string> row{std::to_string(def.count), cell(1000.0 / frameMs), cell(frameMs), cell(medianOf(stamp)),
                                     cell(medianOf(step))};
        if (a.render) row.push_back(cell(medianOf(render)));
        table.addRow(row);
        ours.x.push_back(double(def.count));
        ours.y.push_back(1000.0 / frameMs);
    }
    progress.done();
    table.printMarkdown(stdout);
    if (!a.output.out.empty()) table.writeCsv(a.output.out, machine);
    if (!a.output.chart.empty()) writeSpheresChart(a, ours);
    if (renderer && gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

namespace {

// One kind of bench: its subcommand and its arguments (the command line kept for the report),
// with the action that runs it; the caller adds the kind's flags, then addOutputFlags.
template <class Args> struct BenchKind {
    CLI::App* command;
    std::shared_ptr<Args> args;
};
template <class Args>
BenchKind<Args> addBenchKind(CLI::App* bench, CommandAction& action, const std::string& commandLine, const char* name,
                             const char* help, int (*run)(const Args&)) {
    auto args = std::make_shared<Args>();
    args->output.command = commandLine;
    CLI::App* command = bench->add_subcommand(name, help);
    command->callback([&action, args, run] { action = [args, run] { return run(*args); }; });
    return {command, args};
}

void addSetFlag(CLI::App* command, std::vector<std::string>& sets) {
    command->add_option("--set", sets, "override a scene key: key.path=value (repeatable)");
}

// bench spheres
void addSpheresBench(CLI::App* bench, CommandAction& action, const std::string& commandLine) {
    auto [s, spheres] = addBenchKind(bench, action, commandLine, "spheres",
                                     "[Kang2008] Table 5: fps against the number of jumping fish (one sphere each)", &benchSpheres);
    s->add_option("--counts", spheres->counts, "fish counts, comma-separated")->delimiter(',');
    s->add_flag("--render", spheres->render, "also draw the water with the ripple layer each frame (headless)");
    s->add_option("--size", spheres->size, "framebuffer WxH with --render (default 800x600, the paper's)");
    s->add_option("--field", spheres->field, "ripple field cells per side (default 128)");
    s->add_option("--radius-cells", spheres->radiusCells, "sphere radius SR in cells (default 20)")->check(FINITE_NUMBER);
    s->add_option("--frames", spheres->frames, "measured frames per count (default 60)");
    s->add_option("--warmup", spheres->warmup, "frames run before measuring (default 20)");
    s->add_option("--stamping", spheres->stamping, "batched (default) or sequential (stepSphere per fish, the reference)")
        ->check(CLI::IsMember({"batched", "sequential"}));
    s->add_option("--seed", spheres->seed, "swarm seed (default 1)")->check(SEED);
    s->add_option("--workers", spheres->workers, "worker threads (default 0: every core)");
    addOutputFlags(s, spheres->output);
}

// bench fields
void addFieldsBench(CLI::App* bench, CommandAction& action, const std::string& commandLine) {
    auto [f, fields] = addBenchKind(bench, action, commandLine, "fields",
                                    "[Kang2008] Table 3: fps by scene and ripple field size, rendered and spheres only", &benchFields);
    f->add_option("--sizes", fields->sizes, "ripple field sizes (ripples.resolution), comma-separated")->delimiter(',');
    f->add_option("--scenes", fields->scenes, "scene names (config/scenes/NAME.toml) or paths, comma-separated")->delimiter(',');
    f->add_option("--model", fields->model, "ripple model of every run: kang2008 (default, the paper's) or ewave")
        ->check(CLI::IsMember(std::vector<std::string>(interaction::RippleModels::NAMES.begin(), interaction::RippleModels::NAMES.end())));
    f->add_flag("--no-render", fields->noRender, "only the spheres-only rows (interaction phase, nothing drawn)");
    f->add_option("--size", fields->size, "framebuffer WxH for the rendered rows (default 800x600, the paper's)");
    f->add_option("--frames", fields->frames, "measured frames per point (default 30)");
    f->add_option("--warmup", fields->warmup, "frames run before measuring (default 5)");
    addSetFlag(f, fields->sets);
    addOutputFlags(f, fields->output);
}

// bench ocean
void addOceanBench(CLI::App* bench, CommandAction& action, const std::string& commandLine) {
    auto [o, ocean] = addBenchKind(bench, action, commandLine, "ocean",
                                   "[Lee2007] Tables 1-3: fps against spectrum size (sim + render, sim, FFT, FFTW)", &benchOcean);
    o->add_option("--sizes", ocean->sizes, "spectrum sizes N (ocean.resolution), comma-separated")->delimiter(',');
    o->add_option("--backend", ocean->backendWords, "cpu, gpu or both, comma-separated")->delimiter(',');
    o->add_option("--scene", ocean->scene, "scene drawn for sim + render (default config/scenes/default.toml)");
    o->add_option("--size", ocean->size, "framebuffer WxH for sim + render (default 1280x1024, the paper's)");
    o->add_flag("--no-render", ocean->noRender, "skip the sim + render column");
    o->add_option("--frames", ocean->frames, "measured frames or updates per point (default 20)");
    o->add_option("--warmup", ocean->warmup, "frames or updates run before measuring (default 3)");
    addSetFlag(o, ocean->sets);
    addOutputFlags(o, ocean->output);
}

// bench frame SCENE
void addFrameBench(CLI::App* bench, CommandAction& action, const std::string& commandLine) {
    auto [r, frame] = addBenchKind(bench, action, commandLine, "frame", "every per-phase CPU and GPU time of one scene's frame", &benchFrame);
    r->add_option("scene", frame->scene, "scene name (config/scenes/NAME.toml) or path")->required();
    r->add_option("--size", frame->size, "framebuffer WxH (default: the scene's [window])");
    r->add_option("--frames", frame->frames, "measured frames (default 60)");
    r->add_option("--warmup", frame->warmup, "frames run before measuring (default 10)");
    addSetFlag(r, frame->sets);
    addOutputFlags(r, frame->output);
}

// bench sea [SCENE]
void addSeaBench(CLI::App* bench, CommandAction& action, const std::string& commandLine) {
    auto [e, sea] = addBenchKind(bench, action, commandLine, "sea",
                                 "frame times across a live change of the sea (cross-fade): max frame / median", &benchSea);
    e->add_option("scene", sea->scene, "scene name (config/scenes/NAME.toml) or path (default: default)");
    e->add_option("--size", sea->size, "framebuffer WxH (default: the scene's [window])");
    e->add_option("--preset", sea->preset, "the change: calm, breeze or storm (default storm)")->check(CLI::IsMember({"calm", "breeze", "storm"}));
    e->add_option("--before", sea->before, "measured frames before the change (default 60)");
    e->add_option("--after", sea->after, "measured frames from the change on (default 150)");
    e->add_option("--warmup", sea->warmup, "frames run before measuring (default 30)");
    e->add_option("--runs", sea->runs, "runs, each a fresh world (default 3)");
    addSetFlag(e, sea->sets);
    addOutputFlags(e, sea->output);
}

} // namespace

void addBenchCommand(CLI::App& app, CommandAction& action, const std::string& commandLine) {
    CLI::App* bench = app.add_subcommand("bench", "benchmarks that reproduce the papers' tables (spheres, fields, ocean, frame, sea)");
    bench->require_subcommand(0, 1);
    bench->callback([&action, bench] {
        if (!bench->get_subcommands().empty()) return;
        std::string got;
        for (const std::string& word : bench->remaining()) got += (got.empty() ? "" : " ") + word;
        action = [got] {
            throw InputError("bench: expected a kind, spheres, fields, ocean, frame or sea" +
                             (got.empty() ? std::string() : ", got '" + got + "'"));
            return EXIT_BAD_INPUT;
        };
    });
    addSpheresBench(bench, action, commandLine);
    addFieldsBench(bench, action, commandLine);
    addOceanBench(bench, action, commandLine);
    addFrameBench(bench, action, commandLine);
    addSeaBench(bench, action, commandLine);
    // A word that is no kind lands in bench's extras and is named in the message (set after
    // the subcommands, which would otherwise inherit it).
    bench->allow_extras();
}

} // namespace ob::game
