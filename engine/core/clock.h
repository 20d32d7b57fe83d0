// Injected time sources: the frame loop never reads the wall clock itself, so a headless
// run of N frames is deterministic.
#pragma once
#include <chrono>

namespace ob {

/// A source of time in seconds since its start.
class Clock {
public:
    virtual ~Clock() = default;
    /// Seconds since the clock started; called once per frame.
    virtual double now() = 0;
};

/// Wall-clock time (interactive play).
class SteadyClock final : public Clock {
public:
    double now() override {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    }

private:
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

/// Advances by a fixed interval at every call (scripted and headless runs, tests). The
/// first call returns one interval: the first frame covers [0, interval] of the run, so its
/// steps reach the clock times a run of one step a frame reaches (input stamped t acts in
/// the step that holds t, whatever the frame's length).
class FixedStepClock final : public Clock {
public:
    /// `frameSeconds`: simulated time per frame (s), > 0; `end` > 0: the clock stops there
    /// (s), so the last frame of a run of a set number of steps runs only those left.
    explicit FixedStepClock(double frameSeconds, double end = 0.0) : m_frameSeconds(frameSeconds), m_end(end) {}
    double now() override {
        const double t = double(++m_frames) * m_frameSeconds;
        return m_end > 0.0 && t > m_end ? m_end : t;
    }

private:
    double m_frameSeconds;
    double m_end;
    long long m_frames = 0;
};

} // namespace ob
