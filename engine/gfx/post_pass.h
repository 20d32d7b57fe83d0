// The internal frame to the framebuffer: MSAA resolve, FXAA, upscale (resolution_scale < 1).
// It owns the internal frame's targets and probes once what the driver and framebuffer offer.
#pragma once
#include "gfx/render_frame.h"
#include "gfx/render_target.h"

namespace ob::gfx {

class PostPass {
public:
    PostPass();
    /// Whether the driver multisamples float colour and depth textures 4× (else msaa4 falls back to FXAA).
    bool msaaSupported() const { return m_msaaSupported; }
    /// Targets come and go with the settings: the multisampled one exists only in msaa4, the
    /// internal frame only when the frame is not drawn into the framebuffer directly.
    void resize(const FrameContext& frame, glm::ivec2 internal);
    /// The frame goes straight into the framebuffer only when nothing follows it.
    bool direct(const FrameContext& frame) const;
    /// The framebuffer the frame's passes draw into (0: the default framebuffer).
    GLuint frameFramebuffer(const FrameContext& frame) const;
    /// in: the multisampled or internal frame; out: the default framebuffer of `size`.
    void postPass(FrameContext& frame, glm::ivec2 size);
    void listPrograms(ProgramList& out) const;

private:
    void fxaa(FrameContext& frame, bool upscaled, bool intoFramebuffer);

    Program m_upscaleProgram;
    Program m_fxaaPrograms[2];  // post_fxaa.frag off the edges, then on them
    VertexArray m_emptyVao;
    RenderTarget m_internal;      // the frame (RGBA8, display-encoded) when it is not drawn into the framebuffer directly
    RenderTarget m_multisampled;  // msaa4: the frame's 4 samples a pixel, resolved into m_internal
    RenderTarget m_antialiased;   // fxaa below scale 1 (or a framebuffer without depth): the frame anti-aliased, then scaled up (or copied)
    bool m_msaaSupported = false;     // the driver multisamples float colour and depth textures 4×
    bool m_framebufferDepth = false;  // the default framebuffer has a depth buffer (FXAA draws into it at full size)
};

} // namespace ob::gfx
