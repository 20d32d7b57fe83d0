// The frame: its facts and views set once, then the passes in order; the screenshot read-back.
#include "gfx/renderer.h"

#include "core/error.h"
#include "core/file_write.h"
#include "core/log.h"
#include "gfx/gl.h"

#include <cmath>
#include <cstring>
#include <glm/glm.hpp>
#include <stb_image_write.h>
#include <utility>

namespace ob::gfx {

Antialias antialiasMode(Antialias key, bool softwareRenderer) {
    if (key != Antialias::Auto) return key;
    return softwareRenderer ? Antialias::Fxaa : Antialias::Msaa4;
}

namespace {
glm::ivec2 scaledSize(glm::ivec2 size, float scale) { return glm::max(glm::ivec2(glm::vec2(size) * scale + 0.5f), glm::ivec2(1)); }
} // namespace

Renderer::Renderer(const RenderDef& def) : m_frame(def) {}

ProgramList Renderer::programs() const {
    ProgramList list;
    m_sky.listPrograms(list);
    m_water.listPrograms(list);
    m_objects.listPrograms(list);
    m_splash.listPrograms(list);
    m_post.listPrograms(list);
    return list;
}

// The frame's facts (mode, sizes, the eye's side), the targets sized for them, the views' uniforms.
bool Renderer::autoExposureOn() const {
    const AutoExposureMode mode = m_frame.def.auto_exposure;
    return mode == AutoExposureMode::On || (mode == AutoExposureMode::Auto && m_autoExposureDefault);
}

void Renderer::beginFrame(const CameraView& camera, double time, glm::ivec2 size, float windAngle) {
    FrameState& state = m_frame.state;
    const RenderDef& def = m_frame.def;
    // The eye's side: the near plane's four corners against the water's tangent plane at the eye.
    state.nearPlaneHeight = nearPlaneWaterHeight(camera);
    int below = 0;
    for (float x : {-1.0f, 1.0f})
        for (float y : {-1.0f, 1.0f}) below += glm::dot(glm::vec3(state.nearPlaneHeight), glm::vec3(x, y, 1.0f)) < 0.0f;
    state.underwater = below == 4;
    state.waterline = below > 0 && below < 4;
    state.antialias = antialiasMode(def.antialias, isSoftwareRenderer());
    if (state.antialias == Antialias::Msaa4 && !m_post.msaaSupported()) {
        static bool warned = false;
        if (!std::exchange(warned, true)) logWarn("render.antialias: this GL driver has no 4× multisampled float targets; using fxaa");
        state.antialias = Antialias::Fxaa;
    }
    state.internal = def.resolution_scale < 1.0f ? scaledSize(size, def.resolution_scale) : size;
    m_surfaces.resize(m_frame, state.internal);
    m_post.resize(m_frame, state.internal);
    // The clouds drift downwind with the wind aloft; the exposure gain is the last frame's adaptation.
    state.cloudDrift = float(time) * m_frame.sky.wind_aloft * glm::vec2(std::cos(windAngle), std::sin(windAngle));
    if (!autoExposureOn()) m_exposure.reset();
    state.exposureGain = m_exposure.gain();
    m_frame.views.update(def, m_frame.sky, state, camera, time, m_surfaces.reflection().size, m_surfaces.refraction().size, SkyPass::mipCount());
    // Pixels per radian at the centre of each view's target (the far twins' choice).
    state.eye = camera.position;
    state.pixelsPerRadian[MAIN_VIEW] = 0.5f * float(state.internal.y) * camera.projection[1][1];
    state.pixelsPerRadian[REFLECTION_VIEW] = state.pixelsPerRadian[REFRACTION_VIEW] =
        0.5f * float(m_surfaces.reflection().size.y) * camera.projection[1][1];
}

void Renderer::render(const CameraView& camera, const WaterView& water, const std::vector<ObjectDraw>& objects, double time,
                      glm::ivec2 size, std::span<const SplashDrop> drops) {
    beginFrame(camera, time, size, water.windAngle);
    const FrameState& state = m_frame.state;
    const RenderDef& def = m_frame.def;

    // --- passes
    m_sky.bakePass(m_frame);
    m_water.prepare(m_frame, camera, water);
    m_splash.upload(m_frame, drops, camera);
    if (def.reflections && !state.underwater) m_surfaces.reflectionPass(m_frame, m_objects, m_splash, objects);
    if (def.refractions && !state.underwater) m_surfaces.refractionPass(m_frame, m_objects, objects);
    const GLuint frameFramebuffer = m_post.frameFramebuffer(m_frame);
    glBindFramebuffer(GL_FRAMEBUFFER, frameFramebuffer);
    glViewport(0, 0, state.internal.x, state.internal.y);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    m_frame.views.bind(MAIN_VIEW);
    m_objects.opaquePass(m_frame, objects);
    m_water.waterPass(m_frame, m_sky, m_surfaces, frameFramebuffer);
    m_sky.skyPass(m_frame);              // it shades only the pixels nothing else covered
    m_splash.splashPass(m_frame);        // after the sky: the sprites write no depth
    if (!m_post.direct(m_frame)) m_post.postPass(m_frame, size);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (autoExposureOn()) m_exposure.update(size, def.exposure, time);
    glBindVertexArray(0);
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
