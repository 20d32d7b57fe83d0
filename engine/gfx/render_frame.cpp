// The views' uniforms, the pass timers and the pass span.
#include "gfx/render_frame.h"
#include "gfx/clouds.h"
#include "gfx/sun.h"

#include <algorithm>
#include <glm/glm.hpp>
#include <iterator>

namespace ob::gfx {

namespace {
const char* const PASS_NAMES[] = {"sky_bake", "reflection", "refraction", "opaque", "water", "sky", "splash", "post"};
static_assert(std::size(PASS_NAMES) == PASS_COUNT);
// The direct sunlight on a surface facing the sun, × render.sun_color, relative to the sky's
// radiance: the objects' and the foam's Lambert light (frame.sunLight.w).
constexpr float SUNLIT_SURFACE = 1.4f;
} // namespace

glm::vec4 nearPlaneWaterHeight(const CameraView& camera) {
    const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
    const auto height = [&](float x, float y) {
        const glm::vec4 p = inverse * glm::vec4(x, y, -1.0f, 1.0f);
        const glm::vec3 q = glm::vec3(p) / p.w;
        const glm::vec2 along = glm::vec2(q.x, q.z) - glm::vec2(camera.position.x, camera.position.z);
        return q.y - (camera.waterHeight + glm::dot(camera.waterSlope, along));
    };
    const float c = height(0.0f, 0.0f);
    return {height(1.0f, 0.0f) - c, height(0.0f, 1.0f) - c, c, std::max(camera.waterHeight - camera.position.y, 0.0f)};
}

int mipLevels(int size) {
    int levels = 1;
    while (size > 1) size /= 2, ++levels;
    return levels;
}

FrameViews::FrameViews()
    : m_buffers{createBuffer("frame uniforms: camera", sizeof(FrameUniforms)),
                createBuffer("frame uniforms: reflection", sizeof(FrameUniforms)),
                createBuffer("frame uniforms: refraction", sizeof(FrameUniforms))} {}

// The object shader cuts and mirrors at the composite surface under each vertex, so every
// view's view-projection stays the camera's.
void FrameViews::update(const RenderDef& def, const SkyDef& sky, const FrameState& frame, const CameraView& camera, double time,
                        glm::ivec2 reflectionSize, glm::ivec2 refractionSize, int skyMips) {
    FrameUniforms u{};
    u.sunDirectionFresnel = glm::vec4(sunDirection(def), def.fresnel == Fresnel::Exact ? 1.0f : 0.0f);
    u.waterColorExposure = glm::vec4(def.water_color, def.exposure * frame.exposureGain);
    u.sky = glm::vec4(sky.cloud_cover, frame.cloudDrift, sky.cloud_height);
    u.sunLight = glm::vec4(def.sun_color, SUNLIT_SURFACE);
    // whether a cloud stands before the sun now: the sky's own noise on the sun's ray
    u.sunCloud = glm::vec4(cloudBeamLoss(sky, frame.cloudDrift, sunDirection(def)), 0.0f, 0.0f, 0.0f);
    u.depthParams = glm::vec4(camera.nearM, camera.farM, def.water_clarity, float(skyMips));
    u.shading = glm::vec4(def.dudv_strength, def.normal_distortion, def.glitter, def.light_shafts);
    u.switches = glm::vec4(def.reflections ? 1.0f : 0.0f, def.refractions ? 1.0f : 0.0f, def.foam ? 1.0f : 0.0f,
                           def.dither ? 1.0f : 0.0f);
    u.waterline = frame.nearPlaneHeight;
    const float underwater = frame.underwater ? 1.0f : 0.0f;

    const glm::mat4 viewProjection = camera.projection * camera.view;
    u.viewProjection = viewProjection;
    u.inverseViewProjection = glm::inverse(viewProjection);
    u.cameraPositionTime = glm::vec4(camera.position, float(time));
    u.viewport = glm::vec4(float(frame.internal.x), float(frame.internal.y), frame.antialias == Antialias::Fxaa ? 2.0f : 0.0f, underwater);
    u.surfaceClip = glm::vec4(0.0f);
    glNamedBufferSubData(m_buffers[MAIN_VIEW].id(), 0, sizeof u, &u);

    // The mirrored eye (about the mean level) lights the mirrored objects.
    u.cameraPositionTime = glm::vec4(camera.position.x, 2.0f * WATER_LEVEL - camera.position.y, camera.position.z, float(time));
    u.viewport = glm::vec4(glm::vec2(reflectionSize), 1.0f, underwater);
    u.surfaceClip = glm::vec4(1.0f, REFLECTION_OVERLAP, 1.0f, 0.0f);
    glNamedBufferSubData(m_buffers[REFLECTION_VIEW].id(), 0, sizeof u, &u);

    u.cameraPositionTime = glm::vec4(camera.position, float(time));
    u.viewport = glm::vec4(glm::vec2(refractionSize), 3.0f, underwater);
    u.surfaceClip = glm::vec4(-1.0f, REFRACTION_OVERLAP, 0.0f, 0.0f);
    glNamedBufferSubData(m_buffers[REFRACTION_VIEW].id(), 0, sizeof u, &u);
}

void FrameViews::bind(View view) const { glBindBufferBase(GL_UNIFORM_BUFFER, glsl::FRAME_BLOCK, m_buffers[view].id()); }

PassTimers::PassTimers() {
    for (const char* name : PASS_NAMES) m_timers.emplace_back(name);
}

PassTimes PassTimers::take() {
    PassTimes times;
    for (int p = 0; p < PASS_COUNT; ++p) {
        double ms = m_timers[size_t(p)].takeResultMs();
        if (ms >= 0.0) times.emplace_back(PASS_NAMES[p], ms);
    }
    return times;
}

PassScope::PassScope(FrameContext& frame, Pass pass) : m_timer(frame.timers[pass]) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, GLuint(pass), -1, PASS_NAMES[pass]);
    m_timer.begin();
}

PassScope::~PassScope() {
    m_timer.end();
    glPopDebugGroup();
}

} // namespace ob::gfx
