// The water pass: projected grid, water uniforms, the program per variant, the draw.
#include "gfx/water_pass.h"

#include "gfx/gl.h"
#include "gfx/shader.h"
#include "gfx/sky_pass.h"
#include "gfx/surface_passes.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
// The projected grid reaches this fraction of the far clip distance; past it the grid is a
// wall up to the eye's level, which the camera sees exactly on the horizon line.
constexpr float GRID_REACH = 0.9f;
// A cascade starts to fade out at this fraction of its fade distance ([render] tile_fade tiles).
constexpr float TILE_FADE_START = 1.0f / 3.0f;
// The crest height at which the subsurface term is whole, as a share of the tallest crest the
// layers can raise (their bound adds every wave's amplitude, which few crests reach).
constexpr float CREST_SHARE = 0.25f;

// How far the layers can move a rest point: the FFT cascades' extremes (from the view), the
// Gerstner waves' Σ a (each moves a point by a along its K and by a·cos θ up), the ripple
// patch's extremes (heights only). The projected grid reaches that far past the view.
SurfaceBounds displacementBounds(const WaterView& water) {
    SurfaceBounds bounds;
    if (water.cascades > 0 && water.displacement) bounds = water.fftBounds;
    float amplitudes = 0.0f;
    const size_t waves = std::min(water.gerstner.size(), size_t(MAX_GERSTNER_WAVES));
    for (size_t m = 0; m < waves; ++m) amplitudes += std::abs(water.gerstner[m].z);
    bounds += {amplitudes, amplitudes, amplitudes};
    if (water.ripples && water.rippleCells > 0) {
        const auto [lo, hi] = std::minmax_element(water.ripples, water.ripples + size_t(water.rippleCells) * size_t(water.rippleCells));
        float top = *hi, bottom = *lo;
        for (const WaterView::RippleLevel& level : water.rippleLevels) {  // the cubic's bound from its states' extremes
            float t = 0.0f, b = 0.0f;
            for (int k = 0; k < 4; ++k) {
                const float w = level.weights[k], lo = level.extremes[size_t(k)].x, hi = level.extremes[size_t(k)].y;
                t += std::max(w * lo, w * hi);
                b += std::min(w * lo, w * hi);
            }
            top = std::max(top, t);
            bottom = std::min(bottom, b);
        }
        bounds += {std::max(top, 0.0f), std::max(-bottom, 0.0f), 0.0f};
    }
    return bounds;
}
} // namespace

std::string WaterVariant::defines() const {
    const auto flag = [](const char* name, bool on) { return std::string("#define ") + name + (on ? " true\n" : " false\n"); };
    return "#define WATER_VARIANT\n#define WATER_CASCADES " + std::to_string(cascades) + "\n" + flag("WATER_RIPPLES", ripples) +
           flag("WATER_FOAM_MAP", foamMap) + flag("WATER_UNDERWATER", underwater) + flag("WATER_WATERLINE", waterline) +
           flag("WATER_EXACT_FRESNEL", exactFresnel) + flag("WATER_CLOUDS", clouds) +
           flag("WATER_REFLECTIONS", reflections) + flag("WATER_REFRACTIONS", refractions) + flag("WATER_FOAM", foam) +
           flag("WATER_HULL_CLIP", hullClip) + "#define WATER_HULL_DEPTH_SAMPLES " + std::to_string(hullDepthSamples) + "\n" +
           (fullQuality ? "#define WATER_FULL_QUALITY\n" : "");
}

WaterPass::WaterPass() : m_uniforms(createBuffer("water uniforms", sizeof(WaterUniforms))) {}

void WaterPass::listPrograms(ProgramList& out) const {
    for (const auto& [defines, program] : m_programs) out.emplace_back("water_surface " + defines, program.id());
    m_detail.listPrograms(out);
}

// A (res+1)² vertex grid of (u, v) ∈ [0, 1]², triangles as an index list.
void WaterPass::buildGrid(int resolution) {
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
    glEnableVertexArrayAttrib(m_gridVao.id(), GRID_UV_ATTRIB);
    glVertexArrayAttribFormat(m_gridVao.id(), GRID_UV_ATTRIB, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(m_gridVao.id(), GRID_UV_ATTRIB, 0);
}

static_assert(HULL_OUTLINE_STATIONS == assets::HullOutline::STATIONS && HULL_OUTLINE_HEIGHTS == assets::HullOutline::HEIGHTS);

// The layer of the outlines texture that holds `outline` (a new one is added: the texture is
// made anew, with every outline seen so far).
int WaterPass::hullOutlineLayer(const std::shared_ptr<const assets::HullOutline>& outline) {
    const auto known = std::find(m_hullOutlineLayers.begin(), m_hullOutlineLayers.end(), outline);
    if (known != m_hullOutlineLayers.end()) return int(known - m_hullOutlineLayers.begin());
    m_hullOutlineLayers.push_back(outline);
    return int(m_hullOutlineLayers.size()) - 1;
}

// The outlines seen so far, a layer each (one zero layer when there is none: the sampler is bound).
void WaterPass::uploadHullOutlines() {
    constexpr int ROW = assets::HullOutline::ROW, STATIONS = assets::HullOutline::STATIONS;
    const int layers = std::max(int(m_hullOutlineLayers.size()), 1);
    GLuint id;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, "hull clip: outlines");
    glTextureStorage3D(id, 1, GL_R32F, ROW, STATIONS, layers);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    m_hullOutlines = Texture(id);
    const std::vector<float> zero(size_t(ROW) * STATIONS, 0.0f);
    for (int l = 0; l < layers; ++l) {
        const float* data = l < int(m_hullOutlineLayers.size()) ? m_hullOutlineLayers[size_t(l)]->table.data() : zero.data();
        glTextureSubImage3D(id, 0, 0, 0, l, ROW, STATIONS, 1, GL_RED, GL_FLOAT, data);
    }
}

// The hulls nearest the eye first, at most MAX_HULL_CLIPS (a far hull past the limit spans few
// pixels, and its water shows there).
int WaterPass::uploadHullClips(const WaterView& water, const CameraView& camera, WaterUniforms& u) {
    std::vector<const HullClip*> order;
    for (const HullClip& h : water.hulls) order.push_back(&h);
    const auto eyeDistance = [&camera](const HullClip* h) {  // to the hull box's centre, m
        return glm::length(glm::vec3(glm::inverse(h->worldToHull)[3]) - camera.position);
    };
    const size_t count = std::min(order.size(), size_t(MAX_HULL_CLIPS));
    std::partial_sort(order.begin(), order.begin() + ptrdiff_t(count), order.end(),
                      [&](const HullClip* a, const HullClip* b) { return eyeDistance(a) < eyeDistance(b); });
    // Outlines of hulls gone (a restart, another scene) are dropped once more are held than drawn.
    const bool renew = m_hullOutlineLayers.size() > size_t(MAX_HULL_CLIPS);
    if (renew) m_hullOutlineLayers.clear();
    const size_t layers = m_hullOutlineLayers.size();
    for (size_t i = 0; i < count; ++i) {
        u.hullFromWorld[i] = order[i]->worldToHull;
        u.hullPlan[i] = glm::vec4(order[i]->outline ? float(hullOutlineLayer(order[i]->outline) + 1) : 0.0f, 0.0f, 0.0f, 0.0f);
    }
    if (renew || m_hullOutlineLayers.size() != layers || !m_hullOutlines) uploadHullOutlines();
    u.hullCount = glm::vec4(float(count), 0.0f, 0.0f, 0.0f);
    return int(count);
}

void WaterPass::uploadUniforms(FrameContext& frame, const CameraView& camera, const WaterView& water) {
    const RenderDef& def = frame.def;
    WaterUniforms u{};
    for (int i = 0; i < 4; ++i) u.corner[i] = m_grid.corner[size_t(i)];
    const bool layers = water.cascades > 0 && water.displacement && water.slopes;
    const int cascades = layers ? water.cascades : 1;
    for (int c = 0; c < 4; ++c) u.cascadeSize[c] = layers ? water.cascadeSize[size_t(c)] : 1.0f;
    for (int c = 0; c < 4; ++c) u.cascadeSlopeVariance[c] = layers ? water.cascadeSlopeVariance[size_t(c)] : 0.0f;
    u.glitterParams = glm::vec4(water.seaSlopeVariance, water.windSpeed, 0.0f, 0.0f);
    u.farFade = glm::vec4(def.far_fade ? 1.0f : 0.0f, water.whitecapJacobian, water.whitecapSigma, water.windAngle);
    u.crest = glm::vec4(CREST_SHARE * m_crestBound, def.subsurface, camera.projection[1][1], 0.0f);
    for (int c = 0; c < 4 && layers && def.far_fade; ++c) {
        u.cascadeFadeEnd[c] = def.tile_fade * water.cascadeSize[size_t(c)];
        u.cascadeFade[c] = TILE_FADE_START * u.cascadeFadeEnd[c];
    }
    const int waves = std::min(int(water.gerstner.size()), MAX_GERSTNER_WAVES);
    for (int m = 0; m < waves; ++m) u.gerstner[m] = water.gerstner[size_t(m)];
    u.waterParams = glm::vec4(water.lambda, water.gravity, float(waves), 0.5f * m_grid.minW);  // the clamp only guards rounding
    u.gridParams = glm::vec4(float(m_gridResolution), GRID_REACH * camera.farM, float(cascades), float(layers ? water.resolution : 1));
    m_layers.upload(water, layers, def.foam, u);
    const int hulls = def.hull_clip ? uploadHullClips(water, camera, u) : 0;
    m_variant = {.cascades = layers ? cascades : 0,
                 .ripples = u.rippleParams.w > 0.0f,
                 .foamMap = u.foamParams.w > 0.0f,
                 .underwater = frame.state.underwater,
                 .waterline = frame.state.waterline,
                 .exactFresnel = def.fresnel == Fresnel::Exact,
                 .clouds = frame.sky.cloud_cover > 0.0f,
                 .reflections = def.reflections,
                 .refractions = def.refractions,
                 .foam = def.foam,
                 .fullQuality = def.water_full_quality,
                 .hullClip = hulls > 0,
                 .hullDepthSamples = hulls > 0 && frame.state.antialias == Antialias::Msaa4 ? MSAA_SAMPLES : 1};
    glNamedBufferSubData(m_uniforms.id(), 0, sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, WATER_BLOCK, m_uniforms.id());
}

void WaterPass::prepare(FrameContext& frame, const CameraView& camera, const WaterView& water) {
    const SurfaceBounds bounds = displacementBounds(water);
    m_grid = projectedGridCorners(camera.projection * camera.view, camera.position, bounds);
    m_crestBound = bounds.up;
    frame.state.waterVisible = m_grid.visible;
    // Auto: a grid row per 3 px of internal height on a GPU, per 12 px on a software rasteriser,
    // within [32, 512]. A software rasteriser shades vertices on one thread, and it shades a 4×4
    // block of pixels once for every triangle that touches it (docs/frame.md).
    const int autoCells = std::clamp(frame.state.internal.y / (isSoftwareRenderer() ? 12 : 3), 32, 512);
    const int resolution = frame.def.grid_resolution > 0 ? frame.def.grid_resolution : autoCells;  // [16, 2048]: render_def.h
    if (m_gridResolution != resolution) buildGrid(resolution);
    uploadUniforms(frame, camera, water);
}

// The hull clip drops a water fragment only where the opaque scene behind it is the hull's
// (common_hull_clip.glsl), so the water reads the depth the objects left, copied out of the
// frame's own depth buffer (which the water pass tests and writes): straight from the read
// framebuffer when single-sampled (any depth format converts), by a blit of the samples in msaa4.
void WaterPass::copySceneDepth(const FrameContext& frame, GLuint frameFramebuffer) {
    const glm::ivec2 size = frame.state.internal;
    const int samples = m_variant.hullDepthSamples;
    if (m_sceneDepthSize != size || m_sceneDepthSamples != samples) {
        GLuint id;
        glCreateTextures(samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, 1, &id);
        glObjectLabel(GL_TEXTURE, id, -1, "hull clip: scene depth");
        if (samples > 1) {
            glTextureStorage2DMultisample(id, samples, GL_DEPTH_COMPONENT32F, size.x, size.y, GL_TRUE);
        } else {
            glTextureStorage2D(id, 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
            glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        m_sceneDepth = Texture(id);
        GLuint fbo;
        glCreateFramebuffers(1, &fbo);
        glObjectLabel(GL_FRAMEBUFFER, fbo, -1, "hull clip: scene depth");
        glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, id, 0);
        glNamedFramebufferDrawBuffer(fbo, GL_NONE);
        glNamedFramebufferReadBuffer(fbo, GL_NONE);
        m_sceneDepthFramebuffer = Framebuffer(fbo);
        m_sceneDepthSize = size;
        m_sceneDepthSamples = samples;
    }
    if (samples > 1)
        glBlitNamedFramebuffer(frameFramebuffer, m_sceneDepthFramebuffer.id(), 0, 0, size.x, size.y, 0, 0, size.x, size.y,
                               GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    else
        glCopyTextureSubImage2D(m_sceneDepth.id(), 0, 0, 0, 0, 0, size.x, size.y);  // the bound read framebuffer's depth
    glBindTextureUnit(SCENE_DEPTH_UNIT, m_sceneDepth.id());
    if (!m_hullOutlines) uploadHullOutlines();
    glBindTextureUnit(HULL_OUTLINE_UNIT, m_hullOutlines.id());
}

void WaterPass::waterPass(FrameContext& frame, const SkyPass& sky, const SurfacePasses& surfaces, GLuint frameFramebuffer) {
    if (!m_grid.visible) return;
    const PassScope scope(frame, WATER_PASS);
    if (m_variant.hullClip) copySceneDepth(frame, frameFramebuffer);
    glBindTextureUnit(SKY_UNIT, sky.cube().id());
    glBindTextureUnit(REFLECTION_UNIT, surfaces.reflection().color.id());
    glBindTextureUnit(REFRACTION_UNIT, surfaces.refraction().color.id());
    glBindTextureUnit(DETAIL_UNIT, m_detail.detailMap().id());
    glBindTextureUnit(FOAM_PATTERN_UNIT, m_detail.foamPattern().id());
    glBindTextureUnit(REFLECTION_DEPTH_UNIT, surfaces.reflection().depth.id());
    // A software rasteriser filters the ocean's slopes, the detail map and the foam pattern from
    // their nearest mip only: bilinear, not trilinear (full quality keeps trilinear).
    const GLuint mipSampler = isSoftwareRenderer() && !frame.def.water_full_quality ? m_detail.nearestMipSampler().id() : 0;
    for (GLuint unit : {SLOPES_UNIT, DETAIL_UNIT, FOAM_PATTERN_UNIT}) glBindSampler(unit, mipSampler);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const std::string defines = m_variant.defines();
    auto program = m_programs.find(defines);
    if (program == m_programs.end())
        program = m_programs.emplace(defines, loadProgram("water_surface", {"water_surface.vert", "water_surface.frag"}, defines)).first;
    glUseProgram(program->second.id());
    glBindVertexArray(m_gridVao.id());
    glDrawElements(GL_TRIANGLES, m_gridIndexCount, GL_UNSIGNED_INT, nullptr);
    // The targets are drawn into again next frame: never leave them bound for sampling.
    for (GLuint unit : {REFLECTION_UNIT, REFRACTION_UNIT, REFLECTION_DEPTH_UNIT, SCENE_DEPTH_UNIT, HULL_OUTLINE_UNIT}) glBindTextureUnit(unit, 0);
    for (GLuint unit : {SLOPES_UNIT, DETAIL_UNIT, FOAM_PATTERN_UNIT}) glBindSampler(unit, 0);
}

} // namespace ob::gfx
