// `oceanbox dump ocean`: the first cascade of the CPU FFT ocean at one time, as .npy (docs/references.md#contracts).
#pragma once
#include "ocean/ocean_def.h"

#include <string>

namespace ob::game {

/// Writes cascade 0 of def at time `time` (seconds) to outPath as float32 .npy of shape
/// [N, N, 5]: element [j, i, :] = (h, Dx, Dz, ∂h/∂x, ∂h/∂z) at X = (i·L/N, j·L/N), metres and
/// slopes, D not multiplied by λ. backend "gpu": compute shaders on a headless GL context,
/// read back; "cpu" and "auto": FFTW (auto means the CPU where no GPU is known).
/// Returns ob::EXIT_OK; throws ob::InputError for a bad def, ob::RuntimeError if the file
/// cannot be written.
int dumpOcean(const ob::ocean::OceanDef& def, double time, const std::string& outPath);

} // namespace ob::game
