// `oceanbox bench KIND`: the papers' performance tables measured on this machine (docs/references.md#paper-experiments, docs/references.md#contracts).
//   spheres — [Kang2008] Table 5, fps against the number of jumping fish
//   fields  — [Kang2008] Table 3, fps by scene and ripple field size, rendered and spheres only
//   ocean   — [Lee2007] Tables 1–3, fps against spectrum size: sim + render, sim, FFT, FFTW
//   frame   — every per-phase and per-pass time of one scene's frame
//   sea     — frame times across a live change of the sea (the cross-fade): max frame / median
// Each prints a Markdown table, and writes CSV (--out) and an SVG chart (--chart).
#pragma once
#include "core/backend.h"
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ob::game {

/// Output flags every bench takes.
struct BenchOutput {
    std::string command;  ///< the command line, for the CSV's first comment line
    std::string out;      ///< CSV path ("" = none)
    std::string chart;    ///< SVG path ("" = none)
};

/// `bench spheres`: the Table 5 swarm (FishSwarm) per count.
struct SpheresBenchArgs {
    BenchOutput output;
    std::vector<long> counts{1, 10, 30, 100, 300, 1000, 3000, 10000, 30000, 100000};
    bool render = false;       ///< also draw the ripple field each frame (headless, --size)
    std::string size = "800x600";  ///< framebuffer with --render (the paper's)
    int field = 128;           ///< ripple field cells per side
    float radiusCells = 20.0f; ///< SR
    int frames = 60;           ///< measured frames per count
    int warmup = 20;           ///< frames run first, not measured
    std::string stamping = "batched";  ///< "batched" or "sequential" (stepSphere per fish)
    int workers = 0;           ///< worker threads, 0 = every core
    long long seed = 1;
};

/// `bench fields`: scenes × ripple field sizes, rendered and spheres only.
struct FieldsBenchArgs {
    BenchOutput output;
    std::vector<long> sizes{64, 128, 256, 512, 1024, 2048};
    std::vector<std::string> scenes{"cannon", "fish", "ship", "all"};
    std::string model = "kang2008";  ///< ripples.model for every run: "kang2008" ([Kang2008]'s) or "ewave"
    bool noRender = false;     ///< only the spheres-only rows
    std::string size = "800x600";
    int frames = 30;
    int warmup = 5;
    std::vector<std::string> sets;
};

/// `bench ocean`: spectrum sizes × backends.
struct OceanBenchArgs {
    BenchOutput output;
    std::vector<long> sizes{64, 128, 256, 512, 1024};
    std::vector<std::string> backendWords{"cpu", "gpu"};  ///< --backend as given: "cpu" and/or "gpu" (oceanBackends reads them)
    std::string scene;         ///< scene drawn for sim + render (default: config/scenes/default.toml)
    std::string size = "1280x1024";  ///< the paper's
    bool noRender = false;     ///< skip sim + render
    int frames = 20;
    int warmup = 3;
    std::vector<std::string> sets;
};

/// `bench frame SCENE`.
struct FrameBenchArgs {
    BenchOutput output;
    std::string scene;
    std::string size;          ///< "" = the scene's [window]
    int frames = 60;
    int warmup = 10;
    std::vector<std::string> sets;
};

/// `bench sea [SCENE]`.
struct SeaBenchArgs {
    BenchOutput output;
    std::string scene = "default";  ///< scene name or path
    std::string size;          ///< "" = the scene's [window]
    std::string preset = "storm";  ///< the change: a preset (calm, breeze, storm) requested at the change frame
    int before = 60;           ///< measured frames before the change
    int after = 150;           ///< measured frames from the change on (the fade is 2 s: 120 steps at 60 Hz)
    int warmup = 30;           ///< frames run first, not measured
    int runs = 3;              ///< runs, each a fresh world; the table's last row is their median
    std::vector<std::string> sets;
};

int benchSpheres(const SpheresBenchArgs& args);
int benchFields(const FieldsBenchArgs& args);
int benchOcean(const OceanBenchArgs& args);
/// The backends `bench ocean` measures, in the order given (throws InputError naming --backend
/// for a word that is neither cpu nor gpu).
std::vector<Backend> oceanBackends(const OceanBenchArgs& args);
int benchFrame(const FrameBenchArgs& args);
int benchSea(const SeaBenchArgs& args);

/// Parses "WxH" (16..8192 each); throws ob::InputError naming the flag.
std::pair<int, int> parseSize(const std::string& flag, const std::string& text);

/// Throws ob::InputError unless lo <= v <= hi, naming the flag.
void checkRange(const char* flag, long v, long lo, long hi);
/// Throws ob::InputError unless the --out and --chart paths can be written, are not one
/// file, and are none of `scenes` (the scene files the bench reads).
void checkOutputs(const BenchOutput& output, const std::vector<std::string>& scenes = {});

/// Resolves a scene name ("fish" → config/scenes/fish.toml beside the default scene) or a
/// path; throws ob::InputError when there is no such file.
std::string resolveScene(const std::string& nameOrPath);

} // namespace ob::game
