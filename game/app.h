// Running a scene: `play` (interactive, real time) and `run` (scripted, fixed time per frame).
#pragma once
#include "scene.h"

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
    std::string input;           ///< scripted input file (TOML, game/input_script.h; "" = none)
    int stepsPerFrame = 1;       ///< fixed clock only: simulation steps each rendered frame advances
    bool dynamicResolution = false;  ///< the internal scale holds [render] target_fps
};

/// Runs the scene; returns the process exit code. Throws ob::InputError / ob::RuntimeError.
int runScene(const SceneDef& scene, const std::string& scenePath, const RunOptions& options);

/// Throws ob::InputError unless `path` can be created (its folder exists and is writable).
void checkWritable(const std::string& path, const char* what);

/// Writes `text` to `path` whole or not at all: into path + ".tmp", then renamed over
/// `path`. Throws ob::InputError naming `what` and the path when it cannot (the temporary
/// file removed).
void writeTextFile(const std::string& path, const std::string& text, const char* what);

} // namespace ob::game
