// The frame read back at SMALL_SIZE, its log-average luminance and the adapting gain.
#include "gfx/auto_exposure.h"

#include "gfx/gl.h"

#include <algorithm>
#include <cmath>

namespace ob::gfx {

namespace {
constexpr glm::ivec2 SMALL_SIZE{96, 54};     // the read-back's size: 5184 samples of the frame
constexpr float DISPLAY_GAMMA = 2.2f;        // common_frame.glsl's encoding
constexpr float DISPLAY_TOP = 0.98f;         // the tone curve's flat top: brighter reads as this
constexpr float LUMINANCE_FLOOR = 1e-4f;     // black pixels do not take the log to −∞
constexpr float LONGEST_STEP_S = 0.25f;      // a stalled frame does not adapt in one jump
} // namespace

float AutoExposureLaw::target(float logAverage) {
    return std::clamp(std::pow(KEY / std::max(logAverage, LUMINANCE_FLOOR), STRENGTH), MIN_GAIN, MAX_GAIN);
}

float AutoExposureLaw::adapt(float gain, float target, float dt) {
    const float k = 1.0f - std::exp(-std::clamp(dt, 0.0f, LONGEST_STEP_S) / TIME_CONSTANT_S);
    return std::exp2(std::log2(gain) + (std::log2(target) - std::log2(gain)) * k);
}

// The curve y = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14) solved for x ≥ 0 (a quadratic).
float displayToExposed(float display) {
    const float y = std::min(std::pow(std::clamp(display, 0.0f, 1.0f), DISPLAY_GAMMA), DISPLAY_TOP);
    const float a = 2.51f - 2.43f * y, b = 0.03f - 0.59f * y, c = -0.14f * y;
    return (-b + std::sqrt(b * b - 4.0f * a * c)) / (2.0f * a);
}

float logAverageLuminance(std::span<const unsigned char> rgb, float exposure) {
    float table[256];
    for (int i = 0; i < 256; ++i) table[i] = displayToExposed(float(i) / 255.0f) / exposure;
    double sum = 0.0;
    const size_t count = rgb.size() / 3;
    for (size_t i = 0; i < count; ++i) {
        const float l = 0.2126f * table[rgb[3 * i]] + 0.7152f * table[rgb[3 * i + 1]] + 0.0722f * table[rgb[3 * i + 2]];
        sum += std::log(std::max(l, LUMINANCE_FLOOR));
    }
    return count ? float(std::exp(sum / double(count))) : 0.0f;
}

AutoExposure::AutoExposure() : m_pixels(size_t(SMALL_SIZE.x * SMALL_SIZE.y * 3)) {
    GLuint id;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, "auto exposure: the frame small");
    glTextureStorage2D(id, 1, GL_RGBA8, SMALL_SIZE.x, SMALL_SIZE.y);
    m_small = Texture(id);
    glCreateFramebuffers(1, &id);
    glObjectLabel(GL_FRAMEBUFFER, id, -1, "auto exposure");
    glNamedFramebufferTexture(id, GL_COLOR_ATTACHMENT0, m_small.id(), 0);
    m_framebuffer = Framebuffer(id);
}

void AutoExposure::reset() {
    m_gain = 1.0f;
    m_time = -1.0;
}

float AutoExposure::update(glm::ivec2 size, float exposure, double time) {
    glBlitNamedFramebuffer(0, m_framebuffer.id(), 0, 0, size.x, size.y, 0, 0, SMALL_SIZE.x, SMALL_SIZE.y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(m_small.id(), 0, GL_RGB, GL_UNSIGNED_BYTE, GLsizei(m_pixels.size()), m_pixels.data());
    const float target = AutoExposureLaw::target(logAverageLuminance(m_pixels, exposure * m_gain) * exposure);
    const float dt = m_time < 0.0 ? 0.0f : float(time - m_time);
    m_time = time;
    m_gain = AutoExposureLaw::adapt(m_gain, target, dt);
    return m_gain;
}

} // namespace ob::gfx
