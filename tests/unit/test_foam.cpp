// Persistent foam (engine/foam): exponential decay to 1%, advection of a blob by v·t, the wake
// behind a moving hull and never ahead of it, the whitecap, ripple and drop sources by their
// laws, the world-space query and scrolling, and determinism across worker counts.
#include "core/hash.h"
#include "core/parallel.h"
#include "core/thread_choice.h"
#include "foam/foam_map.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"
#include "water/composite_water.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace ob;
using foam::FoamDef;
using foam::FoamMap;

namespace {

constexpr float DT = 1.0f / 60.0f;

// Coverage-weighted centroid of the map in world metres.
glm::dvec2 centroid(const FoamMap& map) {
    double sum = 0.0, sx = 0.0, sz = 0.0;
    const int n = map.grid().n;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double f = map.coverage()[size_t(j) * size_t(n) + size_t(i)];
            sum += f;
            sx += f * i;
            sz += f * j;
        }
    const glm::vec2 o = map.grid().origin();
    return glm::dvec2(o.x + sx / sum * map.grid().cell, o.y + sz / sum * map.grid().cell);
}

// A Gaussian blob of peak 0.9 and σ = sigma metres at world (x, z).
void blob(FoamMap& map, float x, float z, float sigma) {
    const int n = map.grid().n;
    const glm::vec2 o = map.grid().origin();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float dx = o.x + float(i) * map.grid().cell - x, dz = o.y + float(j) * map.grid().cell - z;
            map.coverage()[size_t(j) * size_t(n) + size_t(i)] = 0.9f * std::exp(-(dx * dx + dz * dz) / (2 * sigma * sigma));
        }
}

// The inputs of the ripple source alone.
foam::FoamInputs ripplesOf(const interaction::RipplePatch& patch) {
    foam::FoamInputs in;
    in.ripples = &patch;
    return in;
}

FoamDef smallDef(int resolution = 128) {
    FoamDef d;
    d.resolution = resolution;
    d.whitecap_from_wind = false;  // law (a) with the threshold and gain as given
    return d;
}

} // namespace

TEST_CASE("with no sources foam decays as exp(−t/decay_s) to 1% of its initial mean", "[foam]") {
    for (float dt : {DT, 0.5f}) {
        FoamDef def = smallDef(64);
        def.decay_s = 4.0f;
        FoamMap map(def, 16.0f);
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (float& f : map.coverage()) f = u(rng);
        const double initial = map.mean();
        const double tEnd = def.decay_s * std::log(100.0);  // exp(−t/τ) = 1%
        double t = 0.0;
        double worst = 0.0;
        while (t + dt <= tEnd + 1e-9) {
            map.step(dt);
            t += dt;
            worst = std::max(worst, std::abs(map.mean() / initial / std::exp(-t / def.decay_s) - 1.0));
        }
        const double last = std::exp(-(tEnd - t) / def.decay_s);  // the part of a step left over
        INFO("dt " << dt << ": worst relative error " << worst);
        CHECK(worst < 1e-4);  // the float factor e^(−dt/τ) rounds by ~3e-8 a step
        CHECK(map.mean() * last / initial == Approx(0.01).epsilon(1e-4));
    }
}

TEST_CASE("a uniform flow carries a foam blob by v·t (within a cell), by the uniform and the per-cell path", "[foam]") {
    const glm::vec2 v(1.3f, -0.7f);  // m/s
    const float t = 3.0f;
    for (bool perCell : {false, true}) {
        FoamDef def = smallDef(128);
        def.decay_s = 1e4f;
        FoamMap map(def, 32.0f);  // Δ = 0.25 m
        blob(map, -2.0f, 2.0f, 0.6f);
        const glm::dvec2 before = centroid(map);
        if (perCell) {
            std::span<float> ux = map.flow().velocityX(), uz = map.flow().velocityZ();
            std::fill(ux.begin(), ux.end(), v.x);
            std::fill(uz.begin(), uz.end(), v.y);
        } else {
            map.flow().setUniform(v);
        }
        const int steps = int(std::lround(t / DT));
        for (int s = 0; s < steps; ++s) map.step(DT);
        const glm::dvec2 moved = centroid(map) - before;
        INFO((perCell ? "per-cell" : "uniform") << " path: moved (" << moved.x << ", " << moved.y << ") m, expected ("
                                                 << v.x * t << ", " << v.y * t << ")");
        CHECK(std::abs(moved.x - v.x * t) < map.grid().cell);
        CHECK(std::abs(moved.y - v.y * t) < map.grid().cell);
        // Its peak sits where the flow took it (within a cell; the bilinear step widens it).
        const auto peak = std::max_element(map.coverage().begin(), map.coverage().end()) - map.coverage().begin();
        const glm::vec2 at = map.grid().origin() + glm::vec2(float(peak % 128), float(peak / 128)) * map.grid().cell;
        CHECK(std::abs(at.x - (-2.0f + v.x * t)) <= map.grid().cell);
        CHECK(std::abs(at.y - (2.0f + v.y * t)) <= map.grid().cell);
        CHECK(map.sample(-2.0f, 2.0f) < 0.01f);
    }
}

TEST_CASE("a per-cell flow that crosses more than a cell a step moves the blob like the uniform path", "[foam]") {
    // 0.5 s steps at (1.3, −0.7) m/s on 0.25 m cells: 2.6 and 1.4 cells a step, beyond the
    // neighbour-only passes; the rows are redone by a general linear interpolation.
    const glm::vec2 v(1.3f, -0.7f);
    const float dt = 0.5f;
    std::vector<float> result[2];
    for (bool perCell : {false, true}) {
        FoamDef def = smallDef(128);
        def.decay_s = 1e4f;
        FoamMap map(def, 32.0f);
        blob(map, -2.0f, 2.0f, 0.6f);
        if (perCell) {
            std::span<float> ux = map.flow().velocityX(), uz = map.flow().velocityZ();
            std::fill(ux.begin(), ux.end(), v.x);
            std::fill(uz.begin(), uz.end(), v.y);
        } else {
            map.flow().setUniform(v);
        }
        const glm::dvec2 before = centroid(map);
        for (int s = 0; s < 6; ++s) map.step(dt);
        const glm::dvec2 moved = centroid(map) - before;
        INFO((perCell ? "per-cell" : "uniform") << " path: moved (" << moved.x << ", " << moved.y << ") m, expected ("
                                                 << v.x * 3.0f << ", " << v.y * 3.0f << ")");
        CHECK(std::abs(moved.x - v.x * 3.0) < map.grid().cell);
        CHECK(std::abs(moved.y - v.y * 3.0) < map.grid().cell);
        result[perCell].assign(map.coverage().begin(), map.coverage().end());
    }
    // Both are the same linear interpolation, per axis or as a bilinear stencil: equal to rounding.
    double worst = 0.0;
    for (size_t c = 0; c < result[0].size(); ++c) worst = std::max(worst, double(std::abs(result[0][c] - result[1][c])));
    CHECK(worst < 1e-5);
}

TEST_CASE("one Gerstner wave carries a foam blob along its particles' orbit: out by the closed-form excursion, back after a period", "[foam]") {
    // A wave of λ = 64 m along x (k = 2π/64, ω = sqrt(g·k), T = 2π/ω = 6.4 s), a = 1 m (k·a = 0.1).
    // Foam moves with the surface particles: the one displaced to x0 at t = 0 has its rest point
    // α0 = x0 + a·sin(k·α0 − φ) and sits at x(t) = α0 − a·sin(k·α0 − ω·t − φ): the horizontal
    // part of a circle, closed (no drift), so the blob swings by 2a and comes back after T.
    // Its coverage centroid follows the particle up to ~1.5·σ²·∂²x/∂x0² (the flow stretches the
    // blob unevenly): 1.5 · (0.7 m)² · 2a·k² < 1.5 cm for the blob widened by resampling; the
    // step's velocity is its start's, a phase lag of ω·Δt/2: a·ω·Δt/2 = 0.8 cm.
    const float k = 2.0f * std::numbers::pi_v<float> / 64.0f, a = 1.0f, phase = 0.3f;
    const double omega = std::sqrt(9.81 * double(k)), period = 2.0 * std::numbers::pi / omega;
    const std::vector<ocean::GerstnerWave> waves{{k, 0.0f, a, phase}};
    water::CompositeWater water(waves, 9.81f);
    FoamDef def = smallDef(512);
    def.decay_s = 1e4f;
    def.flow_resolution = 32;  // nodes every 16 cells (1 m)
    FoamMap map(def, 32.0f);   // Δ = 0.0625 m
    const float x0 = 1.0f, z0 = -2.0f, sigma = 0.5f;
    blob(map, x0, z0, sigma);
    double alpha0 = x0;  // fixed point of α = x0 + a·sin(kα − φ) (contracts: k·a < 1)
    for (int it = 0; it < 100; ++it) alpha0 = x0 + a * std::sin(k * alpha0 - phase);
    const glm::dvec2 start = centroid(map);
    const std::vector<glm::vec2> nodes = map.flow().nodePositions();
    std::vector<glm::vec2> velocity(nodes.size());
    const int steps = int(std::lround(period / DT));
    double worst = 0.0, lo = 1e9, hi = -1e9, worstZ = 0.0;
    for (int s = 0; s < steps; ++s) {
        water.update(s * double(DT));
        water.horizontalVelocityBatch(nodes, velocity);
        map.flow().setNodes(velocity);
        map.step(DT);
        const double t = (s + 1) * double(DT);
        const glm::dvec2 at = centroid(map);
        const double expected = alpha0 - a * std::sin(k * alpha0 - omega * t - phase);
        worst = std::max(worst, std::abs(at.x - expected));
        worstZ = std::max(worstZ, std::abs(at.y - start.y));
        lo = std::min(lo, at.x);
        hi = std::max(hi, at.x);
    }
    const glm::dvec2 end = centroid(map);
    INFO("start " << start.x << " m, worst |x − orbit| " << worst << " m, swing " << hi - lo << " m (2a = " << 2 * a
                  << "), after a period " << end.x - start.x << " m (" << steps << " steps of " << DT << " s for T = "
                  << period << " s), worst z drift " << worstZ << " m");
    CHECK(std::abs(start.x - x0) < 1e-3);
    CHECK(worst < 0.03);
    CHECK(std::abs((hi - lo) - 2 * a) < 0.03);
    CHECK(std::abs(end.x - start.x) < 0.02);  // closed orbit: back where it started (T is 0.3 steps off a whole number)
    CHECK(worstZ < 1e-3);                    // the wave runs along x
}

TEST_CASE("wake foam appears behind a moving hull, along its track, and not in front of it", "[foam]") {
    FoamDef def = smallDef(128);
    def.decay_s = 1e4f;  // no decay: the deposit along the centre line is wake_weight
    def.wake_weight = 0.8f;  // below the clamp
    def.wake_streaks = 0.0f;  // laid evenly across (the streaks: the next test)
    FoamMap map(def, 32.0f);
    const float radius = 1.0f, speed = 4.0f;
    glm::vec3 hull(-10.0f, 0.0f, 0.0f);
    const glm::vec3 velocity(speed, 0.0f, 0.0f);
    while (hull.x < 0.0f) {
        map.addWake(hull, velocity, radius, DT);
        map.step(DT);
        hull.x += speed * DT;
    }
    // Behind, on the track: ~wake_weight (the clamp at 1 is above it); off the track: nothing.
    for (float x = -8.5f; x <= -1.5f; x += 0.5f) {
        INFO("x " << x);
        CHECK(map.sample(x, 0.0f) == Approx(def.wake_weight).epsilon(0.1));
        CHECK(map.sample(x, 0.5f) == Approx(def.wake_weight * std::sqrt(1.0 - 0.25)).epsilon(0.15));
        CHECK(map.sample(x, 1.5f) == 0.0f);
    }
    // In front of the hull: not a trace.
    for (float x = hull.x + 0.3f; x < 15.0f; x += 0.25f)
        for (float z = -2.0f; z <= 2.0f; z += 0.25f) REQUIRE(map.sample(x, z) == 0.0f);
    // A hull at rest leaves nothing.
    FoamMap still(def, 32.0f);
    for (int s = 0; s < 60; ++s) still.addWake(glm::vec3(0.0f), glm::vec3(0.0f), radius, DT);
    CHECK(still.mean() == 0.0);
}

namespace {

// The wake's streak factor as docs/splash_foam.md states it: 1 − depth·(½ + ½·n(y)), n the
// mean of three sines of the lateral offset y (wavelengths 0.9, 1.5, 2.6 m) weighted 1, 0.7, 0.5.
double streaks(double y, double depth) {
    const double twoPi = 2.0 * std::numbers::pi;
    const double n = (std::sin(twoPi * y / 0.9 + 1.3) + 0.7 * std::sin(twoPi * y / 1.5 + 4.1) + 0.5 * std::sin(twoPi * y / 2.6 + 2.2)) / 2.2;
    return 1.0 - depth * (0.5 + 0.5 * n);
}

} // namespace

TEST_CASE("a hull's wake foam lies in streaks along its track: wake_weight·sqrt(1 − (y/R)²)·m(y)", "[foam]") {
    FoamDef def = smallDef(256);  // Δ = 0.125 m
    def.decay_s = 1e4f;
    def.wake_weight = 0.8f;
    def.wake_streaks = 0.6f;
    FoamMap map(def, 32.0f);
    const float radius = 1.5f, speed = 4.0f;
    glm::vec3 hull(-10.0f, 0.0f, 0.0f);
    const glm::vec3 velocity(speed, 0.0f, 0.0f);  // the track along +x: y = +z to its left
    while (hull.x < 0.0f) {
        map.addWake(hull, velocity, radius, DT);
        map.step(DT);
        hull.x += speed * DT;
    }
    double lo = 1.0, hi = 0.0;
    for (int k = -10; k <= 10; ++k) {
        const double y = 0.125 * k;  // on cell centres across the track
        const double expected = 0.8 * std::sqrt(1.0 - (y / radius) * (y / radius)) * streaks(y, 0.6);
        const double got = map.sample(-5.0f, float(y));
        INFO("y " << y << " m: " << got << ", expected " << expected);
        CHECK(got == Approx(expected).margin(0.04));  // the deposit per step is a sum over ~R/(U·dt) steps: ±1 step
        lo = std::min(lo, got), hi = std::max(hi, got);
    }
    // Streaks: the foam across the track varies by more than half of its largest value.
    CHECK(hi - lo > 0.5 * hi);
    // The factor stays in [1 − depth, 1].
    for (double y = -5.0; y <= 5.0; y += 0.01) {
        REQUIRE(foam::wakeStreaks(float(y), 0.6f) >= 0.4f - 1e-6f);
        REQUIRE(foam::wakeStreaks(float(y), 0.6f) <= 1.0f + 1e-6f);
    }
}

TEST_CASE("the turbulent wake behind a stern widens as b² = R² + 2·K·a and thins as R/b, adding w·e^(−a/a_s)/a_s", "[foam]") {
    FoamDef def = smallDef(256);  // Δ = 0.125 m
    def.decay_s = 1e4f;
    def.wake_weight = 1.0f;
    def.wake_streaks = 0.0f;
    def.wake_turbulence_s = 3.0f;
    def.wake_diffusivity = 0.3f;
    const float radius = 1.4f, seconds = 1.0f;
    for (float age : {0.0f, 4.0f, 10.0f}) {
        FoamMap map(def, 32.0f);
        // One segment of the track along x, from −8 m to 8 m, held at this age for a second.
        for (int s = 0; s < int(seconds / DT + 0.5f); ++s) map.addWakeTrail({-8.0f, 0.0f}, {8.0f, 0.0f}, age, radius, DT);
        const double b = std::sqrt(1.4 * 1.4 + 2.0 * 0.3 * age);
        const double peak = std::exp(-age / 3.0) / 3.0 * (1.4 / b) * seconds;
        INFO("age " << age << " s: half-width " << b << " m, peak " << peak);
        CHECK(map.sample(0.0f, 0.0f) == Approx(peak).epsilon(1e-3));
        CHECK(map.sample(0.0f, float(0.5 * b)) == Approx(peak * std::sqrt(0.75)).epsilon(0.02));
        CHECK(map.sample(0.0f, float(b + 0.2)) == 0.0f);   // nothing beyond b (and its bilinear cell)
        CHECK(map.sample(0.0f, float(b - 0.3)) > 0.0f);
        CHECK(map.sample(-8.5f, 0.0f) == 0.0f);            // nothing past the segment's ends
        CHECK(map.sample(8.5f, 0.0f) == 0.0f);
    }
    // No turbulence time: nothing.
    def.wake_turbulence_s = 0.0f;
    FoamMap none(def, 32.0f);
    none.addWakeTrail({-8.0f, 0.0f}, {8.0f, 0.0f}, 1.0f, radius, DT);
    CHECK(none.mean() == 0.0);
}

TEST_CASE("a breaking bow wave leaves foam along two arms at the Kelvin angle, bow_weight·q where they swept, none ahead", "[foam]") {
    FoamDef def = smallDef(256);  // Δ = 0.125 m
    def.decay_s = 1e4f;
    def.bow_weight = 0.5f;
    FoamMap map(def, 32.0f);
    const float radius = 1.0f, speed = 5.0f, q = 0.5f;  // q = U/U_b − 1 for U_b = 3.33 m/s
    glm::vec3 bow(-12.0f, 0.0f, 0.0f);
    const glm::vec3 velocity(speed, 0.0f, 0.0f);
    while (bow.x < 0.0f) {
        map.addBowWave(bow, velocity, radius, q, DT);
        bow.x += speed * DT;
    }
    // The arms: from the shoulders (x_c + R/2, ±R), back at asin(1/3), 8·R·q = 4 m long: they
    // reach R + 4/3 m off the track. Well behind the bow, every point between swept: bow_weight·q.
    const double reach = 1.0 + 4.0 / 3.0;
    for (float y : {1.3f, 1.7f, 2.0f}) {
        for (float side : {-1.0f, 1.0f}) {
            INFO("y " << side * y);
            CHECK(map.sample(-6.0f, side * y) == Approx(0.5 * q).epsilon(0.05));
        }
    }
    CHECK(map.sample(-6.0f, float(reach + 0.3)) == 0.0f);  // beyond the arms' reach (+ half the line, a cell)
    CHECK(map.sample(-6.0f, 0.5f) == 0.0f);                // inside the hull's beam: no arm passes
    // Nothing ahead of the shoulders.
    for (float x = bow.x + 0.5f * radius + 0.3f; x < 15.0f; x += 0.25f)
        for (float z = -4.0f; z <= 4.0f; z += 0.25f) REQUIRE(map.sample(x, z) == 0.0f);
    // Below the bow-spray speed (q ≤ 0): nothing.
    FoamMap slow(def, 32.0f);
    slow.addBowWave(glm::vec3(0.0f), velocity, radius, 0.0f, DT);
    CHECK(slow.mean() == 0.0);
}

TEST_CASE("whitecaps, steep ripples and landed drops feed foam by their laws", "[foam]") {
    FoamDef def = smallDef(64);
    SECTION("whitecaps: whitecap_weight·(J_0 − J)·dt where J < J_0, nothing elsewhere") {
        FoamMap map(def, 16.0f);  // Δ = 0.25 m, from −8 m to 7.75 m
        // A 32 m tile of 64 samples: J = 0 where x mod 32 < 8 m... in world terms x ∈ [0, 8).
        const int n = 64;
        const float tile = 32.0f;
        std::vector<float> jac(size_t(n) * n, 1.0f);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (float(i) * tile / n < 8.0f) jac[size_t(j) * n + size_t(i)] = 0.0f;
        map.addSources({jac, n, tile}, 0.1f);
        CHECK(map.sample(4.0f, 0.0f) == Approx(def.whitecap_weight * def.whitecap_jacobian * 0.1f));
        CHECK(map.sample(-4.0f, 3.0f) == 0.0f);  // x ∈ [−8, 0) is x mod 32 ∈ [24, 32): J = 1
    }
    SECTION("ripples: ripple_weight·(|∇h| − s_0)·dt where the ripples are steep") {
        interaction::RippleDef rd;
        rd.model = interaction::rippleModel("kang2008");  // its field is written directly here
        rd.resolution = 64;
        rd.cell_size = 0.25f;
        interaction::RipplePatch patch(rd);
        // A ramp of slope 0.8 over x ∈ [2, 4] m of the patch, flat elsewhere.
        std::span<float> h = patch.solverAs<ob::interaction::Kang2008Solver>()->field().current();
        for (int z = 1; z < 63; ++z)
            for (int x = 1; x < 63; ++x) {
                const float wx = patch.origin().x + float(x) * rd.cell_size;
                h[size_t(z) * 64 + size_t(x)] = 0.8f * std::clamp(wx - 2.0f, 0.0f, 2.0f);
            }
        FoamMap map(def, 16.0f);
        map.addSources(ripplesOf(patch), 0.1f);
        CHECK(map.sample(3.0f, 0.0f) == Approx(def.ripple_weight * (0.8f - def.ripple_slope) * 0.1f).epsilon(1e-4));
        CHECK(map.sample(-3.0f, 0.0f) == 0.0f);
        CHECK(map.sample(6.0f, 0.0f) == 0.0f);
    }
    SECTION("drops: splash_weight·π·(10·r)²/Δ² in the cell each lands in") {
        FoamMap map(def, 16.0f);
        splash::Landing l;
        l.position = glm::vec3(1.0f, 0.0f, -2.0f);  // a cell centre
        l.radius = 0.004f;
        map.addLandings(std::span(&l, 1));
        const float expected = def.splash_weight * float(M_PI) * 0.04f * 0.04f / (0.25f * 0.25f);
        CHECK(map.sample(1.0f, -2.0f) == Approx(expected));
        for (int k = 0; k < 100; ++k) map.addLandings(std::span(&l, 1));
        CHECK(map.sample(1.0f, -2.0f) == 1.0f);  // clamped at full coverage
    }
    SECTION("drops between cell centres: the amount spread over the four cells around, by bilinear weights") {
        FoamMap map(def, 16.0f);
        splash::Landing l;
        l.position = glm::vec3(1.0f + 0.25f * 0.25f, 0.0f, -2.0f + 0.75f * 0.25f);  // a quarter and three quarters of a cell on
        l.radius = 0.004f;
        map.addLandings(std::span(&l, 1));
        const float expected = def.splash_weight * float(M_PI) * 0.04f * 0.04f / (0.25f * 0.25f);
        float total = 0.0f;
        for (float c : map.coverage()) total += c;
        CHECK(total == Approx(expected).epsilon(1e-5));
        CHECK(map.sample(1.0f, -2.0f) == Approx(expected * 0.75f * 0.25f).epsilon(1e-5));
        CHECK(map.sample(1.25f, -1.75f) == Approx(expected * 0.25f * 0.75f).epsilon(1e-5));
    }
}

TEST_CASE("the foam query is world-space: bilinear, 0 outside, unchanged by scrolling the map", "[foam]") {
    FoamDef def = smallDef(64);
    FoamMap map(def, 16.0f);
    blob(map, 1.0f, 1.0f, 0.5f);
    const float inside = map.sample(1.0f, 1.0f), nearby = map.sample(1.3f, 0.8f);
    CHECK(inside > 0.85f);
    CHECK(map.sample(100.0f, 0.0f) == 0.0f);
    map.centerOn(glm::vec2(3.0f, -2.0f));  // 12 and −8 cells
    CHECK(map.sample(1.0f, 1.0f) == inside);
    CHECK(map.sample(1.3f, 0.8f) == nearby);
    map.centerOn(glm::vec2(200.0f, 0.0f));  // the blob left the map
    CHECK(map.mean() == 0.0);
}

TEST_CASE("same inputs give bit-identical foam for any worker count", "[foam][determinism]") {
    auto run = [](int workers) {
        setWorkerCount(workers);
        FoamDef def = smallDef(256);
        FoamMap map(def, 64.0f);
        blob(map, 0.0f, 0.0f, 3.0f);
        std::span<float> ux = map.flow().velocityX(), uz = map.flow().velocityZ();
        for (size_t c = 0; c < ux.size(); ++c) {
            ux[c] = 0.5f * std::sin(float(c % 256) * 0.05f);
            uz[c] = 0.3f * std::cos(float(c / 256) * 0.07f);
        }
        for (int s = 0; s < 60; ++s) {
            map.addWake(glm::vec3(float(s) * 0.1f, 0.0f, 0.0f), glm::vec3(6.0f, 0.0f, 0.0f), 1.0f, DT);
            map.step(DT);
        }
        std::vector<glm::vec2> nodes = map.flow().nodePositions();  // a velocity grid's nodes
        for (glm::vec2& v : nodes) v = glm::vec2(0.6f * std::sin(v.y * 0.3f), 0.4f * std::cos(v.x * 0.2f));
        map.flow().setNodes(nodes);
        for (int s = 0; s < 60; ++s) map.step(DT);
        map.flow().setUniform(glm::vec2(0.7f, 0.2f));
        for (int s = 0; s < 60; ++s) map.step(DT);
        setWorkerCount(0);
        StateHasher h;
        map.hash(h);
        return h.value();
    };
    const uint64_t one = run(1);
    CHECK(run(2) == one);
    CHECK(run(3) == one);
}

TEST_CASE("update()'s velocity grid, each node evaluated every K steps and extrapolated linearly between, stays within the extrapolation's error bound on a scrolling map", "[foam]") {
    // One wave along x (λ = 64 m, a = 1 m, k·a = 0.098; trochoid x = α − a·sin(k·α − ω·t − φ)).
    // At a fixed world point the velocity of the particle there is a·ω·cos θ, θ the phase of its
    // rest point: |∂²u/∂t²| ≤ a·ω³·(1 + k·a)/(1 − k·a)³ and |∂u/∂x| ≤ k·a·ω/(1 − k·a). A node
    // evaluated at t0 and t1 ≤ t0 + T (T = K·dt) and extrapolated to t1 + s, s ≤ (K − 1)·dt, misses
    // by at most |∂²u/∂t²|·(T + s)·s/2 (the remainder of the linear interpolant through t0, t1);
    // each evaluation may take the particle up to FLOW_REST_TOLERANCE from the node, an error of
    // |∂u/∂x| times it that the extrapolation carries with weight up to 1 + 2·s/T. The map
    // scrolls every step (0.2 m/s along x, 0.1 m/s along z: onto new node rows and columns).
    const float k = 2.0f * std::numbers::pi_v<float> / 64.0f, a = 1.0f, phase = 0.3f;
    const double ka = k * a, omega = std::sqrt(9.81 * double(k)), period = 2.0 * std::numbers::pi / omega;
    const std::vector<ocean::GerstnerWave> waves{{k, 0.0f, a, phase}};
    water::CompositeWater water(waves, 9.81f);
    const double uttMax = a * omega * omega * omega * (1 + ka) / std::pow(1 - ka, 3);
    const double uxMax = ka * omega / (1 - ka);
    double worstOf[9] = {};
    for (int K : {1, 4, 8}) {
        FoamDef def = smallDef(256);
        def.flow_resolution = 16;  // nodes every 16 cells: 4 m
        def.flow_refresh_steps = K;
        FoamMap map(def, 64.0f);  // Δ = 0.25 m
        foam::FoamInputs in;
        in.water = &water;
        const int steps = int(std::lround(period / DT));
        double worst = 0.0;
        for (int s = 0; s < steps; ++s) {
            const double t = s * double(DT);
            water.update(t);
            map.centerOn(glm::vec2(float(0.2 * t), float(0.1 * t)) + glm::vec2(0.1f));
            map.update(in, DT);
            if (s < K) continue;  // every node has two evaluations from step K − 1 on
            const std::vector<glm::vec2> nodes = map.flow().nodePositions();
            std::vector<glm::vec2> exact(nodes.size());
            water.horizontalVelocityBatch(nodes, exact);
            const std::span<const glm::vec2> used = map.flow().nodes();
            REQUIRE(used.size() == exact.size());
            for (size_t c = 0; c < exact.size(); ++c) {
                const glm::vec2 d = used[c] - exact[c];
                worst = std::max(worst, std::sqrt(double(d.x) * d.x + double(d.y) * d.y));
            }
        }
        const double T = K * double(DT), sMax = (K - 1) * double(DT);
        const double extrapolation = uttMax * (T + sMax) * sMax / 2;
        const double rest = (1 + 2 * sMax / T) * uxMax * foam::FLOW_REST_TOLERANCE;
        INFO("K " << K << ": worst |u − exact| " << worst << " m/s; bound " << extrapolation << " (extrapolation) + " << rest
                  << " (rest points) of a·ω = " << a * omega << " m/s");
        CHECK(worst <= extrapolation + rest + 1e-4);
        worstOf[K] = worst;
    }
    // The error is the extrapolation's: it grows as (T + s)·s, 21·dt² for K = 4, 105·dt² for K = 8.
    INFO("worst: K = 1 " << worstOf[1] << ", K = 4 " << worstOf[4] << ", K = 8 " << worstOf[8] << " m/s");
    CHECK(worstOf[8] > 2.5 * worstOf[4]);
    // and reaches a good part of the bound's a·ω³ (where |∂²u/∂t²| is largest) for K = 8
    CHECK(worstOf[8] > 0.4 * a * omega * omega * omega * (8 + 7) * 7 * double(DT) * double(DT) / 2);
}

TEST_CASE("update() in one sweep gives the bits of the whitecaps, then the ripples, then step", "[foam]") {
    // Whitecaps over half the tile, a ramp of steep ripples, a blob moved by a velocity grid;
    // ripple cells the size of the foam's (read in place) and half of it (gathered).
    for (float rippleCell : {0.25f, 0.125f}) {
        FoamDef def = smallDef(128);
        def.flow_resolution = 8;
        const int n = 64;
        const float tile = 20.0f;
        std::vector<float> jac(size_t(n) * n);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) jac[size_t(j) * n + size_t(i)] = 0.6f + 0.5f * std::sin(0.3f * float(i)) * std::cos(0.2f * float(j));
        interaction::RippleDef rd;
        rd.model = interaction::rippleModel("kang2008");  // its field is written directly here
        rd.resolution = 64;
        rd.cell_size = rippleCell;
        interaction::RipplePatch patch(rd);
        std::span<float> h = patch.solverAs<ob::interaction::Kang2008Solver>()->field().current();
        for (int z = 0; z < 64; ++z)
            for (int x = 0; x < 64; ++x) h[size_t(z) * 64 + size_t(x)] = 0.8f * rippleCell * float(x % 9) * std::sin(0.4f * float(z));
        FoamMap calls(def, 32.0f, glm::vec2(1.3f, -0.6f)), swept(def, 32.0f, glm::vec2(1.3f, -0.6f));
        for (FoamMap* map : {&calls, &swept}) {
            blob(*map, 2.0f, -1.0f, 2.0f);
            std::vector<glm::vec2> nodes = map->flow().nodePositions();
            for (glm::vec2& v : nodes) v = glm::vec2(1.5f * std::sin(v.y * 0.3f), 1.2f * std::cos(v.x * 0.2f));
            map->flow().setNodes(nodes);
        }
        foam::FoamInputs in;
        in.jacobian = jac;
        in.jacobianN = n;
        in.jacobianTile = tile;
        in.ripples = &patch;
        for (int s = 0; s < 20; ++s) {
            calls.addSources({jac, n, tile}, DT);
            calls.addSources(ripplesOf(patch), DT);
            calls.step(DT);
            swept.update(in, DT);
        }
        INFO("ripple cell " << rippleCell << " m; mean coverage " << calls.mean());
        CHECK(calls.mean() > 0.01);
        CHECK(std::equal(calls.coverage().begin(), calls.coverage().end(), swept.coverage().begin()));
    }
}

TEST_CASE("update() gives bit-identical foam for any worker count, scrolling, with every source and the water's velocity", "[foam][determinism]") {
    const std::vector<ocean::GerstnerWave> waves{{0.2f, 0.3f, 0.5f, 0.1f}, {0.5f, -1.1f, 0.1f, 2.0f}};
    auto run = [&](int workers) {
        setWorkerCount(workers);
        water::CompositeWater water(waves, 9.81f);
        FoamDef def = smallDef(256);
        FoamMap map(def, 64.0f);
        blob(map, 0.0f, 0.0f, 3.0f);
        const int n = 32;
        std::vector<float> jac(size_t(n) * n);
        for (size_t c = 0; c < jac.size(); ++c) jac[c] = 0.5f + 0.4f * std::sin(float(c) * 0.37f);
        interaction::RippleDef rd;
        rd.model = interaction::rippleModel("kang2008");
        rd.resolution = 64;
        interaction::RipplePatch patch(rd);
        std::span<float> height = patch.solverAs<ob::interaction::Kang2008Solver>()->field().current();
        for (size_t c = 0; c < height.size(); ++c) height[c] = 0.2f * std::sin(float(c) * 1.3f);
        foam::FoamInputs in;
        in.jacobian = jac;
        in.jacobianN = n;
        in.jacobianTile = 40.0f;
        in.ripples = &patch;
        in.water = &water;
        for (int s = 0; s < 90; ++s) {
            water.update(s * double(DT));
            map.centerOn(glm::vec2(0.3f * float(s), -0.2f * float(s)));
            map.addWake(glm::vec3(0.3f * float(s), 0.0f, -0.2f * float(s)), glm::vec3(18.0f, 0.0f, -12.0f), 1.0f, DT);
            map.update(in, DT);
        }
        setWorkerCount(0);
        StateHasher h;
        map.hash(h);
        return h.value();
    };
    setThreadMeasuring(false);  // every worker count splits, whatever this machine measured
    const uint64_t one = run(1);
    CHECK(run(2) == one);
    CHECK(run(3) == one);
    setThreadMeasuring(true);
}

TEST_CASE("a constant velocity grid moves a blob like the uniform path, in one sweep and where it crosses more than a cell a step", "[foam]") {
    // For a uniform u the split passes are the uniform path's bilinear stencil (equal to rounding),
    // whether the sweep takes them (0.08 and 0.04 cells a step) or the two passes over the map
    // (0.5 s steps: 2.6 and 1.4 cells); the map scrolls between steps (the nodes keep their place).
    const glm::vec2 v(1.3f, -0.7f);
    for (float dt : {DT, 0.5f}) {
        FoamDef def = smallDef(128);
        def.decay_s = 1e4f;
        def.flow_resolution = 16;
        FoamMap uniform(def, 32.0f), grid(def, 32.0f);
        for (FoamMap* map : {&uniform, &grid}) blob(*map, -2.0f, 2.0f, 0.6f);
        uniform.flow().setUniform(v);
        grid.flow().setNodes(std::vector<glm::vec2>(grid.flow().nodePositions().size(), v));
        const int steps = int(std::lround(3.0f / dt));
        for (int s = 0; s < steps; ++s) {
            const glm::vec2 centre = glm::vec2(0.6f, -0.4f) * (float(s) * dt);  // 0.25 m cells: scrolls every few steps
            uniform.centerOn(centre);
            grid.centerOn(centre);
            uniform.step(dt);
            grid.step(dt);
        }
        double worst = 0.0;
        for (size_t c = 0; c < uniform.coverage().size(); ++c)
            worst = std::max(worst, double(std::abs(uniform.coverage()[c] - grid.coverage()[c])));
        INFO("dt " << dt << " s: worst difference " << worst << ", mean " << uniform.mean());
        CHECK(uniform.mean() > 0.001);
        CHECK(worst < 1e-5);
    }
}
