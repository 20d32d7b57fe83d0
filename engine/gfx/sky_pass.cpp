// Sky bake (six faces of a cube map) and the sky behind everything.
#include "gfx/sky_pass.h"

#include "gfx/shader.h"
#include "gfx/sun.h"

#include <glm/mat3x3.hpp>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
constexpr int SKY_CUBE_SIZE = 128;

// Faces in GL's cube map order (+x, −x, +y, −y, +z, −z), each as the world direction of face
// coordinates (s, t) = (ndc.x, ndc.y): columns s axis, t axis, face normal.
const glm::mat3 CUBE_FACES[6] = {
    glm::mat3(glm::vec3(0, 0, -1), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0)),
    glm::mat3(glm::vec3(0, 0, 1), glm::vec3(0, -1, 0), glm::vec3(-1, 0, 0)),
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0)),
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, -1, 0)),
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1)),
    glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, -1)),
};
} // namespace

int SkyPass::mipCount() { return mipLevels(SKY_CUBE_SIZE); }

SkyPass::SkyPass()
    : m_bakeProgram(loadProgram("sky bake", {"common_fullscreen.vert", "sky_cube.frag"})),
      m_program(loadProgram("sky", {"common_fullscreen.vert", "sky_background.frag"})),
      m_emptyVao(createVertexArray("sky: fullscreen triangle")) {
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // filter across cube faces: no seams in the sky
    GLuint id;
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, "sky cube");
    glTextureStorage2D(id, mipCount(), GL_RGBA16F, SKY_CUBE_SIZE, SKY_CUBE_SIZE);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    m_cube = Texture(id);
    glCreateFramebuffers(1, &id);
    glObjectLabel(GL_FRAMEBUFFER, id, -1, "sky bake");
    m_bakeFramebuffer = Framebuffer(id);
}

void SkyPass::listPrograms(ProgramList& out) const {
    out.emplace_back("sky bake", m_bakeProgram.id());
    out.emplace_back("sky", m_program.id());
}

void SkyPass::bakePass(FrameContext& frame) {
    const glm::vec4 clouds(frame.sky.cloud_cover, frame.state.cloudDrift, frame.sky.cloud_height);
    if (sunDirection(frame.def) == m_bakedSun && (clouds == m_bakedClouds || (clouds.x == 0.0f && m_bakedClouds.x == 0.0f))) return;
    const PassScope scope(frame, SKY_BAKE_PASS);
    m_bakedSun = sunDirection(frame.def);
    m_bakedClouds = clouds;
    frame.views.bind(MAIN_VIEW);
    glBindFramebuffer(GL_FRAMEBUFFER, m_bakeFramebuffer.id());
    glViewport(0, 0, SKY_CUBE_SIZE, SKY_CUBE_SIZE);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(m_bakeProgram.id());
    glBindVertexArray(m_emptyVao.id());
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTextureLayer(m_bakeFramebuffer.id(), GL_COLOR_ATTACHMENT0, m_cube.id(), 0, face);
        glProgramUniformMatrix3fv(m_bakeProgram.id(), SKY_FACE_LOCATION, 1, GL_FALSE, &CUBE_FACES[face][0][0]);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glGenerateTextureMipmap(m_cube.id());
}

void SkyPass::skyPass(FrameContext& frame) {
    const PassScope scope(frame, SKY_PASS);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // the triangle sits on the far plane: only uncovered pixels pass
    glDepthMask(GL_FALSE);
    glBindTextureUnit(SKY_UNIT, m_cube.id());
    glBindVertexArray(m_emptyVao.id());
    glUseProgram(m_program.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
}

} // namespace ob::gfx
