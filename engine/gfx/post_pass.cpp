// MSAA resolve, FXAA and the upscale to the framebuffer.
#include "gfx/post_pass.h"

#include "gfx/shader.h"

#include <algorithm>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

PostPass::PostPass()
    : m_upscaleProgram(loadProgram("upscale", {"common_fullscreen.vert", "post_upscale.frag"})),
      m_fxaaPrograms{loadProgram("fxaa off the edges", {"common_fullscreen.vert", "post_fxaa.frag"}, "#define FXAA_OFF_EDGES\n"),
                     loadProgram("fxaa on the edges", {"common_fullscreen.vert", "post_fxaa.frag"})},
      m_emptyVao(createVertexArray("post: fullscreen triangle")) {
    GLint colorSamples = 0, depthSamples = 0;
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colorSamples);
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depthSamples);
    m_msaaSupported = std::min(colorSamples, depthSamples) >= MSAA_SAMPLES;
    GLint depthBits = 0;
    glGetNamedFramebufferAttachmentParameteriv(0, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    m_framebufferDepth = depthBits > 0;
}

void PostPass::listPrograms(ProgramList& out) const {
    out.emplace_back("upscale", m_upscaleProgram.id());
    out.emplace_back("fxaa off the edges", m_fxaaPrograms[0].id());
    out.emplace_back("fxaa on the edges", m_fxaaPrograms[1].id());
}

void PostPass::resize(const FrameContext& frame, glm::ivec2 internal) {
    const RenderDef& def = frame.def;
    const Antialias mode = frame.state.antialias;
    const bool msaa = mode == Antialias::Msaa4;
    if (!msaa) m_multisampled = {};
    if (msaa && m_multisampled.size != internal)
        m_multisampled = createRenderTarget("internal frame samples", internal, MSAA_SAMPLES, GL_RGBA8);
    const bool offscreen = def.resolution_scale < 1.0f || mode != Antialias::Off;
    if (!offscreen) m_internal = {};
    if (offscreen && m_internal.size != internal) m_internal = createRenderTarget("internal frame", internal, 1, GL_RGBA8);
    const bool antialiased = mode == Antialias::Fxaa && (def.resolution_scale < 1.0f || !m_framebufferDepth);
    if (!antialiased) m_antialiased = {};
    if (antialiased && m_antialiased.size != internal) m_antialiased = createRenderTarget("anti-aliased frame", internal, 1, GL_RGBA8);
}

bool PostPass::direct(const FrameContext& frame) const {
    return frame.def.resolution_scale >= 1.0f && frame.state.antialias == Antialias::Off;
}

GLuint PostPass::frameFramebuffer(const FrameContext& frame) const {
    if (direct(frame)) return 0;
    return (frame.state.antialias == Antialias::Msaa4 ? m_multisampled : m_internal).framebuffer.id();
}

// Off the edges first, marked at depth 0; then the edges' walk only where depth is left at 1
// (post_fxaa.frag): the rasteriser skips the blocks with no edge pixel. Each pixel is written
// once, into the framebuffer itself at full size when it has a depth buffer.
void PostPass::fxaa(FrameContext& frame, bool upscaled, bool intoFramebuffer) {
    const glm::ivec2 internal = m_internal.size;
    const GLuint target = intoFramebuffer ? 0 : m_antialiased.framebuffer.id();
    const float far = 1.0f;
    glClearNamedFramebufferfv(target, GL_DEPTH, 0, &far);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, internal.x, internal.y);
    glEnable(GL_DEPTH_TEST);
    glBindTextureUnit(POST_SOURCE_UNIT, m_internal.color.id());
    glBindVertexArray(m_emptyVao.id());
    for (const Program& program : m_fxaaPrograms) {
        const bool offEdges = &program == &m_fxaaPrograms[0];
        glDepthFunc(offEdges ? GL_ALWAYS : GL_LEQUAL);
        glDepthMask(offEdges ? GL_TRUE : GL_FALSE);
        glProgramUniform2f(program.id(), FXAA_TEXEL_LOCATION, 1.0f / float(internal.x), 1.0f / float(internal.y));
        glProgramUniform1f(program.id(), FXAA_SHARPNESS_LOCATION, upscaled ? frame.def.upscale_sharpness : 0.0f);
        glUseProgram(program.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glBindTextureUnit(POST_SOURCE_UNIT, 0);  // drawn into again next frame
}

// The samples resolved (msaa4) or FXAA (sharpened off the edges when it is to be scaled up),
// at the internal size; then a blit, bilinear when it scales up. FXAA before the scaling costs
// its lookups per internal pixel only.
void PostPass::postPass(FrameContext& frame, glm::ivec2 size) {
    const PassScope scope(frame, POST_PASS);
    if (frame.state.antialias == Antialias::Msaa4) resolveTarget(m_multisampled, m_internal, false);
    const glm::ivec2 internal = m_internal.size;
    const RenderTarget* last = &m_internal;
    if (frame.state.antialias == Antialias::Fxaa) {
        const bool upscaled = internal != size;
        const bool intoFramebuffer = !upscaled && m_framebufferDepth;
        fxaa(frame, upscaled, intoFramebuffer);
        last = intoFramebuffer ? nullptr : &m_antialiased;
    }
    if (last && internal == size) {
        glBlitNamedFramebuffer(last->framebuffer.id(), 0, 0, 0, internal.x, internal.y, 0, 0, size.x, size.y,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
    } else if (last) {  // scaled up: one bilinear lookup a pixel (a draw; llvmpipe's blit costs more)
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_DEPTH_TEST);
        glBindTextureUnit(POST_SOURCE_UNIT, last->color.id());
        glUseProgram(m_upscaleProgram.id());
        glBindVertexArray(m_emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindTextureUnit(POST_SOURCE_UNIT, 0);
    }
}

} // namespace ob::gfx
