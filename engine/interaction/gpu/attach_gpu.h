// The ripple patch's solver onto its GPU twin, whichever model it is (needs a GL context).
#pragma once

namespace ob::interaction {

class RipplePatch;
struct RippleDef;

/// Moves the patch's step to its solver's GPU twin (the model's moveToGpu, kang2008:
/// RippleFieldGpu, ewave: EWaveGpu; needs a current GL 4.3+ context). Returns false, and leaves
/// the patch on the CPU, where the twin cannot run it (ewave: N above EWaveGpu::MAX_RESOLUTION).
bool attachGpu(RipplePatch& patch);

/// ripples.backend = "auto" beside a GPU: whether a patch of `def` (its model, N, cells and levels)
/// steps faster on its GPU twin than on the CPU, on this machine. Two still patches of `def` are
/// stepped alternately, each step followed by a query (what the next physics step waits for: the
/// GPU's read-back, the coarse levels' pipelined step); the GPU only when its median is under 0.9
/// of the CPU's, measured once per machine and kept (core/thread_choice.h, measuredChoice). False
/// where the twin cannot run it and with measuring off. Needs a current GL context.
bool gpuStepsFaster(const RippleDef& def);

} // namespace ob::interaction
