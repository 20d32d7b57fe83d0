// oceanbox dump LAYER SCENE: a layer of the water as a NumPy .npy field (docs/references.md#contracts).
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/scene_flags.h"
#include "ocean/ocean_fft_cpu.h"
#include "tools/cmd_dump_foam.h"
#include "tools/cmd_dump_ocean.h"
#include "tools/cmd_dump_ripples.h"
#include "tools/cmd_dump_surface.h"
#include "water/composite_water.h"

#include <memory>

namespace ob::game {

namespace {

struct DumpArgs {
    SceneFlags scene;
    std::string layer, out, points;
    double time = 0.0;
    int grid = 0;
    int frames = -1;
    float extent = 0.0f;
};

int dump(const DumpArgs& a) {
    SceneDef scene = a.scene.load();
    checkWritable(a.out, "output");
    std::vector<NamedPath> inputs = sceneInputs(scene, a.scene.scene);
    inputs.push_back({"--points", a.points});
    checkOutputsApart(inputs, {{"--out", a.out}});
    if (a.layer == "ocean") return dumpOcean(scene.ocean, a.time, a.out);
    if (a.layer == "ripples") {
        if (a.frames < 0) throw InputError("dump ripples needs --frames K");
        return dumpRipples(scene, a.frames, a.out);
    }
    if (a.layer == "foam") {
        if (a.frames < 0) throw InputError("dump foam needs --frames K");
        return dumpFoam(scene, a.frames, a.out);
    }
    if (a.layer == "gerstner") {
        if (a.grid <= 0 || a.extent <= 0.0f) throw InputError("dump gerstner needs --grid N and --extent E (both > 0)");
        return dumpGerstner(scene.gerstner, scene.ocean.gravity, a.time, a.grid, a.extent, a.out, &scene.ocean);
    }
    if (a.points.empty()) throw InputError("dump surface needs --points P.npy");
    ocean::OceanFftCpu fft(scene.ocean);
    std::vector<ocean::GerstnerWave> waves = ocean::resolveWaves(scene.gerstner, scene.ocean);
    water::CompositeWater surface(waves, scene.ocean.gravity, &fft);
    water::primeAt(&fft, surface, a.time);
    return dumpSurface(surface, a.points, a.out, largestWavenumber(waves, &fft));
}

} // namespace

void addDumpCommand(CLI::App& app, CommandAction& action) {
    auto a = std::make_shared<DumpArgs>();
    CLI::App* cmd = app.add_subcommand("dump", "write a layer of the water as a NumPy .npy field");
    cmd->add_option("layer", a->layer,
                    "ocean: the first FFT cascade [N, N, 5] = (h, Dx, Dz, dh/dx, dh/dz); "
                    "gerstner: [N, N, 6] = (x, y, z, nx, ny, nz) of rest points (i, j)·E/N; "
                    "surface: [K, 5] = (height, nx, ny, nz, vertical velocity) at --points; "
                    "ripples: the ripple field Vh(t) [N, N] after --frames K; "
                    "foam: the foam map's coverage [N, N] after --frames K (logs the share of samples over 0.5)")
        ->required()->check(CLI::IsMember({"ocean", "gerstner", "surface", "ripples", "foam"}));
    cmd->add_option("scene", a->scene.scene, "scene file")->required();
    cmd->add_option("--time", a->time, "simulated time (s)")->check(FINITE_NUMBER)->check(CLI::Range(0.0, 1e9));
    cmd->add_option("--out", a->out, "output .npy file")->required()->check(NON_EMPTY_PATH);
    cmd->add_option("--grid", a->grid, "gerstner: rest points per side N");
    cmd->add_option("--extent", a->extent, "gerstner: side E of the rest grid (m)")->check(FINITE_NUMBER);
    cmd->add_option("--points", a->points, "surface: float32 .npy [K, 2] of world (x, z)")->check(NON_EMPTY_PATH);
    cmd->add_option("--frames", a->frames, "ripples, foam: frames (simulation steps) to run first")->check(NON_NEGATIVE);
    cmd->add_option("--set", a->scene.sets, "override a scene key: key.path=value (repeatable)");
    cmd->add_option("--seed", a->scene.seed, "scene seed (same as --set sim.seed=N)")->check(SEED);
    cmd->callback([&action, a] { action = [a] { return dump(*a); }; });
}

} // namespace ob::game
