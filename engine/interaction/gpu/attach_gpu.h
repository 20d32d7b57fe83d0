// The ripple patch's solver onto its GPU twin, whichever model it is (needs a GL context).
#pragma once

namespace ob::interaction {

class RipplePatch;

/// Moves the patch's step to its solver's GPU twin (the model's moveToGpu, kang2008:
/// RippleFieldGpu, ewave: EWaveGpu; needs a current GL 4.3+ context). Returns false, and leaves
/// the patch on the CPU, where the twin cannot run it (ewave: N above EWaveGpu::MAX_RESOLUTION).
bool attachGpu(RipplePatch& patch);

} // namespace ob::interaction
