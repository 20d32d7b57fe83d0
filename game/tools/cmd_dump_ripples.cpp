// `oceanbox dump ripples`: run a scene headless for K steps, write the ripple patch's height
// (kang2008: Vh(t); ewave: h). ripples.backend = "gpu" runs the GPU twin in an OSMesa context.
#include "tools/cmd_dump_ripples.h"

#include "core/error.h"
#include "core/log.h"
#include "core/npy.h"
#include "gfx/gl.h"
#include "interaction/ripple_patch.h"
#include "platform/platform.h"
#include "world/sandbox.h"

#include <memory>

namespace ob::game {

int dumpRipples(const SceneDef& scene, int frames, const std::string& out) {
    if (!scene.ripples.enabled)
        throw InputError("dump ripples: the scene has ripples.enabled = false, so there is no ripple patch to dump "
                         "(set it to true, e.g. --set ripples.enabled=true)");
    if (frames < 0) throw InputError("dump ripples: --frames " + std::to_string(frames) + " is negative (need >= 0)");

    // The GPU twin needs a GL context for the sandbox's life (declared first, destroyed last).
    std::unique_ptr<platform::Platform> context;
    if (scene.ripples.backend == Backend::Gpu) context = platform::createHeadlessPlatform({16, 16});
    Sandbox sandbox(scene);
    if (context) sandbox.attachPlatform(*context, false);
    for (int k = 0; k < frames; ++k) sandbox.step();
    if (gfx::glErrorCount() > 0) throw RuntimeError("dump ripples: " + std::to_string(gfx::glErrorCount()) + " GL error(s) in the run");
    const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
    if (!patch) throw RuntimeError("dump ripples: the sandbox built no ripple patch");  // enabled scenes always do

    // Either model's height level is row-major with row = z, column = x: already the [N, N] layout.
    writeNpy(out, {size_t(patch->rows()), size_t(patch->cols())}, patch->height().data());
    logInfo("ripples: wrote %s [%d, %d] (%s, %s) after %d step(s) (cell %g m, origin (%g, %g) m)", out.c_str(), patch->rows(),
            patch->cols(), enumName(patch->def().model), patch->onGpu() ? "gpu" : "cpu", frames, double(patch->def().cell_size), double(patch->origin().x),
            double(patch->origin().y));
    return EXIT_OK;
}

} // namespace ob::game
