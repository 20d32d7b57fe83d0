// The splash drops' upload and sprites (main view and reflection).
#include "gfx/splash_pass.h"

#include "gfx/shader.h"

#include <algorithm>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
// The smallest sprite radius (px): 1.5 px across. Smaller sprites are drawn at this size with
// their opacity cut by the area ratio, so drops far away fade rather than alias away.
constexpr float MIN_SPRITE_RADIUS_PX = 0.75f;
} // namespace

void SplashPass::listPrograms(ProgramList& out) const {
    if (!m_program.id()) return;
    out.emplace_back("splash_drops", m_program.id());
    out.emplace_back("splash_drops_mirror", m_mirrorProgram.id());
}

void SplashPass::upload(const FrameContext& frame, std::span<const SplashDrop> drops, const CameraView& camera) {
    m_count = frame.def.splash_drops ? GLsizei(drops.size()) : 0;
    if (m_count == 0) return;
    if (!m_program.id()) {
        m_program = loadProgram("splash_drops", {"splash_drops.vert", "splash_drops.frag"});
        m_mirrorProgram = loadProgram("splash_drops_mirror", {"splash_drops_mirror.vert", "splash_drops.frag"});
        m_vao = createVertexArray("splash drops");
        glEnableVertexArrayAttrib(m_vao.id(), SPLASH_DROP_ATTRIB);
        glVertexArrayAttribFormat(m_vao.id(), SPLASH_DROP_ATTRIB, 4, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(m_vao.id(), SPLASH_DROP_ATTRIB, 0);
    }
    if (drops.size() > m_capacity) {
        m_capacity = std::max(drops.size(), 2 * m_capacity);
        m_buffer = createBuffer("splash drops", GLsizeiptr(m_capacity * sizeof(SplashDrop)));
        glVertexArrayVertexBuffer(m_vao.id(), 0, m_buffer.id(), 0, sizeof(SplashDrop));
    }
    glNamedBufferSubData(m_buffer.id(), 0, GLsizeiptr(drops.size_bytes()), drops.data());
    // The sprites' sphere normals use the camera's axes in both views: the reflection mirrors
    // the drops, not the eye.
    const glm::vec3 right(camera.view[0][0], camera.view[1][0], camera.view[2][0]);
    const glm::vec3 up(camera.view[0][1], camera.view[1][1], camera.view[2][1]);
    const glm::vec3 sprite(frame.def.splash_sprite_scale, camera.projection[1][1], MIN_SPRITE_RADIUS_PX);
    for (GLuint program : {m_program.id(), m_mirrorProgram.id()}) {
        glProgramUniform3fv(program, SPLASH_RIGHT_LOCATION, 1, &right.x);
        glProgramUniform3fv(program, SPLASH_UP_LOCATION, 1, &up.x);
        glProgramUniform3fv(program, SPLASH_SPRITE_LOCATION, 1, &sprite.x);
    }
}

// Premultiplied alpha over the target, unsorted: the sprites share one colour up to their
// lighting, so their order barely shows. Depth-tested against what was drawn, never written.
// The frame's alpha (FXAA's luma, or the reflection's coverage) is kept for the main view and
// accumulated as coverage for the reflection.
void SplashPass::draw(FrameContext& frame, View view) {
    if (m_count == 0) return;
    frame.views.bind(view);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    if (view == MAIN_VIEW) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glUseProgram(view == REFLECTION_VIEW ? m_mirrorProgram.id() : m_program.id());
    glBindVertexArray(m_vao.id());
    glEnable(GL_PROGRAM_POINT_SIZE);
    glDrawArrays(GL_POINTS, 0, m_count);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    frame.views.bind(MAIN_VIEW);
}

void SplashPass::splashPass(FrameContext& frame) {
    const PassScope scope(frame, SPLASH_PASS);
    draw(frame, MAIN_VIEW);
}

} // namespace ob::gfx
