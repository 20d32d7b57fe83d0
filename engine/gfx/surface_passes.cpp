// Reflection and refraction passes and their targets.
#include "gfx/surface_passes.h"

#include "gfx/object_pass.h"
#include "gfx/splash_pass.h"

#include <glm/glm.hpp>

namespace ob::gfx {

namespace {
glm::ivec2 scaled(glm::ivec2 size, float scale) { return glm::max(glm::ivec2(glm::vec2(size) * scale + 0.5f), glm::ivec2(1)); }

// Binds a target for drawing, cleared to transparent black and the far plane.
void clearTarget(const RenderTarget& target) {
    const float color[4] = {0, 0, 0, 0}, depth = 1.0f;
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, 0, color);
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_DEPTH, 0, &depth);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.size.x, target.size.y);
}
} // namespace

void SurfacePasses::resize(const FrameContext& frame, glm::ivec2 internal) {
    const glm::ivec2 target = scaled(internal, frame.def.rtt_scale);
    if (m_reflection.size != target) {
        m_reflection = createRenderTarget("reflection target", target);
        m_refraction = createRenderTarget("refraction target", target);
    }
    const bool msaa = frame.state.antialias == Antialias::Msaa4;
    if (!msaa) m_samples = {};
    if (msaa && m_samples.size != target) m_samples = createRenderTarget("reflection/refraction samples", target, MSAA_SAMPLES);
}

void SurfacePasses::reflectionPass(FrameContext& frame, ObjectPass& objects, SplashPass& splash, const std::vector<ObjectDraw>& draws) {
    const PassScope scope(frame, REFLECTION_PASS);
    const bool msaa = frame.state.antialias == Antialias::Msaa4;
    clearTarget(msaa ? m_samples : m_reflection);  // alpha 0: no local reflection, the sky cube shows
    glFrontFace(GL_CW);  // the mirror flips the winding
    objects.draw(frame, draws, REFLECTION_VIEW);
    glFrontFace(GL_CCW);
    splash.draw(frame, REFLECTION_VIEW);
    if (msaa) resolveTarget(m_samples, m_reflection, true);  // alpha becomes fractional coverage at edges
}

void SurfacePasses::refractionPass(FrameContext& frame, ObjectPass& objects, const std::vector<ObjectDraw>& draws) {
    const PassScope scope(frame, REFRACTION_PASS);
    const bool msaa = frame.state.antialias == Antialias::Msaa4;
    clearTarget(msaa ? m_samples : m_refraction);  // depth 1: open water, the full body colour
    objects.draw(frame, draws, REFRACTION_VIEW);
    if (msaa) resolveTarget(m_samples, m_refraction, true);
}

} // namespace ob::gfx
