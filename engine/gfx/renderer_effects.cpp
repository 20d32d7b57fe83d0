// The renderer's splash drops (sprites, main view and reflection) and the foam map's upload.
#include "gfx/renderer.h"

#include "gfx/shader.h"

#include <algorithm>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
// The smallest sprite radius (px): 1.5 px across. Smaller sprites are drawn at this size with
// their opacity cut by the area ratio, so drops far away fade rather than alias away.
constexpr float MIN_SPRITE_RADIUS_PX = 0.75f;
} // namespace

void Renderer::uploadSplashDrops(std::span<const SplashDrop> drops, const CameraView& camera) {
    m_splashCount = m_def.splash_drops ? GLsizei(drops.size()) : 0;
    if (m_splashCount == 0) return;
    if (!m_splashProgram.id()) {
        m_splashProgram = loadProgram("splash_drops", {"splash_drops.vert", "splash_drops.frag"});
        m_splashMirrorProgram = loadProgram("splash_drops_mirror", {"splash_drops_mirror.vert", "splash_drops.frag"});
        m_splashVao = createVertexArray("splash drops");
        glEnableVertexArrayAttrib(m_splashVao.id(), SPLASH_DROP_ATTRIB);
        glVertexArrayAttribFormat(m_splashVao.id(), SPLASH_DROP_ATTRIB, 4, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(m_splashVao.id(), SPLASH_DROP_ATTRIB, 0);
    }
    if (drops.size() > m_splashCapacity) {
        m_splashCapacity = std::max(drops.size(), 2 * m_splashCapacity);
        m_splashBuffer = createBuffer("splash drops", GLsizeiptr(m_splashCapacity * sizeof(SplashDrop)));
        glVertexArrayVertexBuffer(m_splashVao.id(), 0, m_splashBuffer.id(), 0, sizeof(SplashDrop));
    }
    glNamedBufferSubData(m_splashBuffer.id(), 0, GLsizeiptr(drops.size_bytes()), drops.data());
    // The sprites' sphere normals use the camera's axes in both views: the reflection mirrors
    // the drops, not the eye.
    const glm::vec3 right(camera.view[0][0], camera.view[1][0], camera.view[2][0]);
    const glm::vec3 up(camera.view[0][1], camera.view[1][1], camera.view[2][1]);
    const glm::vec3 sprite(m_def.splash_sprite_scale, camera.projection[1][1], MIN_SPRITE_RADIUS_PX);
    for (GLuint program : {m_splashProgram.id(), m_splashMirrorProgram.id()}) {
        glProgramUniform3fv(program, SPLASH_RIGHT_LOCATION, 1, &right.x);
        glProgramUniform3fv(program, SPLASH_UP_LOCATION, 1, &up.x);
        glProgramUniform3fv(program, SPLASH_SPRITE_LOCATION, 1, &sprite.x);
    }
}

// Premultiplied alpha over the target, unsorted: the sprites share one colour up to their
// lighting, so their order barely shows. Depth-tested against what was drawn, never written.
// The frame's alpha (FXAA's luma, or the reflection's coverage) is kept for the main view and
// accumulated as coverage for the reflection.
void Renderer::drawSplashDrops(View view) {
    if (m_splashCount == 0) return;
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_BLOCK, m_frameUniforms[view].id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    if (view == MAIN_VIEW) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glUseProgram(view == REFLECTION_VIEW ? m_splashMirrorProgram.id() : m_splashProgram.id());
    glBindVertexArray(m_splashVao.id());
    glEnable(GL_PROGRAM_POINT_SIZE);
    glDrawArrays(GL_POINTS, 0, m_splashCount);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_BLOCK, m_frameUniforms[MAIN_VIEW].id());
}

void Renderer::splashPass() {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, SPLASH_PASS, -1, "splash");
    m_passTimers[SPLASH_PASS].begin();
    drawSplashDrops(MAIN_VIEW);
    m_passTimers[SPLASH_PASS].end();
    glPopDebugGroup();
}

void Renderer::uploadFoam(const WaterView& water, WaterUniforms& u) {
    u.foamParams = glm::vec4(0.0f);
    if (!m_def.foam || !water.foam || water.foamCells <= 0) return;
    if (m_foamCells != water.foamCells) {
        m_foamTexture = createTexture2D("foam coverage", GL_R32F, glm::ivec2(water.foamCells));
        glTextureParameteri(m_foamTexture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glTextureParameteri(m_foamTexture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        const float zero[4] = {0, 0, 0, 0};
        glTextureParameterfv(m_foamTexture.id(), GL_TEXTURE_BORDER_COLOR, zero);  // no foam outside the map
        m_foamCells = water.foamCells;
    }
    glTextureSubImage2D(m_foamTexture.id(), 0, 0, 0, m_foamCells, m_foamCells, GL_RED, GL_FLOAT, water.foam);
    u.foamParams = glm::vec4(water.foamOrigin, water.foamCellSize, float(m_foamCells));
}

} // namespace ob::gfx
