// Renderer passes and the screenshot read-back.
#include "gfx/renderer.h"

#include "core/error.h"
#include "gfx/shader.h"
#include "ocean/projected_grid.h"

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <glm/glm.hpp>
#include <stb_image_write.h>
#include <vector>

namespace ob::gfx {

constexpr GLuint FRAME_UBO_BINDING = 0;
constexpr GLuint WATER_UBO_BINDING = 1;
// The grid reaches this far past the screen edges (NDC), so displaced waves leave no gap.
constexpr float GRID_MARGIN = 0.15f;
// Smallest |w| of a projected grid vertex (corners scaled to max w = 1): the horizon bound.
constexpr float GRID_MIN_W = 2e-5f;

Renderer::Renderer(const RenderDef& def)
    : m_def(def),
      m_skyProgram(loadProgram("sky", {"common_fullscreen.vert", "sky_background.frag"})),
      m_waterProgram(loadProgram("water_surface", {"water_surface.vert", "water_surface.frag"})),
      m_objectProgram(loadProgram("object_mesh", {"object_mesh.vert", "object_mesh.frag"})),
      m_sphereMesh(makeSphereMesh(16)),
      m_boxMesh(makeBoxMesh()),
      m_emptyVao(createVertexArray("fullscreen triangle")),
      m_frameUniforms(createBuffer("frame uniforms", sizeof(FrameUniforms))),
      m_waterUniforms(createBuffer("water uniforms", sizeof(WaterUniforms))) {
    GLuint id;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, "flat water maps");
    glTextureStorage3D(id, 1, GL_RGBA32F, 1, 1, 1);
    const float flat[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glTextureSubImage3D(id, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, flat);
    m_flatMaps = Texture(id);
}

// A (res+1)² vertex grid of (u, v) ∈ [0, 1]², triangles as an index list.
void Renderer::buildGrid(int resolution) {
    m_gridResolution = resolution;
    const int n = resolution + 1;
    std::vector<glm::vec2> uv;
    uv.reserve(size_t(n) * size_t(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) uv.emplace_back(float(i) / float(resolution), float(j) / float(resolution));
    std::vector<uint32_t> indices;
    indices.reserve(size_t(resolution) * size_t(resolution) * 6);
    for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i) {
            uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
    m_gridIndexCount = GLsizei(indices.size());
    m_gridVertices = createBuffer("projected grid uv", GLsizeiptr(uv.size() * sizeof(glm::vec2)), uv.data());
    m_gridIndices = createBuffer("projected grid indices", GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data());
    m_gridVao = createVertexArray("projected grid");
    glVertexArrayVertexBuffer(m_gridVao.id(), 0, m_gridVertices.id(), 0, sizeof(glm::vec2));
    glVertexArrayElementBuffer(m_gridVao.id(), m_gridIndices.id());
    glEnableVertexArrayAttrib(m_gridVao.id(), 0);
    glVertexArrayAttribFormat(m_gridVao.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(m_gridVao.id(), 0, 0);
}

void Renderer::render(const CameraView& camera, const WaterView& water, const std::vector<ObjectDraw>& objects, double time,
                      glm::ivec2 size) {
    m_gpuTimer.begin();
    glm::mat4 viewProjection = camera.projection * camera.view;
    FrameUniforms u{};
    u.viewProjection = viewProjection;
    u.inverseViewProjection = glm::inverse(viewProjection);
    u.cameraPositionTime = glm::vec4(camera.position, float(time));
    u.sunDirectionFresnel = glm::vec4(glm::normalize(m_def.sun_direction), m_def.fresnel == "exact" ? 1.0f : 0.0f);
    u.waterColorExposure = glm::vec4(m_def.water_color, m_def.exposure);
    u.viewport = glm::vec4(float(size.x), float(size.y), 0.0f, 0.0f);
    glNamedBufferSubData(m_frameUniforms.id(), 0, sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_UBO_BINDING, m_frameUniforms.id());

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // --- passes (sky last: it shades only the pixels nothing else covered)
    opaquePass(objects);
    waterPass(camera, water);
    skyPass();

    glBindVertexArray(0);
    m_gpuTimer.end();
}

void Renderer::skyPass() {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 1, -1, "sky");
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // the triangle sits on the far plane: only uncovered pixels pass
    glDepthMask(GL_FALSE);
    glBindVertexArray(m_emptyVao.id());
    glUseProgram(m_skyProgram.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    glPopDebugGroup();
}

void Renderer::opaquePass(const std::vector<ObjectDraw>& objects) {
    if (objects.empty()) return;
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 3, -1, "opaque");
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glUseProgram(m_objectProgram.id());
    for (const ObjectDraw& o : objects) {
        const Mesh& mesh = o.mesh == MeshKind::Sphere ? m_sphereMesh : m_boxMesh;
        glProgramUniformMatrix4fv(m_objectProgram.id(), 0, 1, GL_FALSE, &o.model[0][0]);
        glProgramUniform3fv(m_objectProgram.id(), 1, 1, &o.color.x);
        glBindVertexArray(mesh.vao.id());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_CULL_FACE);
    glPopDebugGroup();
}

void Renderer::waterPass(const CameraView& camera, const WaterView& water) {
    ocean::GridCorners grid = ocean::projectedGridCorners(camera.projection * camera.view, camera.position, GRID_MARGIN);
    if (!grid.visible) return;
    // Software rasterisers shade vertices on one thread: a coarser grid there.
    int resolution = m_def.grid_resolution > 0 ? std::max(m_def.grid_resolution, 16) : (isSoftwareRenderer() ? 128 : 512);
    if (m_gridResolution != resolution) buildGrid(resolution);

    WaterUniforms u{};
    for (int i = 0; i < 4; ++i) u.corner[i] = grid.corner[size_t(i)];
    const bool layers = water.cascades > 0 && water.displacement && water.slopes;
    const int cascades = layers ? water.cascades : 1;
    for (int c = 0; c < 4; ++c) u.cascadeSize[c] = layers ? water.cascadeSize[size_t(c)] : 1.0f;
    const int waves = std::min(int(water.gerstner.size()), MAX_GERSTNER_WAVES);
    for (int m = 0; m < waves; ++m) u.gerstner[m] = water.gerstner[size_t(m)];
    u.waterParams = glm::vec4(water.lambda, water.gravity, float(waves), GRID_MIN_W);
    u.gridParams = glm::vec4(float(m_gridResolution), 0.9f * camera.farM, float(cascades), float(layers ? water.resolution : 1));
    if (water.ripples && water.rippleCells > 0) {
        if (m_rippleCells != water.rippleCells) {
            GLuint id;
            glCreateTextures(GL_TEXTURE_2D, 1, &id);
            glObjectLabel(GL_TEXTURE, id, -1, "ripple heights");
            glTextureStorage2D(id, 1, GL_R32F, water.rippleCells, water.rippleCells);
            glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
            glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
            const float zero[4] = {0, 0, 0, 0};
            glTextureParameterfv(id, GL_TEXTURE_BORDER_COLOR, zero);
            m_rippleTexture = Texture(id);
            m_rippleCells = water.rippleCells;
        }
        glTextureSubImage2D(m_rippleTexture.id(), 0, 0, 0, m_rippleCells, m_rippleCells, GL_RED, GL_FLOAT, water.ripples);
        u.rippleParams = glm::vec4(water.rippleOrigin, water.rippleCellSize, float(m_rippleCells));
    }
    glNamedBufferSubData(m_waterUniforms.id(), 0, sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, WATER_UBO_BINDING, m_waterUniforms.id());

    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 2, -1, "water");
    glBindTextureUnit(0, layers ? water.displacement->id() : m_flatMaps.id());
    glBindTextureUnit(1, layers ? water.slopes->id() : m_flatMaps.id());
    glBindTextureUnit(2, u.rippleParams.w > 0.0f ? m_rippleTexture.id() : 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(m_waterProgram.id());
    glBindVertexArray(m_gridVao.id());
    glDrawElements(GL_TRIANGLES, m_gridIndexCount, GL_UNSIGNED_INT, nullptr);
    glPopDebugGroup();
}

void writeScreenshot(const std::string& path, glm::ivec2 size) {
    std::vector<unsigned char> pixels(size_t(size.x) * size_t(size.y) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glFinish();
    glReadPixels(0, 0, size.x, size.y, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows run bottom-up; PNG rows top-down.
    const size_t stride = size_t(size.x) * 3;
    std::vector<unsigned char> flipped(pixels.size());
    for (int y = 0; y < size.y; ++y)
        std::memcpy(&flipped[stride * size_t(y)], &pixels[stride * size_t(size.y - 1 - y)], stride);
    std::string tmp = path + ".tmp";
    errno = 0;
    int ok = stbi_write_png(tmp.c_str(), size.x, size.y, 3, flipped.data(), int(stride));
    if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
        int err = errno;
        std::remove(tmp.c_str());
        throw InputError("cannot write screenshot '" + path + "': " + std::strerror(err ? err : EIO));
    }
}

} // namespace ob::gfx
