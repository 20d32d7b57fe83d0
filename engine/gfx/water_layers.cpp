// Ripple and foam textures, re-uploaded every frame, the ripple slopes made from them on the GPU; the flat FFT stand-ins.
#include "gfx/water_layers.h"

#include "gfx/render_target.h"
#include "gfx/shader.h"
#include "gfx/water_pass.h"

#include "ripple_levels_bindings.glsl"

#include <algorithm>
#include <tuple>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
// A map read with a zero border: no ripples, no foam outside it.
Texture borderedMap(const char* label, GLenum format, int cells) {
    Texture texture = createTexture2D(label, format, glm::ivec2(cells));
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float zero[4] = {0, 0, 0, 0};
    glTextureParameterfv(texture.id(), GL_TEXTURE_BORDER_COLOR, zero);
    return texture;
}
// A 2D array of `layers` layers of cells², linear, clamped (to a zero border: `bordered`).
Texture createLevelArray(const char* label, GLenum format, int cells, bool bordered, int layers = MAX_RIPPLE_LEVELS) {
    GLuint id;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, label);
    glTextureStorage3D(id, 1, format, cells, cells, layers);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    const GLint wrap = bordered ? GL_CLAMP_TO_BORDER : GL_CLAMP_TO_EDGE;
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, wrap);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, wrap);
    const float zero[4] = {0, 0, 0, 0};
    glTextureParameterfv(id, GL_TEXTURE_BORDER_COLOR, zero);
    return Texture(id);
}
} // namespace

WaterLayers::WaterLayers() {
    // No FFT layers: flat maps, J = 1 where each layout keeps it (displacement w, slopes z).
    const float flatDisplacement[4] = {0.0f, 0.0f, 0.0f, 1.0f}, flatSlopes[4] = {0.0f, 0.0f, 1.0f, 0.0f};
    for (auto [texture, label, texel] : {std::tuple{&m_flatDisplacement, "flat water displacement", flatDisplacement},
                                         std::tuple{&m_flatSlopes, "flat water slopes", flatSlopes}}) {
        GLuint id;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
        glObjectLabel(GL_TEXTURE, id, -1, label);
        glTextureStorage3D(id, 1, GL_RGBA32F, 1, 1, 1);
        glTextureSubImage3D(id, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, texel);
        *texture = Texture(id);
    }
}

void WaterLayers::upload(const WaterView& water, bool fft, bool foamOn, WaterUniforms& u) {
    if (water.ripples && water.rippleCells > 0) {
        if (m_rippleCells != water.rippleCells) {
            m_ripples = borderedMap("ripple heights", GL_R32F, water.rippleCells);
            m_rippleSlopes = createTexture2D("ripple slopes", GL_RG32F, glm::ivec2(water.rippleCells + 2));
            m_rippleCells = water.rippleCells;
        }
        glTextureSubImage2D(m_ripples.id(), 0, 0, 0, m_rippleCells, m_rippleCells, GL_RED, GL_FLOAT, water.ripples);
        makeRippleSlopes(water.rippleCellSize);
        u.rippleParams = glm::vec4(water.rippleOrigin, water.rippleCellSize, float(m_rippleCells));
        uploadLevels(water, u);
    }
    u.foamParams = glm::vec4(0.0f);
    if (foamOn && water.foam && water.foamCells > 0) {
        if (m_foamCells != water.foamCells) {
            m_foam = borderedMap("foam coverage", GL_R32F, water.foamCells);
            m_foamCells = water.foamCells;
        }
        glTextureSubImage2D(m_foam.id(), 0, 0, 0, m_foamCells, m_foamCells, GL_RED, GL_FLOAT, water.foam);
        u.foamParams = glm::vec4(water.foamOrigin, water.foamCellSize, float(m_foamCells));
    }
    const bool ripples = u.rippleParams.w > 0.0f;
    glBindTextureUnit(FOAM_UNIT, u.foamParams.w > 0.0f ? m_foam.id() : 0);
    glBindTextureUnit(DISPLACEMENT_UNIT, fft ? water.displacement->id() : m_flatDisplacement.id());
    glBindTextureUnit(SLOPES_UNIT, fft ? water.slopes->id() : m_flatSlopes.id());
    glBindTextureUnit(RIPPLES_UNIT, ripples ? m_ripples.id() : 0);
    glBindTextureUnit(RIPPLE_SLOPES_UNIT, ripples ? m_rippleSlopes.id() : 0);
    const bool levels = ripples && u.rippleFade.x > 0.0f;
    glBindTextureUnit(RIPPLE_LEVELS_UNIT, levels ? m_levels.id() : 0);
    glBindTextureUnit(RIPPLE_LEVEL_SLOPES_UNIT, levels ? m_levelSlopes.id() : 0);
}

// Level 0's slopes from the heights just uploaded (ripple_slopes.comp): central differences
// (dh/dx, dh/dz) = (h(i+1, j) − h(i−1, j), h(i, j+1) − h(i, j−1)) / 2Δ with heights outside the
// patch 0, on an (n + 2)² grid whose texel (i + 1, j + 1) is cell (i, j): the water shader's
// ripple slope in one lookup. On the GPU, not the main thread: the same floats (1/2Δ from here).
void WaterLayers::makeRippleSlopes(float cellSize) {
    if (!m_slopeProgram.id()) m_slopeProgram = loadProgram("ripple slopes", {"ripple_slopes.comp"});
    glUseProgram(m_slopeProgram.id());
    glBindTextureUnit(RIPPLE_SLOPES_HEIGHT_UNIT, m_ripples.id());
    glBindImageTexture(RIPPLE_SLOPES_IMAGE, m_rippleSlopes.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    glProgramUniform2f(m_slopeProgram.id(), RIPPLE_SLOPES_GRID_LOCATION, float(m_rippleCells), 1.0f / (2.0f * cellSize));
    const GLuint groups = GLuint((m_rippleCells + 2 + RIPPLE_LEVEL_TILE - 1) / RIPPLE_LEVEL_TILE);
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindTextureUnit(RIPPLE_SLOPES_HEIGHT_UNIT, 0);
    glUseProgram(0);
}

// The coarse ripple levels as layers of two arrays (heights with a zero border, slopes with a
// margin as level 0's), made on the GPU from their two states (uploaded when a level stepped or
// moved) and this frame's weights of the cubic in time (ripple_levels.comp); their placement in
// rippleLevels / rippleFade.
void WaterLayers::uploadLevels(const WaterView& water, WaterUniforms& u) {
    const int count = std::min(int(water.rippleLevels.size()), int(MAX_RIPPLE_LEVELS));
    u.rippleFade = glm::vec4(float(count), float(water.rippleFadeCells), 0.0f, 0.0f);
    if (count == 0) return;
    const int n = water.rippleCells;
    if (m_levelCells != n) {
        m_levels = createLevelArray("ripple level heights", GL_R32F, n, true);
        m_levelSlopes = createLevelArray("ripple level slopes", GL_RG32F, n + 2, false);
        m_levelStates = createLevelArray("ripple level states", GL_R32F, n, true, 4 * MAX_RIPPLE_LEVELS);
        m_levelVersions.fill(0);
        m_levelCells = n;
    }
    if (!m_levelProgram.id()) m_levelProgram = loadProgram("ripple levels in time", {"ripple_levels.comp"});
    glUseProgram(m_levelProgram.id());
    glBindTextureUnit(RIPPLE_LEVEL_STATES_UNIT, m_levelStates.id());
    glBindImageTexture(RIPPLE_LEVEL_HEIGHT_IMAGE, m_levels.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(RIPPLE_LEVEL_SLOPE_IMAGE, m_levelSlopes.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG32F);
    glProgramUniform2f(m_levelProgram.id(), RIPPLE_LEVEL_GRID_LOCATION, float(n), 0.0f);
    const GLuint groups = GLuint((n + 2 + RIPPLE_LEVEL_TILE - 1) / RIPPLE_LEVEL_TILE);
    for (int L = 0; L < count; ++L) {
        const WaterView::RippleLevel& level = water.rippleLevels[size_t(L)];
        if (m_levelVersions[size_t(L)] != level.version || level.version == 0) {
            for (int k = 0; k < 4; ++k)
                glTextureSubImage3D(m_levelStates.id(), 0, 0, 0, 4 * L + k, n, n, 1, GL_RED, GL_FLOAT, level.states[size_t(k)]);
            m_levelVersions[size_t(L)] = level.version;
        }
        glProgramUniform1i(m_levelProgram.id(), RIPPLE_LEVEL_LOCATION, L);
        glProgramUniform4fv(m_levelProgram.id(), RIPPLE_LEVEL_WEIGHTS_LOCATION, 1, &level.weights.x);
        glProgramUniform2f(m_levelProgram.id(), RIPPLE_LEVEL_GRID_LOCATION, float(n), level.cellSize);
        glDispatchCompute(groups, groups, 1);
        u.rippleLevels[L] = glm::vec4(level.origin, level.cellSize, 0.0f);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindTextureUnit(RIPPLE_LEVEL_STATES_UNIT, 0);
    glUseProgram(0);
}

} // namespace ob::gfx
