// Kelvin wake of the dispersive ripple model (docs/references.md#dispersive-ripples): a bounding sphere moving at constant
// speed U over still deep water, stamped by Table 2 (planStamp) as an ewave pressure source,
// leaves a wake whose outer envelope makes arcsin(1/3) = 19.47° with its track, for any U; over
// water of depth d it widens to Havelock's (1908) angle as U/√(g·d) nears 1.
#include "interaction/ewave/ewave_field.h"
#include "interaction/ewave/ewave_solver.h"
#include "interaction/obstruction.h"
#include "interaction/sphere_stamp.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace ob::interaction;

namespace {

// k0 of the transverse waves: g·k·tanh(k·d) = U²·k² (deep, d = 0: k0 = g/U²), by bisection.
double transverseWavenumber(double speed, double depth) {
    const double deep = 9.81 / (speed * speed);
    if (depth <= 0.0) return deep;
    double lo = 1e-9, hi = deep;  // tanh(k·d)·g/(U²·k) falls from g·d/U² (> 1 below Fd = 1) through 1
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (9.81 * std::tanh(mid * depth) > speed * speed * mid ? lo : hi) = mid;
    }
    return hi;
}

struct Wake {
    double angleDeg = 0.0;  // fitted envelope angle
    int samples = 0;        // cross-sections used
};

// Runs a sphere (radius two cells, half under water, SD down, SHR 1, AF 0) along +x at speed U
// for `seconds` over a rows × cols field of `cell` m cells (absorbing border, no damping)
// stepped at `hz`, then measures the wake's outer envelope. The sphere's push ramps up over the first 3 s
// (smoothstep), so the start's own ring does not blur the envelope.
//
// How the angle is measured: in the sphere's frame, for each distance d behind it, |h| is
// first smoothed along the track by a running maximum over one transverse wavelength
// λ = 2πU²/g (so the crests merge into an envelope); the envelope's edge on each side is the
// outermost lateral offset y where it still reaches a third of that cross-section's largest
// value (on the outer flank of the cusp waves' peak, which beyond the caustic falls off as an
// Airy tail: the caustic itself sits near 2/3 of the peak, a third a little outside it),
// and y(d) (both sides averaged) is fitted by a straight line y = a + b·d over
// 1.5λ <= d <= min(0.75·U·t, dCap) (the wake formed after the start, inside the band-free
// part of the field). The angle is atan(b): the intercept a absorbs the source's size.
// `depth` m (0: deep water); the transverse wavelength λ is then 2π/k0 with
// g·k0·tanh(k0·d) = U²·k0² (the waves that keep pace with the sphere along its track).
// `hull` (m, semi-axes along and across the track; 0: none): a displacing hull's waterplane
// centred on the sphere, as EWaveSolver::step runs it (docs/ewave.md#hulls): no source acts
// inside it (maskHullSources) and after each step it holds its water at its hollow, `hollow` m
// deep on its keel line (ramped in with the push; ObstacleShape::hollowLevel).
Wake runWake(double speed, double seconds, int rows, int cols, double hz, double dCap, double depth = 0.0,
             double rampSeconds = 3.0, glm::vec2 hull = glm::vec2(0.0f), float hollow = 0.0f, float cell = 0.25f) {
    const float dt = float(1.0 / hz);
    EWaveField field(rows, cols, cell, RippleBoundary::Absorbing, 32);
    if (depth > 0.0) field.setMedium({9.81, 0.074 / 1025.0, depth, 0.0});
    BoundingSphere sphere;
    sphere.radius = 2.0f * cell;
    sphere.direction = SphereDirection::Down;
    sphere.heightRatio = 1.0f;
    SphereContact contact;
    const double x0 = 40.0, zTrack = rows * cell / 2.0;
    const int steps = int(std::lround(seconds / dt));
    for (int s = 0; s < steps; ++s) {
        SphereMotion m;
        const double x = x0 + speed * s * double(dt);
        m.gridX = float(x / cell);
        m.gridZ = float(zTrack / cell);
        m.centreY = 0.0f;
        m.speed = float(speed);
        m.surfaceY = 0.0f;
        RippleStamp st;
        double ramp = std::min(1.0, s * double(dt) / rampSeconds);
        ramp = ramp * ramp * (3.0 - 2.0 * ramp);
        if (planStamp(rows, cols, cell, sphere, contact, m, [&](int cx, int cz) { return field.heightAt(cx, cz); }, st)) {
            const EWaveSource src = ewaveSource(st, m.gridX, m.gridZ, cell, 9.81f);
            field.addSource(src.gx, src.gz, src.radiusCells, float(src.accel * ramp), dt);
        }
        std::vector<ObstructionCell> cells;
        if (hull.x > 0.0f) {
            ObstacleShape shape{ObstacleShape::Kind::Ellipse, {float(x), float(zTrack)}, {1.0f, 0.0f}, hull};
            shape.displaces = true;
            shape.hollow = float(hollow * ramp);
            rasteriseObstacles(std::span(&shape, 1), rows, cols, cell, [&](glm::vec2 w) { return w / cell; }, cells);
            maskHullSources(field, cells);
        }
        field.step(dt);
        if (!cells.empty()) obstructField(field, cells);
    }
    const double xs = x0 + speed * steps * double(dt);  // the sphere now
    const double lambda = 2.0 * std::numbers::pi / transverseWavenumber(speed, depth);
    const int window = std::max(1, int(std::lround(lambda / cell / 2.0)));
    const int zc = int(std::lround(zTrack / cell));
    const double dMin = 1.5 * lambda, dMax = std::min(0.75 * speed * seconds, dCap);
    std::vector<double> ds, ys;
    for (double d = dMin; d <= dMax; d += cell) {
        const int xc = int(std::lround((xs - d) / cell));
        if (xc - window < 0) break;
        std::vector<double> env(size_t(rows), 0.0);
        for (int z = 0; z < rows; ++z)
            for (int x = xc - window; x <= std::min(cols - 1, xc + window); ++x)
                env[size_t(z)] = std::max(env[size_t(z)], double(std::abs(field.heightAt(x, z))));
        const double peak = *std::max_element(env.begin(), env.end());
        if (!(peak > 0.0)) continue;
        int up = 0, down = 0;
        for (int z = rows - 1; z > zc; --z)
            if (3.0 * env[size_t(z)] >= peak) { up = z - zc; break; }
        for (int z = 0; z < zc; ++z)
            if (3.0 * env[size_t(z)] >= peak) { down = zc - z; break; }
        ds.push_back(d);
        ys.push_back(0.5 * (up + down) * cell);
    }
    // Least squares y = a + b·d.
    const double n = double(ds.size());
    double sd = 0, sy = 0, sdd = 0, sdy = 0;
    for (size_t i = 0; i < ds.size(); ++i) {
        sd += ds[i];
        sy += ys[i];
        sdd += ds[i] * ds[i];
        sdy += ds[i] * ys[i];
    }
    const double b = (n * sdy - sd * sy) / (n * sdd - sd * sd);
    return {std::atan(b) * 180.0 / std::numbers::pi, int(ds.size())};
}

// Havelock (1908): at depth Froude number Fd = U/√(g·d) < 1 the wave of wavenumber k at angle
// θ to the track keeps pace with the ship when cos²θ = tanh(κ)/(Fd²·κ), κ = k·d, and its energy
// runs at the group speed n·c, n = 1/2 + κ/sinh 2κ; in the ship's frame it lies along the ray
// tan α = n·tan θ/(1 − n + tan²θ). The wake's edge is the largest α over κ (deep water:
// n = 1/2, tan θ = 1/√2, α = arcsin 1/3). Gravity waves, as Havelock's.
double havelockAngleDeg(double froude) {
    double best = 0.0;
    for (double kappa = 1e-3; kappa < 60.0; kappa *= 1.0002) {
        const double cos2 = std::tanh(kappa) / (froude * froude * kappa);
        if (cos2 > 1.0) continue;
        const double t = std::sqrt(1.0 / cos2 - 1.0), n = 0.5 + kappa / std::sinh(2.0 * kappa);
        best = std::max(best, std::atan(n * t / (1.0 - n + t * t)));
    }
    return best * 180.0 / std::numbers::pi;
}

} // namespace

TEST_CASE("ewave: Havelock's wake angle is the Kelvin angle in deep water and widens as Fd → 1", "[ewave][wake][depth]") {
    CHECK(havelockAngleDeg(0.3) == Approx(std::asin(1.0 / 3.0) * 180.0 / std::numbers::pi).margin(0.01));
    CHECK(havelockAngleDeg(0.9) > 30.0);
    CHECK(havelockAngleDeg(0.99) > 60.0);
}

// U = 2 m/s over d = U²/(g·Fd²): 1.63 m at Fd = 0.5 (Havelock: the Kelvin angle still), 0.50 m
// at 0.9 (Havelock: 34.6°, the cusp waves κ ≈ 1.05, 3 m long). The push ramps up over 10 s:
// near Fd = 1 a sudden start sheds a ring of long waves at √(g·d) > U that overtakes the
// wedge's edge. The wedge is fitted over 1.5λ..30 m behind the sphere (the wake made at full
// push). At Fd = 0.5 the envelope's edge holds Havelock's angle to 2°. At Fd = 0.9 the
// one-third edge is not a sharp measure: the near-critical pattern's long waves reach a third
// of the cusp waves far outside the cusp line, and the measured angle moved with the fit's
// range and the ramp (28°, 46°, 60° for 60 m / 10 s, 45 m / 3 s, 30 m / 10 s); what it does
// show is the widening, so that is what is checked there (docs/ewave.md).
TEST_CASE("ewave: in water of depth d the wake holds Havelock's angle at Fd = 0.5 and is markedly wider at Fd = 0.9",
          "[ewave][wake][depth][long]") {
    const double speed = 2.0;  // stepped at 30 Hz: 0.27 cells a step (19.2° at Fd = 0.5, as at 60 Hz)
    double angle[2] = {};
    int i = 0;
    for (double froude : {0.5, 0.9}) {
        const double depth = speed * speed / (9.81 * froude * froude);
        const Wake w = runWake(speed, 40.0, 512, 1024, 30.0, 30.0, depth, 10.0);
        INFO("Fd = " << froude << " (d = " << depth << " m): envelope " << w.angleDeg << "° over " << w.samples
                     << " cross-sections, Havelock " << havelockAngleDeg(froude) << "°");
        CHECK(w.samples >= 40);
        angle[i++] = w.angleDeg;
    }
    INFO("envelope " << angle[0] << "° at Fd = 0.5, " << angle[1] << "° at Fd = 0.9");
    CHECK(std::abs(angle[0] - havelockAngleDeg(0.5)) <= 2.0);
    CHECK(angle[1] >= havelockAngleDeg(0.5) + 5.0);
}

TEST_CASE("ewave: a sphere at constant speed leaves a Kelvin wake of 19.47° for U = 2 and 4 m/s", "[ewave][wake][long]") {
    const double kelvin = std::asin(1.0 / 3.0) * 180.0 / std::numbers::pi;
    for (double speed : {2.0, 4.0}) {
        // 128 m × 256 m: the wake's 1.5λ .. 130 m behind the sphere, ±46 m to the side. Stepped
        // at 30 Hz (the 4 m/s wedge reads 18.60° stepped at 30 Hz and at 60 Hz).
        const Wake w = runWake(speed, 30.0, 512, 1024, 30.0, 130.0);
        INFO("U = " << speed << " m/s: envelope " << w.angleDeg << "° over " << w.samples << " cross-sections");
        INFO("Kelvin wake, U = " << speed << " m/s: envelope angle " << w.angleDeg << "° (theory " << kelvin << "°)");
        CHECK(w.samples >= 40);
        CHECK(std::abs(w.angleDeg - kelvin) <= 1.5);
    }
}

// U = 8 m/s: λ = 41 m, so the far wake needs a field of 256 m × 512 m. The pattern scales with
// λ = 2πU²/g (gravity waves: 16× the area of the 2 m/s wake for 4× the speed), so the cells and
// the sphere scale too: 0.5 m cells (82 a wavelength) and a 1 m sphere, stepped at 30 Hz (exact
// per mode at any step): 512 × 1024 cells, a quarter of the 0.25 m grid's work. Measured:
// 18.25° (the same for a sphere of 0.75 m or 1.5 m; 19.70° on 0.25 m cells with a 0.5 m sphere:
// the one-third edge sits a little inside the caustic on the coarser grid).
TEST_CASE("ewave: a sphere at 8 m/s leaves a Kelvin wake of 19.47°", "[ewave][wake][wake8][long]") {
    const double kelvin = std::asin(1.0 / 3.0) * 180.0 / std::numbers::pi;
    const Wake w = runWake(8.0, 45.0, 512, 1024, 30.0, 300.0, 0.0, 3.0, glm::vec2(0.0f), 0.0f, 0.5f);
    INFO("Kelvin wake, U = 8 m/s: envelope angle " << w.angleDeg << "° over " << w.samples << " cross-sections (theory "
                                                   << kelvin << "°)");
    CHECK(w.samples >= 40);
    CHECK(std::abs(w.angleDeg - kelvin) <= 1.5);
}

// A hull in the water (docs/ewave.md#hulls): the sphere inside a displacing waterplane of
// 10 m × 3 m (the ship's). Its push does not act there (the hull's water is held at its
// hollow, 0.5 m deep on the keel line, the sphere's pressure head SHR·R·(1 + AF)), so the wake
// is the hull's: a pressure distribution moving with it, its head the hollow (Havelock's ship),
// whose wake is Kelvin's. Measured: 18.09° at 4 m/s, 18.13° at 6 m/s (the measure reads a
// long smooth source a little narrow: a sphere alone, 19.03° at 4 m/s). With the sphere
// pressing inside a mask held at 0 (the pumping hull) it was 14.4° at 4 m/s.
TEST_CASE("ewave: a hull's waterplane round the sphere leaves a Kelvin wake of 19.47° at 4 and 6 m/s", "[ewave][wake][hulls][long]") {
    const double kelvin = std::asin(1.0 / 3.0) * 180.0 / std::numbers::pi;
    for (double speed : {4.0, 6.0}) {
        const Wake w = runWake(speed, 30.0, 512, 1024, 60.0, 130.0, 0.0, 3.0, glm::vec2(5.0f, 1.5f), 0.5f);
        INFO("Kelvin wake behind a hull, U = " << speed << " m/s: envelope angle " << w.angleDeg << "° over " << w.samples
                                               << " cross-sections (theory " << kelvin << "°)");
        CHECK(w.samples >= 40);
        CHECK(std::abs(w.angleDeg - kelvin) <= 1.5);
    }
}
