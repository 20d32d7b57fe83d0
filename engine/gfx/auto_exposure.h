// Exposure that adapts (render.auto_exposure, docs/look.md#exposure): the finished frame's
// log-average luminance, read back small, sets a gain on [render] exposure that follows it with
// a time constant of about a second, as an eye adapts; the radiance the passes compute stays
// physical, only the exposure before the tone curve moves.
#pragma once
#include "gfx/handles.h"

#include <glm/vec2.hpp>
#include <span>
#include <vector>

namespace ob::gfx {

/// The exposure gain's law, in one place for the renderer and the tests.
struct AutoExposureLaw {
    /// The log-average linear luminance the gain brings a frame to: the default sea's by day
    /// (config/scenes/default.toml, the play camera), so a sunlit sea keeps about gain 1.
    static constexpr float KEY = 0.30f;
    /// The share of a change in brightness (in stops) the gain takes back: an eye adapts
    /// partly, so a storm stays darker than a sunny day and a view under water dimmer than one above.
    static constexpr float STRENGTH = 2.0f / 3.0f;
    static constexpr float MIN_GAIN = 0.25f;  ///< −2 stops at most
    static constexpr float MAX_GAIN = 8.0f;   ///< +3 stops at most (a level view under water needs about 2–3)
    static constexpr float TIME_CONSTANT_S = 1.0f;
    /// The gain a frame of log-average luminance `logAverage` (radiance × [render] exposure) asks
    /// for: (KEY / logAverage)^STRENGTH, clamped.
    static float target(float logAverage);
    /// One step of the adaptation over dt seconds (in stops, so up and down take as long).
    static float adapt(float gain, float target, float dt);
};

/// Linear radiance (× exposure) of a display-encoded 8-bit value: the inverse of the
/// renderer's tone curve and encoding (shaders/common_frame.glsl), display values near white
/// taken as 0.98 (the curve's top is flat).
float displayToExposed(float display);

/// The log-average luminance of an RGB8 image (linear, Rec. 709 weights), inverted through
/// the display curve at `exposure`.
float logAverageLuminance(std::span<const unsigned char> rgb, float exposure);

/// Reads the framebuffer back small each frame and keeps the adapted gain.
class AutoExposure {
public:
    AutoExposure();
    /// After the frame is drawn into the default framebuffer (size px) at [render] `exposure`
    /// × gain(): measures it and steps the gain toward its target over the
    /// simulated time since the last call. Returns the gain for the next frame.
    float update(glm::ivec2 size, float exposure, double time);
    /// Back to gain 1 (auto exposure switched off).
    void reset();
    float gain() const { return m_gain; }

private:
    Framebuffer m_framebuffer;
    Texture m_small;
    std::vector<unsigned char> m_pixels;
    float m_gain = 1.0f;
    double m_time = -1.0;
};

} // namespace ob::gfx
