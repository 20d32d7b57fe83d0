// CLI11 wiring: every subcommand, its flags, and the mapping of errors to exit codes.
#include "cli/cli.h"

#include "tools/app.h"
#include "bench/cmd_bench.h"
#include "tools/cmd_dump_ocean.h"
#include "tools/cmd_dump_ripples.h"
#include "tools/cmd_dump_surface.h"
#include "tools/cmd_make_models.h"
#include "tools/cmd_soak.h"
#include "ocean/ocean_fft_cpu.h"
#include "water/composite_water.h"
#include "tools/cmd_ripple.h"
#include "core/error.h"
#include "core/log.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <regex>

namespace ob::game {

namespace {

// Flags shared by the scene subcommands.
struct SceneFlags {
    std::string scene;
    std::vector<std::string> sets;
    bool headless = false;
    std::string size;
    long frames = 0;
    long long seed = -1;
    std::string screenshot;
    std::string stats;
    std::string input;
    int stepsPerFrame = 1;

    void addTo(CLI::App* cmd, long defaultFrames) {
        frames = defaultFrames;
        cmd->add_option("--set", sets, "override a scene key: key.path=value (TOML value; repeatable)");
        cmd->add_flag("--headless", headless, "render off-screen with OSMesa (no window)");
        cmd->add_option("--size", size, "framebuffer size WxH in pixels (default: the scene's [window])");
        cmd->add_option("--frames", frames, "frames to run")->check(CLI::Range(1L, 100000000L));
        cmd->add_option("--seed", seed, "scene seed (same as --set sim.seed=N)")->check(CLI::NonNegativeNumber);
        cmd->add_option("--screenshot", screenshot, "write the last frame to this PNG");
        cmd->add_option("--stats", stats, "write a JSON summary (frames, per-phase ms, entities, state hash)");
        cmd->add_option("--input", input, "scripted input: a TOML file of [[press]] and [[mouse]] entries (README)");
        cmd->add_option("--steps-per-frame", stepsPerFrame,
                        "fixed clock: simulation steps each rendered frame advances (a slow machine's frame), 1-64")
            ->check(CLI::Range(1, 64));
    }

    SceneDef load() const {
        std::vector<std::string> overrides = sets;
        if (seed >= 0) overrides.push_back("sim.seed=" + std::to_string(seed));
        return loadScene(scene, overrides);
    }

    RunOptions options() const {
        RunOptions o;
        o.window = !headless;
        o.frames = frames;
        o.screenshot = screenshot;
        o.stats = stats;
        o.input = input;
        o.stepsPerFrame = stepsPerFrame;
        for (const std::string& set : sets) o.dynamicResolution = o.dynamicResolution || set.rfind("render.target_fps", 0) == 0;
        if (!size.empty()) {
            std::smatch m;
            static const std::regex WXH(R"((\d{1,5})x(\d{1,5}))");
            if (!std::regex_match(size, m, WXH) || std::stoi(m[1]) < 16 || std::stoi(m[2]) < 16 ||
                std::stoi(m[1]) > 8192 || std::stoi(m[2]) > 8192)
                throw InputError("--size '" + size + "': expected WxH with 16 <= W, H <= 8192, e.g. 1280x720");
            o.size = {std::stoi(m[1]), std::stoi(m[2])};
        }
        return o;
    }
};

// `play --help`: every key and mouse action (the overlay shows those of the scene).
const char* const PLAY_KEYS = R"(Keys and mouse (H shows and hides the overlay, which lists those this scene uses):
  right drag    orbit the camera about what it looks at (fly mode: look around)
  wheel         zoom: follow distance, orbit radius (fly mode: move forward)
  C             camera mode: follow (a ship) -> orbit -> fly
  W/S  A/D      ship: throttle, rudder (fly mode: move the camera)
  Q/E  Shift    fly mode: down, up; Shift x4 speed; hold Q at the surface to dive
  arrows        cannon: aim (yaw, elevation)
  Space, click  cannon: fire one ball per press
  F             a school of fish where the camera looks
  P  N          pause and resume; one step while paused
  F12           screenshot (oceanbox_shot_NNN.png)
  H             show or hide the overlay
  Esc           quit)";

} // namespace

int runCli(int argc, char** argv) {
    CLI::App app{"oceanbox: an interactive water sandbox (Tessendorf FFT ocean, Gerstner waves, "
                 "interactive ripples, buoyant bodies)",
                 "oceanbox"};
    app.require_subcommand(1);
    app.fallthrough(false);
    std::function<int()> action;

    // play [SCENE]
    SceneFlags play;
    play.scene = defaultScenePath();
    CLI::App* playCmd = app.add_subcommand("play", "open a scene in a window (headless with a screenshot where there is no display)");
    playCmd->add_option("scene", play.scene, "scene file (default: config/scenes/default.toml)");
    play.addTo(playCmd, 0);
    playCmd->footer(PLAY_KEYS);
    playCmd->callback([&] {
        action = [&] {
            SceneDef scene = play.load();
            if (scene.info.purpose == "benchmark")
                logInfo("%s is a benchmark scene: %s", play.scene.c_str(),
                        scene.info.note.empty() ? "it measures, it is not meant to look like the sea" : scene.info.note.c_str());
            else if (!scene.info.note.empty())
                logInfo("%s", scene.info.note.c_str());
            RunOptions o = play.options();
            o.realTime = true;
            o.dynamicResolution = true;
            if (o.frames == 0) o.frames = -1;
            if (!platform::displayAvailable() || play.headless) {
                // No window to look at: run a fixed number of frames and keep a picture.
                o.window = false;
                o.realTime = false;
                o.dynamicResolution = play.options().dynamicResolution;  // reproducible unless asked
                if (o.frames < 0) o.frames = 600;
                if (o.screenshot.empty()) o.screenshot = "oceanbox.png";
            }
            o.fallbackNote = "no display found: running headless for " + std::to_string(o.frames) +
                             " frames, screenshot " + o.screenshot;
            if (!play.headless && !platform::displayAvailable()) logInfo("%s", o.fallbackNote.c_str());
            o.fallbackNote.clear();
            return runScene(scene, play.scene, o);
        };
    });

    // run SCENE
    SceneFlags run;
    CLI::App* runCmd = app.add_subcommand("run", "run a scene for a number of frames at exactly one simulation step per frame");
    runCmd->add_option("scene", run.scene, "scene file")->required();
    run.addTo(runCmd, 600);
    runCmd->callback([&] {
        action = [&] {
            SceneDef scene = run.load();
            RunOptions o = run.options();
            if (runCmd->count("--frames") == 0 && scene.sim.end_time > 0.0f) {
                o.frames = -1;  // the scene says how long it lasts
                o.endTime = scene.sim.end_time;
            }
            o.fallbackNote = "no display found: running headless";
            return runScene(scene, run.scene, o);
        };
    });

    // bench KIND
    std::string commandLine = "oceanbox";
    for (int i = 1; i < argc; ++i) commandLine += std::string(" ") + argv[i];
    addBenchCommand(app, action, commandLine);

    // dump LAYER SCENE
    std::string dumpLayer, dumpOut, dumpPoints;
    double dumpTime = 0.0;
    int dumpGrid = 0;
    int dumpFrames = -1;
    float dumpExtent = 0.0f;
    SceneFlags dump;
    CLI::App* dumpCmd = app.add_subcommand("dump", "write a layer of the water as a NumPy .npy field");
    dumpCmd->add_option("layer", dumpLayer,
                        "ocean: the first FFT cascade [N, N, 5] = (h, Dx, Dz, dh/dx, dh/dz); "
                        "gerstner: [N, N, 6] = (x, y, z, nx, ny, nz) of rest points (i, j)·E/N; "
                        "surface: [K, 5] = (height, nx, ny, nz, vertical velocity) at --points; "
                        "ripples: the ripple field Vh(t) [N, N] after --frames K")
        ->required()->check(CLI::IsMember({"ocean", "gerstner", "surface", "ripples"}));
    dumpCmd->add_option("scene", dump.scene, "scene file")->required();
    dumpCmd->add_option("--time", dumpTime, "simulated time (s)")->check(CLI::Range(0.0, 1e9));
    dumpCmd->add_option("--out", dumpOut, "output .npy file")->required();
    dumpCmd->add_option("--grid", dumpGrid, "gerstner: rest points per side N");
    dumpCmd->add_option("--extent", dumpExtent, "gerstner: side E of the rest grid (m)");
    dumpCmd->add_option("--points", dumpPoints, "surface: float32 .npy [K, 2] of world (x, z)");
    dumpCmd->add_option("--frames", dumpFrames, "ripples: frames (simulation steps) to run first")->check(CLI::NonNegativeNumber);
    dumpCmd->add_option("--set", dump.sets, "override a scene key: key.path=value (repeatable)");
    dumpCmd->add_option("--seed", dump.seed, "scene seed (same as --set sim.seed=N)")->check(CLI::NonNegativeNumber);
    dumpCmd->callback([&] {
        action = [&] {
            SceneDef scene = dump.load();
            checkWritable(dumpOut, "output");
            if (dumpLayer == "ocean") return dumpOcean(scene.ocean, dumpTime, dumpOut);
            if (dumpLayer == "ripples") {
                if (dumpFrames < 0) throw InputError("dump ripples needs --frames K");
                return dumpRipples(scene, dumpFrames, dumpOut);
            }
            if (dumpLayer == "gerstner") {
                if (dumpGrid <= 0 || dumpExtent <= 0.0f) throw InputError("dump gerstner needs --grid N and --extent E (both > 0)");
                return dumpGerstner(scene.gerstner, scene.ocean.gravity, dumpTime, dumpGrid, dumpExtent, dumpOut, &scene.ocean);
            }
            if (dumpPoints.empty()) throw InputError("dump surface needs --points P.npy");
            ocean::OceanFftCpu fft(scene.ocean);
            std::vector<ocean::GerstnerWave> waves = ocean::resolveWaves(scene.gerstner, scene.ocean);
            water::CompositeWater surface(waves, scene.ocean.gravity, &fft);
            water::primeAt(&fft, surface, dumpTime);
            return dumpSurface(surface, dumpPoints, dumpOut);
        };
    });

    // ripple: the bare solver on .npy fields (no scene)
    RippleArgs ripple;
    CLI::App* rippleCmd = app.add_subcommand("ripple", "run a bare ripple solver on a .npy field: kang2008 (seed 001 eq. 1-2, "
                                                       "fixed boundary) or ewave (dispersive, exact per Fourier mode)");
    rippleCmd->add_option("--model", ripple.model, "kang2008 (default) or ewave");
    rippleCmd->add_option("--in", ripple.in, "kang2008 Vh(t), ewave h: float32 .npy [N, M]")->required();
    rippleCmd->add_option("--prev", ripple.prev, "kang2008: Vh(t-1), same shape (default: --in)");
    rippleCmd->add_option("--vel", ripple.vel, "ewave: the vertical velocity v (m/s), same shape (default: 0)");
    rippleCmd->add_option("--steps", ripple.steps, "steps K >= 0")->required();
    rippleCmd->add_option("--damping", ripple.damping, "kang2008: damping factor DF in [0, 1]; ewave: decay time (s, 0 = none)")->required();
    rippleCmd->add_option("--viscosity", ripple.viscosity, "ewave: effective viscosity (m2/s, default 0)");
    rippleCmd->add_option("--dt", ripple.dt, "ewave: step (s, default 1/60)");
    rippleCmd->add_option("--cell-size", ripple.cellSize, "ewave: metres per cell (default 0.25)");
    rippleCmd->add_option("--boundary", ripple.boundary, "ewave: periodic (default), fixed or absorbing; kang2008: fixed");
    rippleCmd->add_option("--out", ripple.out, "kang2008 Vh(t), ewave h after K steps (.npy)")->required();
    rippleCmd->callback([&] {
        action = [&] {
            checkWritable(ripple.out, "output");
            return rippleCommand(ripple);
        };
    });

    // soak SCENE: a long headless simulation with invariants checked
    SceneFlags soak;
    SoakOptions soakOptions;
    CLI::App* soakCmd = app.add_subcommand("soak", "simulate a scene headless (no rendering) for a long time, checking "
                                                   "finite fields, bounded heights, floating bodies and flat memory");
    soakCmd->add_option("scene", soak.scene, "scene file")->required();
    soakCmd->add_option("--seconds", soakOptions.seconds, "simulated seconds (default 3600: one hour)")
        ->check(CLI::Range(1e-3, 1e7));
    soakCmd->add_option("--check-every", soakOptions.checkEvery, "check the invariants every N steps (default 1)")
        ->check(CLI::Range(1, 1000000));
    soakCmd->add_option("--stats", soakOptions.stats, "write a JSON summary (steps/s, maxima, RSS, state hash)");
    soakCmd->add_option("--set", soak.sets, "override a scene key: key.path=value (repeatable)");
    soakCmd->add_option("--seed", soak.seed, "scene seed (same as --set sim.seed=N)")->check(CLI::NonNegativeNumber);
    soakCmd->callback([&] { action = [&] { return soakCommand(soak.load(), soak.scene, soakOptions); }; });

    // make-models: the project's own glTF models
    std::string modelsOut = "assets/models";
    CLI::App* modelsCmd = app.add_subcommand("make-models", "write the project's own glTF models (ship, fish, cannonball, cannon)");
    modelsCmd->add_option("--out", modelsOut, "output folder (default: assets/models)");
    modelsCmd->callback([&] { action = [&] { return makeModels(modelsOut); }; });

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string what = e.what();
        std::fprintf(stderr, "oceanbox: %s\nRun 'oceanbox --help' (or 'oceanbox SUBCOMMAND --help') for usage.\n", what.c_str());
        return EXIT_BAD_INPUT;
    }

    try {
        return action ? action() : EXIT_BAD_INPUT;
    } catch (const InputError& e) {
        std::fprintf(stderr, "oceanbox: error: %s\n", e.what());
        return EXIT_BAD_INPUT;
    } catch (const RuntimeError& e) {
        std::fprintf(stderr, "oceanbox: failed: %s\n", e.what());
        return EXIT_FAILURE_RUNTIME;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "oceanbox: failed: %s\n", e.what());
        return EXIT_FAILURE_RUNTIME;
    }
}

} // namespace ob::game
