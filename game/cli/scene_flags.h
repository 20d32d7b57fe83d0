// The flags every scene subcommand shares (play, run, dump, soak) and what they become.
#pragma once
#include "cli/cli_checks.h"
#include "core/error.h"
#include "core/log.h"
#include "core/printable.h"
#include "platform/window_def.h"
#include "tools/app.h"
#include "world/scene.h"
#include "world/scene_budget.h"

#include <CLI/CLI.hpp>
#include <regex>
#include <string>
#include <vector>

namespace ob::game {

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
    std::string record;  // play only
    int stepsPerFrame = 1;

    void addTo(CLI::App* cmd, long defaultFrames) {
        frames = defaultFrames;
        cmd->add_option("--set", sets, "override a scene key: key.path=value (TOML value; repeatable)");
        cmd->add_flag("--headless", headless, "render off-screen with OSMesa (no window)");
        cmd->add_option("--size", size, "framebuffer size WxH in pixels (default: the scene's [window])");
        cmd->add_option("--frames", frames, "frames to run")->check(CLI::Range(1L, 100000000L));
        cmd->add_option("--seed", seed, "scene seed (same as --set sim.seed=N)")->check(SEED);
        cmd->add_option("--screenshot", screenshot, "write the last frame to this PNG")->check(NON_EMPTY_PATH);
        cmd->add_option("--stats", stats, "write a JSON summary (frames, per-phase ms, entities, state hash)")
            ->check(NON_EMPTY_PATH);
        cmd->add_option("--input", input, "scripted input: a TOML file of [[press]] and [[mouse]] entries (README)")
            ->check(NON_EMPTY_PATH);
        cmd->add_option("--steps-per-frame", stepsPerFrame,
                        "fixed clock: simulation steps each rendered frame advances (a slow machine's frame), 1-64")
            ->check(CLI::Range(1, 64));
    }

    SceneDef load() const {
        std::vector<std::string> overrides = sets;
        if (seed >= 0) overrides.push_back("sim.seed=" + std::to_string(seed));
        SceneDef def = loadScene(scene, overrides);
        for (const std::string& warning : costWarnings(def)) logWarn("%s: %s", printable(scene).c_str(), warning.c_str());
        return def;
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
            using platform::MAX_FRAMEBUFFER_PX, platform::MIN_FRAMEBUFFER_PX;
            if (!std::regex_match(size, m, WXH) || std::stoi(m[1]) < MIN_FRAMEBUFFER_PX || std::stoi(m[2]) < MIN_FRAMEBUFFER_PX ||
                std::stoi(m[1]) > MAX_FRAMEBUFFER_PX || std::stoi(m[2]) > MAX_FRAMEBUFFER_PX)
                throw InputError("--size " + quotedValue(size) + ": expected WxH with " + std::to_string(MIN_FRAMEBUFFER_PX) +
                                 " <= W, H <= " + std::to_string(MAX_FRAMEBUFFER_PX) + ", e.g. 1280x720");
            o.size = {std::stoi(m[1]), std::stoi(m[2])};
        }
        return o;
    }
};

} // namespace ob::game
