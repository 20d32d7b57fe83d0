// Renderer passes and the screenshot read-back.
#include "gfx/renderer.h"

#include "core/error.h"
#include "gfx/shader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <glm/glm.hpp>
#include <stb_image_write.h>
#include <vector>

namespace ob::gfx {

constexpr GLuint FRAME_UBO_BINDING = 0;

Renderer::Renderer(const RenderDef& def)
    : m_def(def),
      m_skyProgram(loadProgram("sky", {"common_fullscreen.vert", "sky_background.frag"})),
      m_waterProgram(loadProgram("water_flat", {"common_fullscreen.vert", "water_flat.frag"})),
      m_emptyVao(createVertexArray("fullscreen triangle")),
      m_frameUniforms(createBuffer("frame uniforms", sizeof(FrameUniforms))) {}

void Renderer::render(const CameraView& camera, double time, glm::ivec2 size) {
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
    glBindVertexArray(m_emptyVao.id());

    // --- passes
    skyPass();
    waterPass();

    glBindVertexArray(0);
    m_gpuTimer.end();
}

void Renderer::skyPass() {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 1, -1, "sky");
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(m_skyProgram.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    glPopDebugGroup();
}

void Renderer::waterPass() {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 2, -1, "water");
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(m_waterProgram.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
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
