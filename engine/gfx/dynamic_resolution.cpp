// Dynamic resolution: windows of frame times, a median, a sqrt step, a dead band.
#include "gfx/dynamic_resolution.h"

#include <algorithm>
#include <cmath>

namespace ob::gfx {

DynamicResolution::DynamicResolution(double targetFps, float startScale)
    : m_target(1.0 / targetFps), m_scale(std::clamp(startScale, MIN_SCALE, MAX_SCALE)) {}

float DynamicResolution::update(double frameSeconds) {
    if (m_skipNext) {
        m_skipNext = false;
        return m_scale;
    }
    m_window.push_back(frameSeconds);
    m_windowSeconds += frameSeconds;
    const bool closed = m_window.size() >= 6 || (m_window.size() >= 2 && m_windowSeconds >= WINDOW_S);
    if (!closed) return m_scale;
    std::vector<double> sorted = m_window;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    const double measured = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    m_window.clear();
    m_windowSeconds = 0.0;
    const double ratio = m_target / std::max(measured, 1e-6);
    const float lastScale = m_lastScale;
    const double lastTime = m_lastTime;
    m_lastScale = m_scale;
    m_lastTime = measured;
    if (ratio >= SLOW_BAND && (ratio <= FAST_BAND || m_scale >= MAX_SCALE)) return m_scale;
    // The pure-pixel step: the bound of any step (a fixed part only shortens it).
    const double pixels = double(m_scale) * std::sqrt(ratio);
    double wanted = ratio > 1.0 ? double(m_scale) * std::sqrt(0.5 * (1.0 + ratio)) : pixels;  // growing: half-way
    if (lastScale > 0.0f && std::abs(lastScale - m_scale) >= STEP) {
        const double s2 = double(m_scale) * m_scale, l2 = double(lastScale) * lastScale;
        const double b = (measured - lastTime) / (s2 - l2), a = measured - b * s2;
        const double goal = AIM * m_target - a;
        if (b > 0.0 && a >= 0.0 && goal > 0.0) wanted = std::sqrt(goal / b);
    }
    wanted = ratio > 1.0 ? std::min(wanted, pixels) : std::max(std::min(wanted, pixels), double(MIN_SCALE));
    float next = std::clamp(float(std::round(wanted / STEP) * STEP), MIN_SCALE, MAX_SCALE);
    if (next != m_scale) {
        m_scale = next;
        m_skipNext = true;
        ++m_changes;
    }
    return m_scale;
}

} // namespace ob::gfx
