// attachGpu through the registration table: each model's moveToGpu lives in its own gpu/.
#include "interaction/gpu/attach_gpu.h"

#include "interaction/ripple_levels.h"
#include "interaction/ripple_patch.h"

namespace ob::interaction {

bool attachGpu(RipplePatch& patch) {
    return RippleModels::visit(size_t(patch.def().model), [&]<class Model>() {
        bool moved = Model::moveToGpu(patch.solver());
        if (RippleLevels* levels = patch.levels())  // each coarse level on its own twin (the same model)
            for (int L = 1; moved && L < levels->count(); ++L) moved = Model::moveToGpu(levels->solver(L));
        return moved;
    });
}

} // namespace ob::interaction
