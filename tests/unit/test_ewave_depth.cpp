// Finite depth in the dispersive ripple field (docs/ewave.md, "Depth"): a travelling wave
// cos(kx − ωt) runs at the phase speed of ω² = (g·k + (σ/ρ)·k³)·tanh(k·d) (Lamb §228, with
// capillarity), the formula written out here, not the field's. Measured from the mode's phase
// over many steps, so a slip of 1e-6 per step would show.
#include "interaction/ewave/ewave_field.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using ob::interaction::EWaveField;
using ob::interaction::EWaveMedium;
using ob::interaction::RippleBoundary;

namespace {

constexpr double PI = std::numbers::pi;
// A default [environment]: g, σ/ρ (its floats, as the field gets them).
const double G = double(9.81f), CAPILLARITY = double(0.074f) / double(1025.0f);

double omegaAt(double k, double depth) { return std::sqrt((G * k + CAPILLARITY * k * k * k) * std::tanh(k * depth)); }

// Phase of the mode m along x: atan2(Σh·sin kx, Σh·cos kx), so h = cos(kx − φ) gives φ.
double phaseOf(const EWaveField& f, int m) {
    double s = 0.0, c = 0.0;
    for (int z = 0; z < f.rows(); ++z)
        for (int x = 0; x < f.cols(); ++x) {
            const double h = f.heightState()[size_t(z) * size_t(f.cols()) + size_t(x)], a = 2.0 * PI * m * x / f.cols();
            s += h * std::sin(a);
            c += h * std::cos(a);
        }
    return std::atan2(s, c);
}

} // namespace

TEST_CASE("ewave: at depth d a wave cos(kx − ωt) runs at the phase speed of ω² = (g·k + (σ/ρ)·k³)·tanh(k·d)",
          "[ewave][depth]") {
    const int n = 64, m = 4;
    const float cell = 0.25f, dt = 1.0f / 60.0f;
    const double k = 2.0 * PI * m / (n * double(cell));  // 1.57 rad/m: 4 m waves
    for (double kd : {0.1, 0.5, 1.0, 2.0, 5.0}) {
        const double depth = kd / k, w = omegaAt(k, depth);
        EWaveField f(n, n, cell, RippleBoundary::Periodic);
        f.setMedium({G, CAPILLARITY, depth, 0.0});
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) {
                const double a = k * x * double(cell);
                f.editHeight()[size_t(z) * n + size_t(x)] = std::cos(a);
                f.editVelocity()[size_t(z) * n + size_t(x)] = w * std::sin(a);  // ∂/∂t cos(kx − ωt) at t = 0
            }
        // Unwrapped phase over 3,000 steps (50 s; the phase advances < π a step).
        double phase = 0.0, last = phaseOf(f, m);
        const int steps = 3000;
        for (int s = 0; s < steps; ++s) {
            f.step(dt);
            const double now = phaseOf(f, m);
            phase += std::remainder(now - last, 2.0 * PI);
            last = now;
        }
        const double t = steps * double(dt), speed = phase / (k * t), theory = w / k;
        const double deep = std::sqrt(G / k + CAPILLARITY * k);
        INFO("k·d = " << kd << ": phase speed " << speed << " m/s, theory " << theory << " m/s (deep water " << deep << ")");
        CHECK(speed == Approx(theory).epsilon(1e-6));
    }
}

TEST_CASE("ewave: depth 0 is deep water, and the medium takes [environment]'s viscosity", "[ewave][depth]") {
    const EWaveMedium deep = EWaveMedium::of({});
    CHECK(deep.depth == 0.0);
    CHECK(deep.viscosity == Approx(1e-6));
    for (double k : {0.01, 1.0, 100.0}) CHECK(deep.omega(k) == Approx(std::sqrt(G * k + CAPILLARITY * k * k * k)).epsilon(1e-12));
    const EWaveMedium shallow = EWaveMedium::of({}, 0.5);
    CHECK(shallow.omega(0.01) == Approx(0.01 * std::sqrt(G * 0.5)).epsilon(1e-4));  // long waves: c = √(g·d)
}
