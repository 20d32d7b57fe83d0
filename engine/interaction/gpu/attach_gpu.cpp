// attachGpu through the registration table: each model's moveToGpu lives in its own gpu/.
#include "interaction/gpu/attach_gpu.h"

#include "interaction/ripple_levels.h"
#include "interaction/ripple_patch.h"

#include "core/thread_choice.h"

#include <string>

namespace ob::interaction {

bool attachGpu(RipplePatch& patch) {
    return RippleModels::visit(size_t(patch.def().model), [&]<class Model>() {
        bool moved = Model::moveToGpu(patch.solver());
        if (RippleLevels* levels = patch.levels())  // each coarse level on its own twin (the same model)
            for (int L = 1; moved && L < levels->count(); ++L) moved = Model::moveToGpu(levels->solver(L));
        return moved;
    });
}

bool gpuStepsFaster(const RippleDef& def) {
    RippleDef still = def;
    still.center = glm::vec2(0.0f);
    RipplePatch cpu(still), gpu(still);
    cpu.setPipelined(true);  // as the frame steps it ([sim] pipelined)
    if (!attachGpu(gpu)) return false;
    const std::string key = std::string("ripples ") + enumName(def.model) + " " + std::to_string(def.resolution) + "² × " +
                            std::to_string(def.levels) + " levels on the gpu";
    constexpr float STEP_S = 1.0f / 60.0f;  // the step's length does not change its cost
    return measuredChoice(key, false, [&](bool onGpu) {
        RipplePatch& patch = onGpu ? gpu : cpu;
        patch.step(STEP_S);
        static_cast<void>(patch.heightAt(glm::vec2(0.0f)));
    });
}

} // namespace ob::interaction
