// `oceanbox dump ripples`: the scene's ripple patch after K simulation steps, as .npy (docs/references.md#contracts, docs/references.md#ripple-layer).
#pragma once
#include "world/scene.h"

#include <string>

namespace ob::game {

/// Builds the scene's Sandbox without a platform (pure simulation, no GL), runs `frames`
/// fixed steps (Sandbox::step: interaction then ocean phases) and writes the ripple patch's
/// Vh(t) to `out` as float32 .npy of shape [N, N], N = ripples.resolution: element [j, i] is
/// the height (m) of cell column i (x), row j (z), i.e. world (origin.x + i·Δ, origin.z + j·Δ).
/// Returns ob::EXIT_OK; throws ob::InputError if the scene has ripples.enabled = false or
/// frames < 0, ob::RuntimeError if the file cannot be written.
int dumpRipples(const SceneDef& scene, int frames, const std::string& out);

} // namespace ob::game
