// The sky: the analytic daylight sky baked into a cube map when the sun moves, and drawn
// (or the underwater fog) where nothing else covered the frame.
#pragma once
#include "gfx/render_frame.h"

namespace ob::gfx {

class SkyPass {
public:
    SkyPass();
    /// in: sun direction, clouds; out: the cube (linear radiance, mipmapped), re-baked only when
    /// the sun moved or the clouds changed or drifted.
    void bakePass(FrameContext& frame);
    /// in: sky cube, depth; out: colour where nothing was drawn.
    void skyPass(FrameContext& frame);
    /// The sky's radiance (RGBA16F cube map, mipmapped): the water reflects it.
    const Texture& cube() const { return m_cube; }
    /// Mip levels of the cube (the water's rough reflections pick among them).
    static int mipCount();
    void listPrograms(ProgramList& out) const;

private:
    Program m_bakeProgram, m_program;
    Texture m_cube;
    Framebuffer m_bakeFramebuffer;
    VertexArray m_emptyVao;
    glm::vec3 m_bakedSun{0.0f};
    glm::vec4 m_bakedClouds{0.0f};  // cover, drift (m), layer height of the baked cube
};

} // namespace ob::gfx
