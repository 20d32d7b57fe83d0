// attachGpu through the registration table: each model's moveToGpu lives in its own gpu/.
#include "interaction/gpu/attach_gpu.h"

#include "interaction/ripple_patch.h"

namespace ob::interaction {

bool attachGpu(RipplePatch& patch) {
    return RippleModels::visit(size_t(patch.def().model), [&]<class Model>() { return Model::moveToGpu(patch.solver()); });
}

} // namespace ob::interaction
