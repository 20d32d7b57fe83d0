// The dynamic-resolution controller against a synthetic frame: cost a + b·s² (fixed work and
// pixels), with load steps, ramps and noise. It must settle where the frame meets the target
// (or at a bound), within the stated time, and not oscillate.
#include "gfx/dynamic_resolution.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <random>

using ob::gfx::DynamicResolution;

namespace {

struct Trace {
    std::vector<double> time, scale, frame;
    int changes = 0;
};

// Runs `seconds` of frames; cost(t, s) is the frame time at clock time t and scale s.
Trace simulate(DynamicResolution& dr, double seconds, const std::function<double(double, float)>& cost, double t0 = 0.0) {
    Trace tr;
    double t = t0;
    const int before = dr.changes();
    while (t < t0 + seconds) {
        const double frame = cost(t, dr.scale());
        t += frame;
        tr.time.push_back(t);
        tr.frame.push_back(frame);
        dr.update(frame);
        tr.scale.push_back(dr.scale());
    }
    tr.changes = dr.changes() - before;
    return tr;
}

// The scale that meets the target exactly under cost a + b·s², clamped to the bounds.
float idealScale(double target, double a, double b) {
    const double s2 = (target - a) / b;
    return float(std::clamp(s2 > 0 ? std::sqrt(s2) : 0.0, double(DynamicResolution::MIN_SCALE), 1.0));
}

} // namespace

TEST_CASE("dynamic resolution: from full scale on a slow machine it settles within a second where the frame meets 30 fps",
          "[dynres]") {
    // llvmpipe-like: 25 ms of fixed work, 70 ms of pixels at scale 1 (10.5 fps at full size).
    const double a = 0.025, b = 0.070, target = 1.0 / 30.0;
    DynamicResolution dr(30.0);
    Trace tr = simulate(dr, 10.0, [&](double, float s) { return a + b * s * s; });
    const float ideal = idealScale(target, a, b);  // 0.34
    // Settled by 1 s of clock: near the ideal, meeting the target.
    for (size_t i = 0; i < tr.time.size(); ++i)
        if (tr.time[i] > 1.0) {
            INFO("t = " << tr.time[i] << " s, scale " << tr.scale[i]);
            CHECK(tr.frame[i] <= target / DynamicResolution::SLOW_BAND + 1e-9);
            CHECK(tr.scale[i] <= ideal + 0.01f);
            CHECK(tr.scale[i] >= ideal * 0.85f);
        }
    CHECK(tr.changes <= 3);  // a step or two down, then none
}

TEST_CASE("dynamic resolution: a load step down and back up is followed within half a second each way", "[dynres]") {
    const double target = 1.0 / 30.0;
    DynamicResolution dr(30.0);
    // 4 s light (the full frame fits), 4 s heavy (pixels 4× dearer), 4 s light again.
    auto cost = [&](double t, float s) {
        const double b = (t >= 4.0 && t < 8.0) ? 0.080 : 0.020;
        return 0.004 + b * s * s;
    };
    Trace tr = simulate(dr, 12.0, cost);
    auto scaleAt = [&](double t) {
        size_t i = 0;
        while (i + 1 < tr.time.size() && tr.time[i] < t) ++i;
        return tr.scale[i];
    };
    CHECK(scaleAt(3.9) == 1.0f);
    // Heavy: the ideal is sqrt((1/30 - 0.004)/0.08) = 0.606; answered within 0.5 s of the
    // step, met within 1 s.
    const float heavy = idealScale(target, 0.004, 0.080);
    CHECK(scaleAt(4.5) < 0.7f);
    CHECK(scaleAt(5.0) <= heavy * 1.02f);
    CHECK(scaleAt(5.0) >= heavy * 0.85f);
    // Light again: back to full scale within a second (growth aims half-way each window).
    CHECK(scaleAt(9.0) == 1.0f);
}

TEST_CASE("dynamic resolution: ±15 % frame noise around a settled scale changes it rarely", "[dynres]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(0.85, 1.15);
    const double a = 0.010, b = 0.060;
    DynamicResolution dr(30.0);
    simulate(dr, 3.0, [&](double, float s) { return (a + b * s * s) * noise(rng); });  // settle
    Trace tr = simulate(dr, 30.0, [&](double, float s) { return (a + b * s * s) * noise(rng); }, 3.0);
    INFO("changes in 30 s: " << tr.changes);
    CHECK(tr.changes <= 6);  // at most one change every 5 s on average
    for (size_t i = 1; i < tr.scale.size(); ++i) CHECK(std::abs(tr.scale[i] - tr.scale[i - 1]) <= 0.2f);
}

TEST_CASE("dynamic resolution: a slow ramp of load is tracked, never more than half a second late", "[dynres]") {
    const double target = 1.0 / 30.0;
    DynamicResolution dr(30.0);
    // Pixels get dearer from 20 ms to 120 ms over 20 s.
    auto bAt = [](double t) { return 0.020 + 0.100 * std::clamp(t / 20.0, 0.0, 1.0); };
    Trace tr = simulate(dr, 20.0, [&](double t, float s) { return 0.004 + bAt(t) * s * s; });
    // Half a second after any time, the scale is at most what met the target then.
    for (size_t i = 0; i < tr.time.size(); ++i) {
        if (tr.time[i] < 2.0) continue;
        const float allowed = idealScale(target, 0.004, bAt(tr.time[i] - 0.5));
        INFO("t = " << tr.time[i]);
        CHECK(tr.scale[i] <= allowed + 0.02f);
    }
    CHECK(tr.scale.back() >= DynamicResolution::MIN_SCALE);
}

TEST_CASE("dynamic resolution: a machine too slow even at the lowest scale stays there, one too fast at full scale", "[dynres]") {
    DynamicResolution slow(30.0), fast(30.0, 0.5f);
    simulate(slow, 5.0, [](double, float s) { return 0.080 + 0.050 * s * s; });
    simulate(fast, 5.0, [](double, float s) { return 0.002 + 0.005 * s * s; });
    CHECK(slow.scale() == DynamicResolution::MIN_SCALE);
    CHECK(fast.scale() == 1.0f);
}
