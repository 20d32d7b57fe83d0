// The ripple patch's GPU twins as its offload (RipplePatch::setOffload): the patch stays a
// CPU object; this is the one place that puts a GPU solver under it.
#pragma once

namespace ob::interaction {

class RipplePatch;

/// Moves the patch's step to its GPU twin (needs a current GL 4.3+ context): kang2008
/// RippleFieldGpu, ewave EWaveGpu. Returns false, and leaves the patch on the CPU, where the
/// twin cannot run it (ewave: N above EWaveGpu::MAX_RESOLUTION).
bool attachGpu(RipplePatch& patch);

} // namespace ob::interaction
