// Running a scene: `play` (interactive, real time) and `run` (scripted, fixed time per frame).
#pragma once
#include "core/file_write.h"  // checkWritable, writeTextFile: what the commands write
#include "world/scene.h"

#include <glm/vec2.hpp>
#include <string>

namespace ob::game {

/// How to run a scene.
struct RunOptions {
    bool window = true;          ///< open a window (falls back to headless without a display)
    bool realTime = false;       ///< wall clock (play) instead of exactly one step per frame
    long frames = -1;            ///< frames to run; -1: until endTime, else until the window closes
    double endTime = 0.0;        ///< with frames = -1: stop once the simulation reaches this time (s); 0: none
    glm::ivec2 size{0, 0};       ///< framebuffer size (px); 0: the scene's [window] size
    std::string screenshot;      ///< PNG of the last frame ("" = none)
    std::string stats;           ///< JSON summary ("" = none)
    std::string fallbackNote;    ///< what to say when falling back to headless
    std::string input;           ///< scripted input file (TOML, game/world/input_script.h; "" = none)
    std::string record;          ///< write the steps' input here at the end, in the input format ("" = none)
    int stepsPerFrame = 1;       ///< fixed clock only: simulation steps each rendered frame advances
    uint64_t steps = 0;          ///< fixed clock: the run ends after exactly this many steps (a recording's; 0: frames decide)
    bool dynamicResolution = false;  ///< the internal scale holds [render] target_fps
    bool autoExposure = false;       ///< render.auto_exposure = "auto" means on (play in a window)
    bool overlay = false;        ///< the player's overlay and start card (play; headless too, so its pictures show them);
                                 ///< the goal clock then waits for the first input
};

/// Runs the scene; returns the process exit code. Throws ob::InputError / ob::RuntimeError.
int runScene(const SceneDef& scene, const std::string& scenePath, const RunOptions& options);


} // namespace ob::game
