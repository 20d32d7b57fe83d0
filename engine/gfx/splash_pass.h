// Splash drops as lit, soft sprites: over the frame (depth-tested, blended) and, mirrored, in
// the reflection.
#pragma once
#include "gfx/render_frame.h"

#include <span>

namespace ob::gfx {

class SplashPass {
public:
    /// out: the drops' buffer and sprite uniforms; nothing when [render] splash_drops is off.
    void upload(const FrameContext& frame, std::span<const SplashDrop> drops, const CameraView& camera);
    /// The uploaded drops as sprites into the bound target (MAIN_VIEW or REFLECTION_VIEW).
    void draw(FrameContext& frame, View view);
    /// in: camera view, uploaded drops, depth; out: framebuffer colour (blended).
    void splashPass(FrameContext& frame);
    void listPrograms(ProgramList& out) const;

private:
    Program m_program, m_mirrorProgram;  // built on the first frame with drops
    VertexArray m_vao;
    Buffer m_buffer;        // this frame's drops, (centre, radius) per instance
    size_t m_capacity = 0;  // drops the buffer holds
    GLsizei m_count = 0;    // drops uploaded this frame
};

} // namespace ob::gfx
