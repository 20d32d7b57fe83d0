// Dynamic resolution: the internal render scale follows the measured frame time so the frame
// rate holds a target, as games do on machines they were not tuned for.
//
// The law: the frame costs about a + b·s² (a: the fixed part, b·s²: the pixels at scale s on
// both axes). A window of frames at one scale gives its median time. With the last two
// windows at different scales, a and b follow (the secant) and the scale goes where
// a + b·s² is AIM × target. Without them (the first change, or a and b that make no sense)
// the step is s·sqrt(target / measured), the scale that would meet the target if every
// millisecond were pixels: with a fixed part it falls short, never past, the goal. Either
// way a step never goes beyond that pure-pixel scale, so the controller approaches from one
// side and does not overshoot into oscillation. Hysteresis: the median must miss the target
// by more than the dead band (slower than target/0.95, or faster than target/1.2 with room
// to grow) before the scale changes; the first frame after a change is not measured (it
// may still carry the old size's work). A window closes after 0.25 s of frames (at least
// two, at most six): a load step is answered within about half a second at any frame rate
// above 4 fps, and the target met within about a second.
#pragma once
#include <vector>

namespace ob::gfx {

class DynamicResolution {
public:
    static constexpr float MIN_SCALE = 0.25f;  ///< the lowest internal scale (per axis)
    static constexpr float MAX_SCALE = 1.0f;
    static constexpr float STEP = 1.0f / 64.0f;   ///< scales are multiples of this (no tiny changes)
    static constexpr double SLOW_BAND = 0.95;     ///< target/measured below this: too slow, scale down
    static constexpr double FAST_BAND = 1.2;      ///< target/measured above this: room, scale up
    static constexpr double WINDOW_S = 0.25;      ///< a window's length (s of frames)
    static constexpr double AIM = 0.97;           ///< the secant aims at this fraction of the target time

    /// `targetFps` > 0; starts at `startScale`.
    explicit DynamicResolution(double targetFps, float startScale = MAX_SCALE);
    /// One finished frame's wall time (s), rendered at scale(); returns the scale for the
    /// next frame.
    float update(double frameSeconds);
    float scale() const { return m_scale; }
    double targetSeconds() const { return m_target; }
    /// Scale changes so far.
    int changes() const { return m_changes; }

private:
    double m_target;
    float m_scale;
    bool m_skipNext = false;
    std::vector<double> m_window;
    double m_windowSeconds = 0.0;
    int m_changes = 0;
    float m_lastScale = -1.0f;  // the previous window's scale and median time (s)
    double m_lastTime = 0.0;
};

} // namespace ob::gfx
