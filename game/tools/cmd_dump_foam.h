// `oceanbox dump foam`: the scene's persistent foam map after K simulation steps, as .npy (docs/splash_foam.md §2, §7).
#pragma once
#include "world/scene.h"

#include <string>

namespace ob::game {

/// Builds the scene's Sandbox, runs `frames` fixed steps and writes the foam map's coverage
/// f ∈ [0, 1] to `out` as float32 .npy of shape [N, N], N = foam.resolution: element [j, i] is
/// the coverage of sample column i (x), row j (z), i.e. world (origin.x + i·Δ, origin.z + j·Δ).
/// Logs the mean coverage and the whitecap fraction (the share of samples over 0.5).
/// Returns ob::EXIT_OK; throws ob::InputError if the scene has no foam map (foam or ripples
/// off) or frames < 0, ob::RuntimeError if the file cannot be written.
int dumpFoam(const SceneDef& scene, int frames, const std::string& out);

} // namespace ob::game
