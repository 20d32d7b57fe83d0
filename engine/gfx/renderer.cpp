// Renderer passes and the screenshot read-back.
#include "gfx/renderer.h"
#include "gfx/sun.h"

#include "core/error.h"
#include "core/file_write.h"
#include "core/log.h"
#include "assets/model.h"
#include "gfx/detail_map.h"
#include "gfx/shader.h"
#include "gfx/projected_grid.h"

#include <cassert>
#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <tuple>
#include <glm/glm.hpp>
#include <stb_image_write.h>
#include <utility>
#include <vector>

namespace ob::gfx {

constexpr GLuint FRAME_UBO_BINDING = 0;
constexpr GLuint WATER_UBO_BINDING = 1;
// Texture units of the water and sky passes (shaders/common_water.glsl, water_surface.frag).
enum TextureUnit : GLuint { DISPLACEMENT_UNIT, SLOPES_UNIT, RIPPLES_UNIT, SKY_UNIT, REFLECTION_UNIT, REFRACTION_UNIT,
                            DETAIL_UNIT, REFLECTION_DEPTH_UNIT, FOAM_UNIT, RIPPLE_SLOPES_UNIT, FOAM_PATTERN_UNIT };
// The projected grid reaches this fraction of the far clip distance; past it the grid is a
// wall up to the eye's level, which the camera sees exactly on the horizon line.
constexpr float GRID_REACH = 0.9f;
// A cascade starts to fade out at this fraction of its fade distance ([render] tile_fade tiles).
constexpr float TILE_FADE_START = 1.0f / 3.0f;
constexpr int SKY_CUBE_SIZE = 128;
constexpr int DETAIL_MAP_SIZE = 256;
// The baked foam pattern's texels over its repeat (three foam tiles, 15 m): 2 cm a texel, 46 over
// the finest octave's period.
constexpr int FOAM_PATTERN_SIZE = 1024;
// Mean water level (m): the mirrored eye's. The reflection and refraction passes cut objects
// at the surface itself, each reaching this far (m) past it so the waterline leaves no seam
// between the surface the water pass shades and the one the objects were cut at.
constexpr float WATER_LEVEL = 0.0f;
constexpr float REFLECTION_OVERLAP = 0.25f;
constexpr float REFRACTION_OVERLAP = 0.25f;
// The water's steepest slope (dh/dx) that the reflection and refraction passes assume when
// they decide that an object lies wholly on one side of the surface (steeper water breaks).
constexpr float MAX_SURFACE_SLOPE = 1.0f;
// Objects within this radius (m: fish, cannonballs) are cut at the surface's tangent plane
// under their origin, larger ones (ships) at the surface evaluated vertex by vertex.
constexpr float TANGENT_PLANE_RADIUS = 1.0f;
// A highlighted object's colour is multiplied by this (the body under the player's cursor).
constexpr glm::vec3 HIGHLIGHT_TINT{1.9f, 1.7f, 1.0f};
// A model's far twin (X.lod1.gltf) is drawn where the object's bounding sphere spans fewer
// than this many pixels of radius: the default scene's fish (0.4 m) 20 m away span 12 px at
// 720 rows (whole) and 3 px at scale 0.25 (the twin, a tenth of the triangles).
constexpr float LOD_RADIUS_PX = 8.0f;
const char* const PASS_NAMES[] = {"sky_bake", "reflection", "refraction", "opaque", "water", "sky", "splash", "post"};
// Samples a pixel of the msaa4 targets; the FXAA pass reads its source on this unit.
constexpr int MSAA_SAMPLES = 4;
constexpr GLuint FXAA_SOURCE_UNIT = 0;

Antialias antialiasMode(Antialias key, bool softwareRenderer) {
    if (key != Antialias::Auto) return key;
    return softwareRenderer ? Antialias::Fxaa : Antialias::Msaa4;
}

// Central differences (dh/dx, dh/dz) = (h(i+1, j) − h(i−1, j), h(i, j+1) − h(i, j−1)) / 2Δ of
// the n² ripple heights (row j along z), heights outside the patch 0, on an (n + 2)² grid
// whose texel (i + 1, j + 1) is cell (i, j): the water shader's ripple slope in one lookup.
static void rippleSlopes(const float* h, int n, float cellSize, std::vector<glm::vec2>& out) {
    const size_t m = size_t(n) + 2;
    out.assign(m * m, glm::vec2(0.0f));
    const auto at = [&](int i, int j) { return i < 0 || j < 0 || i >= n || j >= n ? 0.0f : h[size_t(j) * size_t(n) + size_t(i)]; };
    const float scale = 1.0f / (2.0f * cellSize);
    for (int j = -1; j <= n; ++j)
        for (int i = -1; i <= n; ++i)
            out[size_t(j + 1) * m + size_t(i + 1)] = scale * glm::vec2(at(i + 1, j) - at(i - 1, j), at(i, j + 1) - at(i, j - 1));
}

static int mipLevels(int size) {
    int levels = 1;
    while (size > 1) size /= 2, ++levels;
    return levels;
}

Renderer::Renderer(const RenderDef& def)
    : m_def(def),
      m_skyBakeProgram(loadProgram("sky bake", {"common_fullscreen.vert", "sky_cube.frag"})),
      m_skyProgram(loadProgram("sky", {"common_fullscreen.vert", "sky_background.frag"})),
      m_objectProgram(loadProgram("object_mesh", {"object_mesh.vert", "object_mesh.frag"})),
      m_objectWaterlineProgram(loadProgram("object_mesh_waterline", {"object_mesh_waterline.vert", "object_mesh.frag"})),
      m_upscaleProgram(loadProgram("upscale", {"common_fullscreen.vert", "post_upscale.frag"})),
      m_fxaaPrograms{loadProgram("fxaa off the edges", {"common_fullscreen.vert", "post_fxaa.frag"}, "#define FXAA_OFF_EDGES\n"),
                     loadProgram("fxaa on the edges", {"common_fullscreen.vert", "post_fxaa.frag"})},
      m_sphereMesh(makeSphereMesh(16)),
      m_boxMesh(makeBoxMesh()),
      m_ringMesh(makeRingMesh()),
      m_emptyVao(createVertexArray("fullscreen triangle")),
      m_frameUniforms{createBuffer("frame uniforms: camera", sizeof(FrameUniforms)),
                      createBuffer("frame uniforms: reflection", sizeof(FrameUniforms)),
                      createBuffer("frame uniforms: refraction", sizeof(FrameUniforms))},
      m_waterUniforms(createBuffer("water uniforms", sizeof(WaterUniforms))) {
    GLuint id;
    // No FFT layers: flat maps, J = 1 where each layout keeps it (displacement w, slopes z).
    const float flatDisplacement[4] = {0.0f, 0.0f, 0.0f, 1.0f}, flatSlopes[4] = {0.0f, 0.0f, 1.0f, 0.0f};
    for (auto [texture, label, texel] : {std::tuple{&m_flatDisplacement, "flat water displacement", flatDisplacement},
                                         std::tuple{&m_flatSlopes, "flat water slopes", flatSlopes}}) {
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
        glObjectLabel(GL_TEXTURE, id, -1, label);
        glTextureStorage3D(id, 1, GL_RGBA32F, 1, 1, 1);
        glTextureSubImage3D(id, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, texel);
        *texture = Texture(id);
    }

    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // filter across cube faces: no seams in the sky
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, "sky cube");
    glTextureStorage2D(id, mipLevels(SKY_CUBE_SIZE), GL_RGBA16F, SKY_CUBE_SIZE, SKY_CUBE_SIZE);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    m_skyCube = Texture(id);
    glCreateFramebuffers(1, &id);
    glObjectLabel(GL_FRAMEBUFFER, id, -1, "sky bake");
    m_skyBakeFramebuffer = Framebuffer(id);

    bakeDetailMaps();
    GLuint sampler;
    glCreateSamplers(1, &sampler);
    glObjectLabel(GL_SAMPLER, sampler, -1, "nearest mip, repeated");
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_REPEAT);
    m_nearestMipSampler = Sampler(sampler);

    for (const char* name : PASS_NAMES) m_passTimers.emplace_back(name);
    static_assert(std::size(PASS_NAMES) == PASS_COUNT);

    GLint colorSamples = 0, depthSamples = 0;
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &colorSamples);
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depthSamples);
    m_msaaSupported = std::min(colorSamples, depthSamples) >= MSAA_SAMPLES;
    GLint depthBits = 0;
    glGetNamedFramebufferAttachmentParameteriv(0, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    m_framebufferDepth = depthBits > 0;
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

// The detail map (RGBA8, (du, dv) stored as 0.5 + 0.5·x: llvmpipe filters 8-bit texels on its
// fast path) and the foam pattern baked from it (shaders/foam_pattern_bake.frag), both tiling.
void Renderer::bakeDetailMaps() {
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
    const Program bake = loadProgram("foam pattern bake", {"common_fullscreen.vert", "foam_pattern_bake.frag"});
    glUseProgram(bake.id());
    glBindTextureUnit(DETAIL_UNIT, m_detailMap.id());
    glBindVertexArray(m_emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGenerateTextureMipmap(m_foamPattern.id());
}

// The three views: the camera, the camera seeing the objects mirrored in the water surface
// (keeping what is above it, seed 004 eq. 1–3), and the camera again keeping what is below.
// The object shader cuts and mirrors at the composite surface under each vertex, so its
// view-projection stays the camera's.
void Renderer::updateFrameUniforms(const CameraView& camera, double time, glm::ivec2 size) {
    FrameUniforms u{};
    u.sunDirectionFresnel = glm::vec4(sunDirection(m_def), m_def.fresnel == Fresnel::Exact ? 1.0f : 0.0f);
    u.waterColorExposure = glm::vec4(m_def.water_color, m_def.exposure);
    u.depthParams = glm::vec4(camera.nearM, camera.farM, m_def.water_clarity, float(mipLevels(SKY_CUBE_SIZE)));
    u.shading = glm::vec4(m_def.dudv_strength, m_def.normal_distortion, m_def.glitter, m_def.glitter_shininess);
    u.switches = glm::vec4(m_def.reflections ? 1.0f : 0.0f, m_def.refractions ? 1.0f : 0.0f, m_def.foam ? 1.0f : 0.0f, 0.0f);
    const float underwater = m_underwater ? 1.0f : 0.0f;

    const glm::mat4 viewProjection = camera.projection * camera.view;
    u.viewProjection = viewProjection;
    u.inverseViewProjection = glm::inverse(viewProjection);
    u.cameraPositionTime = glm::vec4(camera.position, float(time));
    u.viewport = glm::vec4(float(size.x), float(size.y), m_antialias == Antialias::Fxaa ? 2.0f : 0.0f, underwater);
    u.surfaceClip = glm::vec4(0.0f);
    glNamedBufferSubData(m_frameUniforms[MAIN_VIEW].id(), 0, sizeof u, &u);

    // The mirrored eye (about the mean level) lights the mirrored objects.
    u.cameraPositionTime = glm::vec4(camera.position.x, 2.0f * WATER_LEVEL - camera.position.y, camera.position.z, float(time));
    u.viewport = glm::vec4(glm::vec2(m_reflection.size), 1.0f, underwater);
    u.surfaceClip = glm::vec4(1.0f, REFLECTION_OVERLAP, 1.0f, 0.0f);
    glNamedBufferSubData(m_frameUniforms[REFLECTION_VIEW].id(), 0, sizeof u, &u);

    u.cameraPositionTime = glm::vec4(camera.position, float(time));
    u.viewport = glm::vec4(glm::vec2(m_refraction.size), 3.0f, underwater);
    u.surfaceClip = glm::vec4(-1.0f, REFRACTION_OVERLAP, 0.0f, 0.0f);
    glNamedBufferSubData(m_frameUniforms[REFRACTION_VIEW].id(), 0, sizeof u, &u);
}

static glm::ivec2 scaled(glm::ivec2 size, float scale) { return glm::max(glm::ivec2(glm::vec2(size) * scale + 0.5f), glm::ivec2(1)); }

// Targets come and go with the settings: the multisampled ones exist only in msaa4, the
// internal frame only when the frame is not drawn into the framebuffer directly.
void Renderer::resizeTargets(glm::ivec2 internal) {
    const glm::ivec2 target = scaled(internal, m_def.rtt_scale);
    if (m_reflection.size != target) {
        m_reflection = createRenderTarget("reflection target", target);
        m_refraction = createRenderTarget("refraction target", target);
    }
    const bool msaa = m_antialias == Antialias::Msaa4;
    if (!msaa) m_rttMultisampled = {}, m_multisampled = {};
    if (msaa && m_rttMultisampled.size != target)
        m_rttMultisampled = createRenderTarget("reflection/refraction samples", target, MSAA_SAMPLES);
    if (msaa && m_multisampled.size != internal)
        m_multisampled = createRenderTarget("internal frame samples", internal, MSAA_SAMPLES, GL_RGBA8);
    const bool offscreen = m_def.resolution_scale < 1.0f || m_antialias != Antialias::Off;
    if (!offscreen) m_internal = {};
    if (offscreen && m_internal.size != internal) m_internal = createRenderTarget("internal frame", internal, 1, GL_RGBA8);
    const bool antialiased = m_antialias == Antialias::Fxaa && (m_def.resolution_scale < 1.0f || !m_framebufferDepth);
    if (!antialiased) m_antialiased = {};
    if (antialiased && m_antialiased.size != internal) m_antialiased = createRenderTarget("anti-aliased frame", internal, 1, GL_RGBA8);
}

void Renderer::render(const CameraView& camera, const WaterView& water, const std::vector<ObjectDraw>& objects, double time,
                      glm::ivec2 size, std::span<const SplashDrop> drops) {
    m_underwater = camera.position.y < camera.waterHeight;
    m_antialias = antialiasMode(m_def.antialias, isSoftwareRenderer());
    if (m_antialias == Antialias::Msaa4 && !m_msaaSupported) {
        static bool warned = false;
        if (!std::exchange(warned, true)) logWarn("render.antialias: this GL driver has no 4× multisampled float targets; using fxaa");
        m_antialias = Antialias::Fxaa;
    }
    const bool upscale = m_def.resolution_scale < 1.0f;
    const glm::ivec2 internal = upscale ? scaled(size, m_def.resolution_scale) : size;
    resizeTargets(internal);
    updateFrameUniforms(camera, time, internal);
    // Pixels per radian at the centre of each view's target (the far twins' choice).
    m_eye = camera.position;
    m_pixelsPerRadian[MAIN_VIEW] = 0.5f * float(internal.y) * camera.projection[1][1];
    m_pixelsPerRadian[REFLECTION_VIEW] = m_pixelsPerRadian[REFRACTION_VIEW] = 0.5f * float(m_reflection.size.y) * camera.projection[1][1];

    // --- passes
    if (sunDirection(m_def) != m_bakedSun) skyBakePass();
    prepareWater(camera, water, internal.y);
    uploadSplashDrops(drops, camera);
    const bool above = !m_underwater;
    if (m_def.reflections && above) reflectionPass(objects);
    if (m_def.refractions && above) refractionPass(objects);
    // The frame goes straight into the framebuffer only when nothing follows it.
    const bool direct = !upscale && m_antialias == Antialias::Off;
    const RenderTarget& frame = m_antialias == Antialias::Msaa4 ? m_multisampled : m_internal;
    glBindFramebuffer(GL_FRAMEBUFFER, direct ? 0 : frame.framebuffer.id());
    glViewport(0, 0, internal.x, internal.y);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_UBO_BINDING, m_frameUniforms[MAIN_VIEW].id());
    opaquePass(objects);
    waterPass(camera);
    skyPass();  // it shades only the pixels nothing else covered
    splashPass();  // after the sky: the sprites write no depth
    if (!direct) postPass(size);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
}

PassTimes Renderer::takePassTimes() {
    PassTimes times;
    for (int p = 0; p < PASS_COUNT; ++p) {
        double ms = m_passTimers[size_t(p)].takeResultMs();
        if (ms >= 0.0) times.emplace_back(PASS_NAMES[p], ms);
    }
    return times;
}

// Faces in GL's cube map order (+x, −x, +y, −y, +z, −z), each as the world direction of face
// coordinates (s, t) = (ndc.x, ndc.y): columns s axis, t axis, face normal.
static const glm::mat3 CUBE_FACES[6] = {
    glm::mat3(glm::vec3(0, 0, -1), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0)),
    glm::mat3(glm::vec3(0, 0, 1), glm::vec3(0, -1, 0), glm::vec3(-1, 0, 0)),
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0)),
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, -1, 0)),
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1)),
    glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, -1)),
};

void Renderer::skyBakePass() {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, SKY_BAKE_PASS, -1, "sky bake");
    m_passTimers[SKY_BAKE_PASS].begin();
    m_bakedSun = sunDirection(m_def);
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_UBO_BINDING, m_frameUniforms[MAIN_VIEW].id());
    glBindFramebuffer(GL_FRAMEBUFFER, m_skyBakeFramebuffer.id());
    glViewport(0, 0, SKY_CUBE_SIZE, SKY_CUBE_SIZE);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(m_skyBakeProgram.id());
    glBindVertexArray(m_emptyVao.id());
    for (int face = 0; face < 6; ++face) {
        glNamedFramebufferTextureLayer(m_skyBakeFramebuffer.id(), GL_COLOR_ATTACHMENT0, m_skyCube.id(), 0, face);
        glProgramUniformMatrix3fv(m_skyBakeProgram.id(), 0, 1, GL_FALSE, &CUBE_FACES[face][0][0]);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glGenerateTextureMipmap(m_skyCube.id());
    m_passTimers[SKY_BAKE_PASS].end();
    glPopDebugGroup();
}

// Binds a target for drawing, cleared to transparent black and the far plane.
static void clearTarget(const RenderTarget& target) {
    const float color[4] = {0, 0, 0, 0}, depth = 1.0f;
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, 0, color);
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_DEPTH, 0, &depth);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glViewport(0, 0, target.size.x, target.size.y);
}

void Renderer::reflectionPass(const std::vector<ObjectDraw>& objects) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, REFLECTION_PASS, -1, "reflection");
    m_passTimers[REFLECTION_PASS].begin();
    const bool msaa = m_antialias == Antialias::Msaa4;
    clearTarget(msaa ? m_rttMultisampled : m_reflection);  // alpha 0: no local reflection, the sky cube shows
    glFrontFace(GL_CW);  // the mirror flips the winding
    drawObjects(objects, REFLECTION_VIEW);
    glFrontFace(GL_CCW);
    drawSplashDrops(REFLECTION_VIEW);
    if (msaa) resolveTarget(m_rttMultisampled, m_reflection, true);  // alpha becomes fractional coverage at edges
    m_passTimers[REFLECTION_PASS].end();
    glPopDebugGroup();
}

void Renderer::refractionPass(const std::vector<ObjectDraw>& objects) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, REFRACTION_PASS, -1, "refraction");
    m_passTimers[REFRACTION_PASS].begin();
    const bool msaa = m_antialias == Antialias::Msaa4;
    clearTarget(msaa ? m_rttMultisampled : m_refraction);  // depth 1: open water, the full body colour
    drawObjects(objects, REFRACTION_VIEW);
    if (msaa) resolveTarget(m_rttMultisampled, m_refraction, true);
    m_passTimers[REFRACTION_PASS].end();
    glPopDebugGroup();
}

void Renderer::opaquePass(const std::vector<ObjectDraw>& objects) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, OPAQUE_PASS, -1, "opaque");
    m_passTimers[OPAQUE_PASS].begin();
    drawObjects(objects, MAIN_VIEW);
    m_passTimers[OPAQUE_PASS].end();
    glPopDebugGroup();
}

// The model X.gltf (X.glb) and its far twin X.lod1.gltf (X.lod1.glb) beside it, if there is
// one: loaded on first use.
const Renderer::ModelMeshes& Renderer::meshesFor(const std::string& file) {
    auto it = m_models.find(file);
    if (it == m_models.end()) {
        ModelMeshes meshes{makeMesh(file, assets::loadGltfModel(file)), std::nullopt};
        const std::string far = assets::lodTwinPath(file);  // checked with the scene (world/scene.cpp)
        if (std::filesystem::exists(far)) meshes.far = makeMesh(far, assets::loadGltfModel(far));
        it = m_models.emplace(file, std::move(meshes)).first;
    }
    return it->second;
}

static float boundingRadius(const ObjectDraw& o, const Mesh& mesh) {
    return mesh.radius * std::max({glm::length(glm::vec3(o.model[0])), glm::length(glm::vec3(o.model[1])), glm::length(glm::vec3(o.model[2]))});
}

// The mesh to draw in a view: a model's far twin where the object's bounding sphere spans
// fewer than LOD_RADIUS_PX pixels of radius in that view's target.
const Mesh& Renderer::meshFor(const ObjectDraw& object, View view) {
    if (object.modelFile.empty())
        switch (object.mesh) {
        case MeshKind::Sphere: return m_sphereMesh;
        case MeshKind::Box: return m_boxMesh;
        case MeshKind::Ring: return m_ringMesh;
        }
    const ModelMeshes& meshes = meshesFor(object.modelFile);
    if (!meshes.far) return meshes.near;
    const float distance = std::max(glm::length(glm::vec3(object.model[3]) - m_eye), 1e-3f);
    const float pixels = boundingRadius(object, meshes.near) / distance * m_pixelsPerRadian[view];
    return pixels < LOD_RADIUS_PX ? *meshes.far : meshes.near;
}

// Where an object's bounding sphere lies against the water: the surface within its radius
// R of the height under its origin h0 stays within h0 ± R·MAX_SURFACE_SLOPE.
enum class Side { Above, Below, Across };
static Side sideOfSurface(const ObjectDraw& o, const Mesh& mesh) {
    const float reach = boundingRadius(o, mesh) * (1.0f + MAX_SURFACE_SLOPE);
    const float y = o.model[3].y;
    if (y - reach > o.waterHeight + REFLECTION_OVERLAP) return Side::Above;
    if (y + reach < o.waterHeight - REFRACTION_OVERLAP) return Side::Below;
    return Side::Across;
}

void Renderer::drawObjects(const std::vector<ObjectDraw>& objects, View view) {
    if (objects.empty()) return;
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_UBO_BINDING, m_frameUniforms[view].id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    if (view != MAIN_VIEW) glEnable(GL_CLIP_DISTANCE0);
    for (const ObjectDraw& o : objects) {
        const Mesh& mesh = meshFor(o, view);
        // An object wholly on one side of the surface is skipped by the pass that keeps the
        // other side, and wholly under it by the camera's view from above: the water surface,
        // drawn after it and opaque, covers it (the refraction pass shows it). The surface per
        // vertex (the cut's cost on a software rasteriser) is evaluated only for large objects
        // across it in the passes that cut; the others take its tangent plane.
        const Side side = sideOfSurface(o, mesh);
        if ((view == REFLECTION_VIEW && side == Side::Below) || (view == REFRACTION_VIEW && side == Side::Above) ||
            (view == MAIN_VIEW && side == Side::Below && !m_underwater && m_grid.visible))
            continue;
        const bool perVertex = view != MAIN_VIEW && side == Side::Across && boundingRadius(o, mesh) > TANGENT_PLANE_RADIUS;
        const GLuint program = perVertex ? m_objectWaterlineProgram.id() : m_objectProgram.id();
        const glm::vec3 plane(o.waterHeight, o.waterSlope);
        // Models carry their own colours; a highlighted object is drawn brighter and warmer.
        const glm::vec3 tint = (o.modelFile.empty() ? o.color : glm::vec3(1.0f)) * (o.highlight ? HIGHLIGHT_TINT : glm::vec3(1.0f));
        glUseProgram(program);
        glProgramUniformMatrix4fv(program, 0, 1, GL_FALSE, &o.model[0][0]);
        glProgramUniform3fv(program, 1, 1, &tint.x);
        if (!perVertex) glProgramUniform3fv(program, 2, 1, &plane.x);
        glBindVertexArray(mesh.vao.id());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CULL_FACE);
    glBindBufferBase(GL_UNIFORM_BUFFER, FRAME_UBO_BINDING, m_frameUniforms[MAIN_VIEW].id());
}

void Renderer::skyPass() {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, SKY_PASS, -1, "sky");
    m_passTimers[SKY_PASS].begin();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // the triangle sits on the far plane: only uncovered pixels pass
    glDepthMask(GL_FALSE);
    glBindTextureUnit(SKY_UNIT, m_skyCube.id());
    glBindVertexArray(m_emptyVao.id());
    glUseProgram(m_skyProgram.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    m_passTimers[SKY_PASS].end();
    glPopDebugGroup();
}

// The internal frame to the framebuffer: the samples resolved (msaa4) or FXAA (sharpened off
// the edges when it is to be scaled up), at the internal size; then a blit, bilinear when it
// scales up. FXAA before the scaling costs its lookups per internal pixel only.
void Renderer::postPass(glm::ivec2 size) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, POST_PASS, -1, "post");
    m_passTimers[POST_PASS].begin();
    if (m_antialias == Antialias::Msaa4) resolveTarget(m_multisampled, m_internal, false);
    const glm::ivec2 internal = m_internal.size;
    const RenderTarget* last = &m_internal;
    if (m_antialias == Antialias::Fxaa) {
        // Off the edges first, marked at depth 0; then the edges' walk only where depth is left
        // at 1 (post_fxaa.frag): the rasteriser skips the blocks with no edge pixel. Each pixel
        // is written once, into the framebuffer itself at full size when it has a depth buffer.
        const bool upscaled = internal != size;
        const bool intoFramebuffer = !upscaled && m_framebufferDepth;
        const GLuint target = intoFramebuffer ? 0 : m_antialiased.framebuffer.id();
        const float far = 1.0f;
        glClearNamedFramebufferfv(target, GL_DEPTH, 0, &far);
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, internal.x, internal.y);
        glEnable(GL_DEPTH_TEST);
        glBindTextureUnit(FXAA_SOURCE_UNIT, m_internal.color.id());
        glBindVertexArray(m_emptyVao.id());
        for (const Program& program : m_fxaaPrograms) {
            const bool offEdges = &program == &m_fxaaPrograms[0];
            glDepthFunc(offEdges ? GL_ALWAYS : GL_LEQUAL);
            glDepthMask(offEdges ? GL_TRUE : GL_FALSE);
            glProgramUniform2f(program.id(), 0, 1.0f / float(internal.x), 1.0f / float(internal.y));
            glProgramUniform1f(program.id(), 1, upscaled ? m_def.upscale_sharpness : 0.0f);
            glUseProgram(program.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glBindTextureUnit(FXAA_SOURCE_UNIT, 0);  // drawn into again next frame
        last = intoFramebuffer ? nullptr : &m_antialiased;
    }
    if (last && internal == size) {
        glBlitNamedFramebuffer(last->framebuffer.id(), 0, 0, 0, internal.x, internal.y, 0, 0, size.x, size.y,
                               GL_COLOR_BUFFER_BIT, GL_NEAREST);
    } else if (last) {  // scaled up: one bilinear lookup a pixel (a draw; llvmpipe's blit costs more)
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_DEPTH_TEST);
        glBindTextureUnit(FXAA_SOURCE_UNIT, last->color.id());
        glUseProgram(m_upscaleProgram.id());
        glBindVertexArray(m_emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindTextureUnit(FXAA_SOURCE_UNIT, 0);
    }
    m_passTimers[POST_PASS].end();
    glPopDebugGroup();
}

// How far the layers can move a rest point: the FFT cascades' extremes (from the view), the
// Gerstner waves' Σ a (each moves a point by a along its K and by a·cos θ up), the ripple
// patch's extremes (heights only). The projected grid reaches that far past the view.
static ocean::DisplacementBounds displacementBounds(const WaterView& water) {
    ocean::DisplacementBounds bounds;
    if (water.cascades > 0 && water.displacement) bounds = water.fftBounds;
    float amplitudes = 0.0f;
    const size_t waves = std::min(water.gerstner.size(), size_t(MAX_GERSTNER_WAVES));
    for (size_t m = 0; m < waves; ++m) amplitudes += std::abs(water.gerstner[m].z);
    bounds += {amplitudes, amplitudes, amplitudes};
    if (water.ripples && water.rippleCells > 0) {
        const auto [lo, hi] = std::minmax_element(water.ripples, water.ripples + size_t(water.rippleCells) * size_t(water.rippleCells));
        bounds += {std::max(*hi, 0.0f), std::max(-*lo, 0.0f), 0.0f};
    }
    return bounds;
}

void Renderer::uploadWaterUniforms(const CameraView& camera, const WaterView& water, const GridCorners& grid) {
    WaterUniforms u{};
    for (int i = 0; i < 4; ++i) u.corner[i] = grid.corner[size_t(i)];
    const bool layers = water.cascades > 0 && water.displacement && water.slopes;
    const int cascades = layers ? water.cascades : 1;
    for (int c = 0; c < 4; ++c) u.cascadeSize[c] = layers ? water.cascadeSize[size_t(c)] : 1.0f;
    u.farFade = glm::vec4(m_def.far_fade ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    for (int c = 0; c < 4 && layers && m_def.far_fade; ++c) {
        u.cascadeFadeEnd[c] = m_def.tile_fade * water.cascadeSize[size_t(c)];
        u.cascadeFade[c] = TILE_FADE_START * u.cascadeFadeEnd[c];
    }
    const int waves = std::min(int(water.gerstner.size()), MAX_GERSTNER_WAVES);
    for (int m = 0; m < waves; ++m) u.gerstner[m] = water.gerstner[size_t(m)];
    u.waterParams = glm::vec4(water.lambda, water.gravity, float(waves), 0.5f * grid.minW);  // the clamp only guards rounding
    u.gridParams = glm::vec4(float(m_gridResolution), GRID_REACH * camera.farM, float(cascades), float(layers ? water.resolution : 1));
    if (water.ripples && water.rippleCells > 0) {
        if (m_rippleCells != water.rippleCells) {
            m_rippleTexture = createTexture2D("ripple heights", GL_R32F, glm::ivec2(water.rippleCells));
            glTextureParameteri(m_rippleTexture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
            glTextureParameteri(m_rippleTexture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
            const float zero[4] = {0, 0, 0, 0};
            glTextureParameterfv(m_rippleTexture.id(), GL_TEXTURE_BORDER_COLOR, zero);
            m_rippleSlopeTexture = createTexture2D("ripple slopes", GL_RG32F, glm::ivec2(water.rippleCells + 2));
            m_rippleCells = water.rippleCells;
        }
        glTextureSubImage2D(m_rippleTexture.id(), 0, 0, 0, m_rippleCells, m_rippleCells, GL_RED, GL_FLOAT, water.ripples);
        rippleSlopes(water.ripples, m_rippleCells, water.rippleCellSize, m_rippleSlopes);
        glTextureSubImage2D(m_rippleSlopeTexture.id(), 0, 0, 0, m_rippleCells + 2, m_rippleCells + 2, GL_RG, GL_FLOAT, m_rippleSlopes.data());
        u.rippleParams = glm::vec4(water.rippleOrigin, water.rippleCellSize, float(m_rippleCells));
    }
    uploadFoam(water, u);
    m_waterVariant = {.cascades = layers ? cascades : 0,
                      .ripples = u.rippleParams.w > 0.0f,
                      .foamMap = u.foamParams.w > 0.0f,
                      .underwater = m_underwater,
                      .exactFresnel = m_def.fresnel == Fresnel::Exact,
                      .reflections = m_def.reflections,
                      .refractions = m_def.refractions,
                      .foam = m_def.foam,
                      .fullQuality = m_def.water_full_quality};
    glNamedBufferSubData(m_waterUniforms.id(), 0, sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, WATER_UBO_BINDING, m_waterUniforms.id());
    glBindTextureUnit(FOAM_UNIT, u.foamParams.w > 0.0f ? m_foamTexture.id() : 0);
    glBindTextureUnit(DISPLACEMENT_UNIT, layers ? water.displacement->id() : m_flatDisplacement.id());
    glBindTextureUnit(SLOPES_UNIT, layers ? water.slopes->id() : m_flatSlopes.id());
    glBindTextureUnit(RIPPLES_UNIT, u.rippleParams.w > 0.0f ? m_rippleTexture.id() : 0);
    glBindTextureUnit(RIPPLE_SLOPES_UNIT, u.rippleParams.w > 0.0f ? m_rippleSlopeTexture.id() : 0);
}

// Before the object passes: they clip against (and mirror about) the surface these describe.
void Renderer::prepareWater(const CameraView& camera, const WaterView& water, int internalHeight) {
    m_grid = projectedGridCorners(camera.projection * camera.view, camera.position, displacementBounds(water));
    // Auto: a grid row per 3 px of internal height on a GPU, per 12 px on a software rasteriser,
    // within [32, 512]. A software rasteriser shades vertices on one thread, and it shades a 4×4
    // block of pixels once for every triangle that touches it (docs/frame.md).
    const int autoCells = std::clamp(internalHeight / (isSoftwareRenderer() ? 12 : 3), 32, 512);
    const int resolution = m_def.grid_resolution > 0 ? m_def.grid_resolution : autoCells;  // [16, 2048]: render_def.h
    if (m_gridResolution != resolution) buildGrid(resolution);
    uploadWaterUniforms(camera, water, m_grid);
}

std::string WaterVariant::defines() const {
    const auto flag = [](const char* name, bool on) { return std::string("#define ") + name + (on ? " true\n" : " false\n"); };
    return "#define WATER_VARIANT\n#define WATER_CASCADES " + std::to_string(cascades) + "\n" + flag("WATER_RIPPLES", ripples) +
           flag("WATER_FOAM_MAP", foamMap) + flag("WATER_UNDERWATER", underwater) + flag("WATER_EXACT_FRESNEL", exactFresnel) +
           flag("WATER_REFLECTIONS", reflections) + flag("WATER_REFRACTIONS", refractions) + flag("WATER_FOAM", foam) +
           (fullQuality ? "#define WATER_FULL_QUALITY\n" : "");
}

void Renderer::waterPass(const CameraView&) {
    if (!m_grid.visible) return;
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, WATER_PASS, -1, "water");
    m_passTimers[WATER_PASS].begin();
    glBindTextureUnit(SKY_UNIT, m_skyCube.id());
    glBindTextureUnit(REFLECTION_UNIT, m_reflection.color.id());
    glBindTextureUnit(REFRACTION_UNIT, m_refraction.color.id());
    glBindTextureUnit(DETAIL_UNIT, m_detailMap.id());
    glBindTextureUnit(FOAM_PATTERN_UNIT, m_foamPattern.id());
    glBindTextureUnit(REFLECTION_DEPTH_UNIT, m_reflection.depth.id());
    // A software rasteriser filters the ocean's slopes, the detail map and the foam pattern from
    // their nearest mip only: bilinear, not trilinear (full quality keeps trilinear).
    const GLuint mipSampler = isSoftwareRenderer() && !m_def.water_full_quality ? m_nearestMipSampler.id() : 0;
    for (GLuint unit : {SLOPES_UNIT, DETAIL_UNIT, FOAM_PATTERN_UNIT}) glBindSampler(unit, mipSampler);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const std::string defines = m_waterVariant.defines();
    auto program = m_waterPrograms.find(defines);
    if (program == m_waterPrograms.end())
        program = m_waterPrograms.emplace(defines, loadProgram("water_surface", {"water_surface.vert", "water_surface.frag"}, defines)).first;
    glUseProgram(program->second.id());
    glBindVertexArray(m_gridVao.id());
    glDrawElements(GL_TRIANGLES, m_gridIndexCount, GL_UNSIGNED_INT, nullptr);
    // The targets are drawn into again next frame: never leave them bound for sampling.
    for (GLuint unit : {REFLECTION_UNIT, REFRACTION_UNIT, REFLECTION_DEPTH_UNIT}) glBindTextureUnit(unit, 0);
    for (GLuint unit : {SLOPES_UNIT, DETAIL_UNIT, FOAM_PATTERN_UNIT}) glBindSampler(unit, 0);
    m_passTimers[WATER_PASS].end();
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
    std::string png;
    const auto put = [](void* to, void* data, int size) { static_cast<std::string*>(to)->append(static_cast<char*>(data), size_t(size)); };
    if (!stbi_write_png_to_func(put, &png, size.x, size.y, 3, flipped.data(), int(stride)))
        throw RuntimeError("cannot write screenshot '" + path + "': PNG encoding failed");
    writeFileWhole(path, "screenshot", [&](std::ostream& out) { out.write(png.data(), std::streamsize(png.size())); });
}

} // namespace ob::gfx
