// A scene's budget, estimated at load (docs/reliability.md#hostile-input): its grids' memory
// (a scene that cannot fit in what this machine gives the process is refused before any grid
// is allocated, in every subcommand alike) and the cost of legal-but-huge maxima (a warning).
#pragma once
#include "world/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ob::game {

/// One grid's (or population's) share: the keys that size it and its bytes, at least.
struct MemoryNeed {
    std::string what;  ///< "ocean.resolution 2048² × ocean.cascades 4"
    double bytes = 0;  ///< a lower bound: the arrays the simulation steps hold (not the GL copies)
};

/// The scene's grids and populations that take memory in proportion to their keys, largest
/// first (per-cell sizes measured: scene_memory.cpp).
std::vector<MemoryNeed> sceneMemory(const SceneDef& scene);

/// The bytes this process may hold: the least of physical memory, `ulimit -v` (RLIMIT_AS) and
/// `ulimit -d` (RLIMIT_DATA).
double processMemoryLimit();

/// "" when the scene's grids fit in `limitBytes`, else one message naming every grid with its
/// bytes, the total and the limit (the caller prefixes the scene's file).
std::string checkSceneMemory(const SceneDef& scene, double limitBytes);

/// The time one live splash drop costs a simulation step, s: 150 ns measured (a 2-core EPYC,
/// `run` of 30 frames at 10⁵ spray drops a step: the interaction phase over the live drops).
constexpr double SPLASH_DROP_STEP_SECONDS = 150e-9;

/// Warnings for legal settings that cannot run in real time: [splash] max_particles whose
/// drops at the maximum take longer to step than a step lasts (1 / sim.step_hz). One line
/// each, naming the keys and the cost; none for the shipped scenes.
std::vector<std::string> costWarnings(const SceneDef& scene);

/// A frame slower than this (ms) is reported once, with the phase that took most of it.
constexpr double SLOW_FRAME_MS = 10000.0;

/// "" unless the timer's latest closed frame took more than `thresholdMs`; else one line
/// naming its time and the phase that took most of it (the frame timer closes a frame when
/// the next begins or the run finishes).
std::string slowFrameNote(const ecs::FrameTimer& timer, double thresholdMs);

/// Bytes as a message shows them: "512 MiB", "6.4 GiB".
std::string byteText(double bytes);

} // namespace ob::game
