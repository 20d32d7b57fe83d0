// `oceanbox dump foam`: run a scene headless for K steps, write its foam map's coverage.
// ripples.backend = "gpu" runs the ripple twin in an OSMesa context (the foam map follows the patch).
#include "tools/cmd_dump_foam.h"

#include "core/error.h"
#include "core/log.h"
#include "core/npy.h"
#include "foam/foam_map.h"
#include "foam/foam_streaks.h"
#include "gfx/gl.h"
#include "platform/platform.h"
#include "sim/splash_foam_system.h"
#include "world/sandbox.h"

#include <memory>

namespace ob::game {

int dumpFoam(const SceneDef& scene, int frames, const std::string& out) {
    if (!scene.foam.enabled || !scene.ripples.enabled)
        throw InputError("dump foam: the scene has " + std::string(scene.foam.enabled ? "ripples" : "foam") +
                         ".enabled = false, so there is no foam map to dump (the map follows the ripple patch; "
                         "set both to true, e.g. --set foam.enabled=true --set ripples.enabled=true)");
    if (frames < 0) throw InputError("dump foam: --frames " + std::to_string(frames) + " is negative (need >= 0)");

    // The GPU ripple twin needs a GL context for the sandbox's life (declared first, destroyed last).
    std::unique_ptr<platform::Platform> context;
    if (scene.ripples.backend == Backend::Gpu) context = platform::createHeadlessPlatform({16, 16});
    Sandbox sandbox(scene);
    if (context) sandbox.attachPlatform(*context, false);
    for (int k = 0; k < frames; ++k) sandbox.step();
    if (gfx::glErrorCount() > 0) throw RuntimeError("dump foam: " + std::to_string(gfx::glErrorCount()) + " GL error(s) in the run");
    const foam::FoamMap* foam = foamMap(sandbox.world());
    if (!foam) throw RuntimeError("dump foam: the sandbox built no foam map (it is made on the first step: --frames >= 1)");

    const int n = foam->grid().n;
    size_t over = 0;
    for (float f : foam->coverage()) over += f > 0.5f ? 1 : 0;
    writeNpy(out, {size_t(n), size_t(n)}, foam->coverage().data());
    logInfo("foam: wrote %s [%d, %d] after %d step(s) (cell %g m, origin (%g, %g) m): mean coverage %.4f, "
            "whitecap fraction (samples over 0.5) %.4f",
            out.c_str(), n, n, frames, double(foam->grid().cell), double(foam->grid().origin().x), double(foam->grid().origin().y),
            foam->mean(), double(over) / double(size_t(n) * size_t(n)));
    // How the foam lies (docs/splash_foam.md §2.2): its autocorrelation length along and across the wind.
    const glm::vec2 wind = glm::normalize(scene.ocean.wind_direction);
    const float maxLag = 0.5f * float(n) * foam->grid().cell;
    const float along = foam::autocorrelationLength(foam->coverage(), n, foam->grid().cell, wind, maxLag);
    const float across = foam::autocorrelationLength(foam->coverage(), n, foam->grid().cell, glm::vec2(-wind.y, wind.x), maxLag);
    logInfo("foam: autocorrelation falls to 1/e at %.2f m along the wind, %.2f m across it (ratio %.2f)", double(along),
            double(across), across > 0.0f ? double(along / across) : 0.0);
    return EXIT_OK;
}

} // namespace ob::game
