// The dispersive ripple field keeps its water (docs/ewave.md, "Volume"): a pressure (a moving
// source) and the absorbing sponge move water, never make or remove it, so Σh, the k = 0 mode,
// holds to the rounding of the sums that restore it. Measured here with compensated (Neumaier)
// summation in double, independently of the field's own plain sum.
#include "interaction/ewave/ewave_field.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

using ob::interaction::EWaveField;
using ob::interaction::EWaveMedium;
using ob::interaction::RippleBoundary;

namespace {

// Σx, Σ|x| and Σx² of h, Neumaier-compensated (error about u·Σ|x|, independent of n).
struct Sums {
    double sum = 0.0, abs = 0.0, squares = 0.0;
};
Sums sums(const EWaveField& f) {
    double s = 0.0, c = 0.0;
    Sums out;
    for (double x : f.heightState()) {
        const double t = s + x;
        c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
        s = t;
        out.abs += std::abs(x);
        out.squares += x * x;
    }
    out.sum = s + c;
    return out;
}

// A Gaussian bump of h (so the volume is not 0 to begin with).
void bump(EWaveField& f, double cx, double cz, double sigma, double height) {
    for (int z = 0; z < f.rows(); ++z)
        for (int x = 0; x < f.cols(); ++x)
            f.editHeight()[size_t(z) * size_t(f.cols()) + size_t(x)] =
                height * std::exp(-((x - cx) * (x - cx) + (z - cz) * (z - cz)) / (2.0 * sigma * sigma));
    f.syncHeight();
}

// Sources that move every step: two hulls pushing down on circles (their stamps have a mean of
// about −accel·dt·πR²/3 per step, which unchecked lowers the whole patch) and one pushing up.
void addMovingSources(EWaveField& f, int step, float dt) {
    const double t = step * double(dt), n = f.rows();
    const double a = 0.3 * n;
    f.addSource(float(0.5 * n + a * std::cos(0.4 * t)), float(0.5 * n + a * std::sin(0.4 * t)), 4.0f, -9.81f, dt);
    f.addSource(float(0.5 * n - 0.5 * a * std::cos(0.7 * t)), float(0.5 * n + 0.5 * a * std::sin(0.7 * t)), 3.0f, -6.0f, dt);
    f.addSource(float(0.25 * n + 0.1 * t), float(0.7 * n), 2.5f, 4.0f, dt);
}

} // namespace

// Periodic: nothing but rounding moves Σh. Scale: the RMS of h, the size of the values whose
// rounding the field's sums (and the float transforms' change) carry: a mean kept to 1e-12 of
// it is far below any wave (the max would be a laxer scale, ~3–5× the RMS here).
TEST_CASE("ewave: on a periodic field the mean of h is kept to 1e-12 of its RMS over 10,000 steps of moving sources",
          "[ewave][volume]") {
    EWaveField f(64, 64, 0.25f, RippleBoundary::Periodic);
    f.setMedium(EWaveMedium::of({}));  // the water's own viscosity, as the solver has it
    f.setDamping(0.5f, 0.0f);          // and a decay: the k = 0 mode must not decay with the waves
    bump(f, 20.0, 30.0, 3.0, 0.1);
    const double mean0 = sums(f).sum / (64.0 * 64.0);
    REQUIRE(mean0 > 1e-4);
    const float dt = 1.0f / 60.0f;
    double worst = 0.0, smallestRms = std::numeric_limits<double>::max();
    for (int s = 1; s <= 10000; ++s) {
        addMovingSources(f, s, dt);
        f.step(dt);
        if (s % 100 == 0) {
            const Sums m = sums(f);
            const double mean = m.sum / (64.0 * 64.0), rms = std::sqrt(m.squares / (64.0 * 64.0) - mean * mean);
            smallestRms = std::min(smallestRms, rms);
            worst = std::max(worst, std::abs(mean - mean0) / rms);
        }
    }
    INFO("largest |mean − mean0| / RMS(h − mean) over 10,000 steps: " << worst << " (mean0 " << mean0
                                                                     << " m, smallest RMS " << smallestRms << " m)");
    CHECK(smallestRms > 1e-3);  // the sources keep the field alive
    CHECK(worst <= 1e-12);
}

// Absorbing: the sponge relaxes h towards the mean level and the step puts back what it still
// moved. Bound: the field restores Σh from its plain double sum of n = rows·cols terms, whose
// error is at most γ_{n−1}·Σ|h| ≈ (n − 1)·u·Σ|h| (Higham, Accuracy and Stability, §4.2), and the
// uniform shift rounds each cell by at most u·|h_i|: (n·u + u)·Σ|h| per step, not accumulating
// (each step restores the same target). Doubled for the test's own sum. Without the
// restoration the sponge alone moves ~1e-3 of Σ|h| in a step here.
TEST_CASE("ewave: the absorbing border moves no water: Σh stays within the rounding bound of its sums over 6,000 steps",
          "[ewave][volume]") {
    const int n = 128;
    EWaveField f(n, n, 0.25f, RippleBoundary::Absorbing, 24);
    f.setMedium(EWaveMedium::of({}));
    bump(f, 40.0, 64.0, 4.0, 0.2);
    const double v0 = sums(f).sum;
    const double u = std::numeric_limits<double>::epsilon() / 2.0, cells = double(n) * n;
    const float dt = 1.0f / 60.0f;
    double worst = 0.0, bound = 0.0;
    for (int s = 1; s <= 6000; ++s) {
        if (s <= 3000) addMovingSources(f, s, dt);  // 50 s of sources, then 50 s of rings leaving
        f.step(dt);
        if (s % 50 == 0) {
            const Sums m = sums(f);
            bound = std::max(bound, 2.0 * (cells + 1.0) * u * m.abs);
            worst = std::max(worst, std::abs(m.sum - v0));
        }
    }
    INFO("largest |Σh − Σh0| " << worst << " m (cells) against the bound " << bound << "; Σh0 = " << v0);
    CHECK(worst <= bound);
    CHECK(std::abs(f.volume() - v0) <= bound);
}
