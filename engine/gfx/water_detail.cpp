// The detail map (CPU, gfx/detail_map.h) uploaded, the foam pattern baked from it
// (shaders/foam_pattern_bake.frag), both tiling.
#include "gfx/water_detail.h"

#include "gfx/detail_map.h"
#include "gfx/render_target.h"
#include "gfx/shader.h"

#include <vector>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
constexpr int DETAIL_MAP_SIZE = 256;
// The baked foam pattern's texels over its repeat (three foam tiles, 15 m): 2 cm a texel, 46 over
// the finest octave's period.
constexpr int FOAM_PATTERN_SIZE = 1024;
} // namespace

// The detail map is RGBA8, (du, dv) stored as 0.5 + 0.5·x: llvmpipe filters 8-bit texels on its
// fast path.
WaterDetail::WaterDetail() {
    std::vector<glm::vec4> detail = makeDetailMap(DETAIL_MAP_SIZE, 0x0CEA4u);
    for (glm::vec4& t : detail) t = glm::vec4(0.5f + 0.5f * t.x, 0.5f + 0.5f * t.y, t.z, t.w);
    m_detailMap = createTexture2D("water detail (du, dv, foam)", GL_RGBA8, glm::ivec2(DETAIL_MAP_SIZE), mipLevels(DETAIL_MAP_SIZE));
    m_foamPattern = createTexture2D("foam pattern (du, dv, bubbles)", GL_RGBA8, glm::ivec2(FOAM_PATTERN_SIZE), mipLevels(FOAM_PATTERN_SIZE));
    for (const Texture* map : {&m_detailMap, &m_foamPattern}) {
        glTextureParameteri(map->id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(map->id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
    glTextureSubImage2D(m_detailMap.id(), 0, 0, 0, DETAIL_MAP_SIZE, DETAIL_MAP_SIZE, GL_RGBA, GL_FLOAT, detail.data());
    glGenerateTextureMipmap(m_detailMap.id());

    GLuint id;
    glCreateFramebuffers(1, &id);
    const Framebuffer framebuffer(id);
    glNamedFramebufferTexture(id, GL_COLOR_ATTACHMENT0, m_foamPattern.id(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    glViewport(0, 0, FOAM_PATTERN_SIZE, FOAM_PATTERN_SIZE);
    glDisable(GL_DEPTH_TEST);
    m_bakeProgram = loadProgram("foam pattern bake", {"common_fullscreen.vert", "foam_pattern_bake.frag"});
    glUseProgram(m_bakeProgram.id());
    glBindTextureUnit(DETAIL_UNIT, m_detailMap.id());
    const VertexArray empty = createVertexArray("foam bake: fullscreen triangle");
    glBindVertexArray(empty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGenerateTextureMipmap(m_foamPattern.id());

    GLuint sampler;
    glCreateSamplers(1, &sampler);
    glObjectLabel(GL_SAMPLER, sampler, -1, "nearest mip, repeated");
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
    m_nearestMipSampler = Sampler(sampler);
}

void WaterDetail::listPrograms(ProgramList& out) const { out.emplace_back("foam pattern bake", m_bakeProgram.id()); }

} // namespace ob::gfx
