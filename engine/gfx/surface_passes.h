// The passes that see in and through the water surface: the reflection (objects above it,
// mirrored about it per vertex, and the mirrored splash drops) and the refraction (objects
// below it). They own their targets, which the water pass samples.
#pragma once
#include "gfx/render_frame.h"
#include "gfx/render_target.h"

#include <vector>

namespace ob::gfx {

class ObjectPass;
class SplashPass;

class SurfacePasses {
public:
    /// Sizes the targets to `internal` × [render] rtt_scale; the shared multisampled target
    /// exists only in msaa4.
    void resize(const FrameContext& frame, glm::ivec2 internal);
    /// in: mirrored view, objects, drops; out: reflection colour (alpha: coverage) + depth.
    void reflectionPass(FrameContext& frame, ObjectPass& objects, SplashPass& splash, const std::vector<ObjectDraw>& draws);
    /// in: camera view, objects; out: refraction colour, 1 / eye depth in alpha.
    void refractionPass(FrameContext& frame, ObjectPass& objects, const std::vector<ObjectDraw>& draws);
    const RenderTarget& reflection() const { return m_reflection; }
    const RenderTarget& refraction() const { return m_refraction; }

private:
    RenderTarget m_reflection, m_refraction;
    RenderTarget m_samples;  // msaa4: the reflection's, then the refraction's samples, resolved into each
};

} // namespace ob::gfx
