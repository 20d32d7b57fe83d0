// The water moves what floats: a floating ball on Gerstner's exact Lagrangian wave rides its
// closed orbit and stays put; on a linear (Airy) wave it drifts at the Stokes drift
// a²·ω·k·e^{2kz} (Stokes 1847); in the wind it drifts at the leeway where the air's drag on its
// emerged part equals the water's on its submerged part. Each is checked against the closed
// form, not against the code's own output.
#include "ecs/components.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/spectrum.h"
#include "ocean/velocity_bands.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>
#include <time.h>

using namespace ob;

namespace {

constexpr double G = 9.81;

// The one body of a sandbox: its position.
glm::vec3 bodyPosition(game::Sandbox& sandbox) {
    auto& bodies = sandbox.world().pool<game::Body>();
    REQUIRE(bodies.size() == 1);
    return sandbox.world().get<ecs::Transform>(bodies.entities()[0]).position;
}

// Steps `steps` times and records the body's position after each step.
std::vector<glm::vec3> track(game::Sandbox& sandbox, int steps) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < steps; ++i) {
        sandbox.step();
        out.push_back(bodyPosition(sandbox));
    }
    return out;
}

// Mean of x over samples [begin, end).
double meanX(const std::vector<glm::vec3>& p, size_t begin, size_t end) {
    double s = 0.0;
    for (size_t i = begin; i < end; ++i) s += p[i].x;
    return s / double(end - begin);
}

const char* BALL = "[[objects]]\ntype = \"sphere\"\nradius = 0.1\ndensity = 500.0\nposition = [0, 0, 0]\n";

} // namespace

TEST_CASE("a small ball on one Gerstner wave rides its closed orbit and does not drift", "[physics][water_motion]") {
    // λ = 20 m, a = 0.5 m along x: k = 0.314 rad/m, ω = √(g·k) = 1.756 rad/s, T = 3.58 s.
    const double k = 2.0 * M_PI / 20.0, a = 0.5, omega = std::sqrt(G * k), period = 2.0 * M_PI / omega;
    const std::string scene = std::string("[ocean]\namplitude = 0.0\nwind_speed = 0.0\nresolution = 16\n[foam]\nenabled = false\n[gerstner]\ncount = 0\n"
                                          "[[gerstner.waves]]\nkx = ") +
                              std::to_string(k) + "\nkz = 0.0\namplitude = 0.5\nphase = 0.0\n[ripples]\nenabled = false\n" + BALL;
    game::Sandbox sandbox(game::parseScene(scene, "gerstner_orbit.toml"));
    const int perPeriod = int(std::lround(period * 60.0));
    track(sandbox, 3 * perPeriod);  // settle
    const std::vector<glm::vec3> p = track(sandbox, 8 * perPeriod);
    double lo = 1e9, hi = -1e9;
    for (size_t i = size_t(4 * perPeriod); i < p.size(); ++i) {
        lo = std::min(lo, double(p[i].x));
        hi = std::max(hi, double(p[i].x));
    }
    const double radius = 0.5 * (hi - lo);
    const double drift = (meanX(p, size_t(6 * perPeriod), size_t(8 * perPeriod)) - meanX(p, 0, size_t(2 * perPeriod))) /
                         (6.0 * period);
    const double stokes = a * a * omega * k;  // what an Airy wave of this a and k would carry it at
    INFO("horizontal orbit radius " << radius << " m (a = " << a << "), drift " << drift << " m/s (Stokes would be "
                                    << stokes << ")");
    CHECK(radius == Approx(a).epsilon(0.10));
    CHECK(std::abs(drift) < 0.1 * stokes);
}

TEST_CASE("a small ball on one linear (Airy) wave drifts at the Stokes drift", "[physics][water_motion]") {
    // One FFT mode, choppiness 0 (the Airy surface, no Lagrangian displacement): the water's
    // velocity at a fixed point is Eulerian, u = a·ω·cos(k·x − ω·t), and a particle carried by it
    // drifts at U_s = a²·ω·k (Stokes; at the surface, e^{2kz} = 1 for the ball's centre on it).
    const double k = 2.0 * M_PI / 20.0, omega = std::sqrt(G * k), period = 2.0 * M_PI / omega;
    const std::string scene = std::string("[ocean]\npatch_size = 160.0\nresolution = 128\ncascades = 1\nchoppiness = 0.0\n"
                                          "wind_speed = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n") +
                              BALL;
    game::Sandbox sandbox(game::parseScene(scene, "airy_drift.toml"));
    auto* ocean = sandbox.world().resource<game::OceanState>();
    REQUIRE(ocean);
    ocean::CascadeSpectrum& spectrum = ocean->cpu->spectrum(0);
    spectrum.clear();
    // h̃0(−K) alone: h = 2|h̃0|·cos(K·x − ω·t + φ), a wave travelling toward +x (8 crests on the tile).
    spectrum.setH0(-8, 0, {0.25f, 0.0f});
    ocean->water->measureWavenumbers();
    track(sandbox, 3 * int(std::lround(period * 60.0)));  // settle (and three map updates for the rates)
    // The amplitude as the surface has it (an independent check of the mode's scale).
    double a = 0.0;
    for (int i = 0; i < 200; ++i) a = std::max(a, double(ocean->water->sample(float(i) * 0.1f, 0.0f).height));
    REQUIRE(a == Approx(0.5).epsilon(0.02));
    REQUIRE(ocean->water->cascadeWavenumber(0) == Approx(k).epsilon(1e-4));
    const int perPeriod = int(std::lround(period * 60.0));
    const std::vector<glm::vec3> p = track(sandbox, 10 * perPeriod);
    const double drift = (meanX(p, size_t(8 * perPeriod), size_t(10 * perPeriod)) - meanX(p, 0, size_t(2 * perPeriod))) /
                         (8.0 * period);
    const double stokes = a * a * omega * k;
    INFO("drift " << drift << " m/s, Stokes " << stokes << " m/s");
    CHECK(drift == Approx(stokes).epsilon(0.25));
}

TEST_CASE("leeway: a floating ball in the wind drifts where the air's drag equals the water's", "[physics][water_motion]") {
    // No waves, no current (the layer off: its water would be dragged along by the ball's own
    // drag, Newton's third law, and carry it faster): steady drift v where, per the drag laws of physics/buoyancy.h with
    // the scene's coefficients (C_da = 1, C_d = 0.6, linear 1000 N·s/m per m²),
    //   ½ρ_a·C_da·A_air·(U − v)² = linear·A_w·v + ½ρ_w·C_d·A_w·v²,
    // A_w = π r²·f and A_air = π r²·(1 − f) (f the submerged fraction), U the wind at the ball's
    // top from the neutral log profile U10·ln(z/z0)/ln(10/z0), z0 = 2e-4 m.
    const double u10 = 20.0, r = 0.5;
    const std::string scene = "[ocean]\namplitude = 0.0\nwind_speed = 20.0\nwind_direction = [1.0, 0.0]\nresolution = 16\n[foam]\nenabled = false\n[gerstner]\ncount = 0\n"
                              "[ripples]\nenabled = false\n[currents]\nenabled = false\n[[objects]]\ntype = \"sphere\"\nradius = 0.5\ndensity = 300.0\n"
                              "position = [0, 0, 0]\n";
    game::Sandbox sandbox(game::parseScene(scene, "leeway.toml"));
    const std::vector<glm::vec3> p = track(sandbox, 60 * 40);
    const double v = (p.back().x - p[p.size() - 600].x) / 10.0;  // the last 10 s
    const game::Body& body = sandbox.world().pool<game::Body>().components()[0];
    const double f = body.submergedFraction;
    const double top = p.back().y + r;  // the surface is at 0
    const double u = u10 * std::log(std::max(top, 0.1) / 2e-4) / std::log(10.0 / 2e-4);
    const double disc = M_PI * r * r, air = 0.5 * 1.225 * 1.0 * disc * (1.0 - f), water = 0.5 * 1025.0 * 0.6 * disc * f,
                 linear = 1000.0 * disc * f;
    // air·(U − v)² = linear·v + water·v²  →  (air − water)·v² − (2·air·U + linear)·v + air·U² = 0, the root below U.
    const double qa = air - water, qb = -(2.0 * air * u + linear), qc = air * u * u;
    const double d = std::sqrt(qb * qb - 4.0 * qa * qc), r1 = (-qb - d) / (2.0 * qa), r2 = (-qb + d) / (2.0 * qa);
    const double expected = r1 > 0.0 && r1 < u ? r1 : r2;
    INFO("drift " << v << " m/s, closed form " << expected << " m/s (wind at the top " << u << ", f " << f << ")");
    CHECK(v == Approx(expected).epsilon(0.10));
    CHECK(v > 0.0);
}

TEST_CASE("the water's velocity of one FFT mode is the Airy wave's, in phase with its height, decaying as e^{kz}",
          "[water][water_motion]") {
    // h = a·cos(K·x − ω·t): u = a·ω·cos(…)·K̂ and w = a·ω·sin(…) at the surface (Airy), each
    // e^{kz} at z below the mean level (choppiness 0: an Eulerian surface, z from y = 0). The
    // maps are read bilinearly: at 32 points a wavelength that costs at most (k·Δ)²/8 = 0.5 %.
    const double k = 2.0 * M_PI / 20.0, omega = std::sqrt(G * k);
    const std::string scene = "[ocean]\npatch_size = 160.0\nresolution = 256\ncascades = 1\nchoppiness = 0.0\n"
                              "wind_speed = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n";
    game::Sandbox sandbox(game::parseScene(scene, "airy_velocity.toml"));
    auto* ocean = sandbox.world().resource<game::OceanState>();
    ocean->cpu->spectrum(0).clear();
    ocean->cpu->spectrum(0).setH0(-8, 0, {0.25f, 0.0f});  // a = 0.5 m toward +x
    ocean->water->measureWavenumbers();
    for (int i = 0; i < 3; ++i) sandbox.step();
    const water::CompositeWater& w = *ocean->water;
    double worst = 0.0, worstDeep = 0.0;
    const double a = 0.5, t = ocean->mapsTime;
    for (int i = 0; i < 40; ++i) {
        const float x = float(i) * 0.5f;
        const double theta = k * x - omega * t;
        const glm::vec3 u = w.sample(x, 3.0f).velocity;
        worst = std::max({worst, std::abs(u.x - a * omega * std::cos(theta)), std::abs(u.y - a * omega * std::sin(theta)),
                          double(std::abs(u.z))});
        const glm::vec3 deep = w.velocityAt(glm::vec3(x, -2.0f, 3.0f));
        const double decay = std::exp(-2.0 * k);
        worstDeep = std::max({worstDeep, std::abs(deep.x - decay * a * omega * std::cos(theta)),
                              std::abs(deep.y - decay * a * omega * std::sin(theta))});
    }
    INFO("largest error at the surface " << worst << ", 2 m down " << worstDeep << " m/s (a·ω = " << a * omega << ")");
    CHECK(worst < 0.01 * a * omega);
    CHECK(worstDeep < 0.01 * a * omega);
}

TEST_CASE("a single FFT mode inside a wind sea decays under the surface as e^{-k·depth}, long and short alike",
          "[water][water_motion]") {
    // One cascade (a 200 m tile of 128², a 5 m/s wind sea in it), choppiness 0 (an Eulerian
    // surface: the point y below the mean level reads e^{k·y}). A mode h = a·cos(k·x − ω·t) added
    // to the sea adds, by linearity, u = a·ω·e^{k·y}·cos(…) and w = a·ω·e^{k·y}·sin(…) to the
    // water's velocity (Airy). Taken as the difference of two oceans, with and without the mode,
    // at grid nodes (no interpolation error). One factor for the whole cascade, e^{k_c·y} with
    // k_c its velocity-weighted mean wavenumber (0.8 rad/m here), missed by 50 % to 4× (the 100 m
    // wave too slow, the 5 m wave too fast); the bands stay within 2.2 % (docs/velocity_bands.md).
    ocean::OceanDef def;
    def.resolution = 128;
    def.patch_size = 200.0f;
    def.cascades = 1;
    def.choppiness = 0.0f;
    def.wind_speed = 5.0f;
    const double a = 0.2, t = 10.0, cell = def.patch_size / def.resolution;
    for (const int index : {2, 10, 40}) {  // 100 m, 20 m and 5 m waves
        ocean::OceanFftCpu seaFft(def, 1), modeFft(def, 1);
        modeFft.spectrum(0).setH0(-index, 0, modeFft.spectrum(0).h0(-index, 0) + std::complex<float>(float(a / 2.0), 0.0f));
        modeFft.spectrum(0).setH0(index, 0, seaFft.spectrum(0).h0(index, 0));  // its partner as the sea has it
        water::CompositeWater sea({}, float(G), &seaFft), withMode({}, float(G), &modeFft);
        water::primeAt(&seaFft, sea, t);
        water::primeAt(&modeFft, withMode, t);
        const double k = 2.0 * M_PI * index / def.patch_size, omega = std::sqrt(G * k);
        for (const double depth : {1.0, 3.0}) {
            const double decay = std::exp(-k * depth);
            double worst = 0.0;
            for (int i = 0; i < 64; ++i) {
                const float x = float(i * cell);
                const glm::vec3 p(x, float(-depth), 0.0f);
                REQUIRE(sea.sample(x, 0.0f).height > p.y + 0.05f);  // the point is under the sea's surface
                const glm::vec3 u = withMode.velocityAt(p) - sea.velocityAt(p);
                const double theta = k * x - omega * t;
                worst = std::max({worst, std::abs(u.x - a * omega * decay * std::cos(theta)),
                                  std::abs(u.y - a * omega * decay * std::sin(theta)), double(std::abs(u.z))});
            }
            INFO("wavelength " << def.patch_size / index << " m, " << depth << " m down (k_c " << sea.cascadeWavenumber(0) << "): largest error " << worst
                               << " m/s against a·ω·e^{-k·depth} = " << a * omega * decay << " m/s");
            CHECK(worst < 0.05 * a * omega * decay);
        }
    }
}

// Not a test: the depth decay's error per cascade, the bands' (bandDecay) against one factor
// e^{−k_c·depth} (k_c the cascade's velocity-weighted mean wavenumber), for the default scene's
// sea (2 cascades) and the same sea in one cascade. build/bin/tests_unit "[.velocity_bands]" -s
TEST_CASE("velocity bands: the depth decay's error per cascade", "[.velocity_bands]") {
    for (const int cascades : {2, 1}) {
        ocean::OceanDef def;  // config/scenes/default.toml's [ocean]
        def.resolution = 256;
        def.patch_size = 250.0f;
        def.wind_speed = 16.0f;
        def.wind_direction = {1.0f, 0.6f};
        def.choppiness = 1.2f;
        def.cascades = cascades;
        const ocean::OceanFftCpu fft(def, 1);
        const water::CompositeWater w({}, float(G), &fft);
        for (int c = 0; c < cascades; ++c) {
            const ocean::VelocityBands& bands = fft.velocityBands(c);
            const ocean::WaveBand band = ocean::cascadeBand(def, c);
            const double dk = 2.0 * M_PI / fft.patchSize(c);
            const double lo = std::max(band.kMin, dk), hi = std::min(band.kMax, dk * (def.resolution / 2 - 1) * std::sqrt(2.0));
            std::printf("%d cascade(s), cascade %d: k %.3f–%.3f rad/m, k_c %.3f, %d bands at", cascades, c, lo, hi,
                        double(w.cascadeWavenumber(c)), bands.count);
            for (int b = 0; b < bands.count; ++b) std::printf(" %.3f", double(bands.k[size_t(b)]));
            std::printf(" rad/m\n");
            for (const double wavelength : {100.0, 5.0}) {
                const double k = 2.0 * M_PI / wavelength;
                if (k < lo || k >= hi) continue;
                std::printf("  %g m wave 1 m down: bands %+.1f %%, one factor %+.1f %%\n", wavelength,
                            100.0 * (ocean::bandDecay(bands, k, 1.0) / std::exp(-k) - 1.0),
                            100.0 * (std::exp((k - w.cascadeWavenumber(c)) * 1.0) - 1.0));
            }
            for (const double depth : {0.5, 1.0, 3.0}) {
                double rel = 0.0, abs = 0.0, relOne = 0.0, absOne = 0.0;
                for (int i = 0; i <= 400; ++i) {
                    const double k = lo * std::pow(hi / lo, i / 400.0), exact = std::exp(-k * depth);
                    const double e = std::abs(ocean::bandDecay(bands, k, depth) - exact);
                    const double eOne = std::abs(std::exp(-w.cascadeWavenumber(c) * depth) - exact);
                    abs = std::max(abs, e), absOne = std::max(absOne, eOne);
                    if (exact >= 0.05) rel = std::max(rel, e / exact), relOne = std::max(relOne, eOne / exact);
                }
                std::printf("  %.1f m down, worst over the band: bands %.1f %% (of e^{-k·d} >= 5 %%), %.3f of the surface "
                            "velocity; one factor %.0f %%, %.3f\n", depth, 100.0 * rel, abs, 100.0 * relOne, absOne);
            }
        }
    }
}

// Not a test: the probe's query cost, sample() against sampleBelow() (height + the velocity at
// depth, one inversion), on the default scene's sea; medians of 9 rounds of 20 000 points.
// build/bin/tests_unit "[.query_cost]" -s
TEST_CASE("water query cost: a probe's sample with and without its velocity", "[.query_cost]") {
    game::Sandbox sandbox(game::loadScene("config/scenes/default.toml"));
    for (int i = 0; i < 3; ++i) sandbox.step();
    const water::CompositeWater& w = *sandbox.world().resource<game::OceanState>()->water;
    std::vector<glm::vec3> points;
    for (int i = 0; i < 20000; ++i) points.push_back({float(i % 200) * 0.37f - 30.0f, -0.3f, float(i / 200) * 0.41f - 20.0f});
    const water::WaterLayers sea{.ripples = false, .currents = false};
    // One round: the thread's CPU ns per point of f over every point (a shared machine's other
    // work does not count).
    const auto cpuNs = [] {
        timespec ts;
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
    };
    const auto round = [&](auto&& f) {
        const double t0 = cpuNs();
        float sink = 0.0f;
        for (const glm::vec3& p : points) sink += f(p);
        return (cpuNs() - t0) / double(points.size()) + 0.0 * sink;
    };
    // The two alternate round by round (a shared machine's load falls on both alike); medians.
    std::vector<double> heights, boths;
    for (int r = 0; r < 9; ++r) {
        heights.push_back(round([&](glm::vec3 p) { return w.sample(p.x, p.z, sea).height; }));
        boths.push_back(round([&](glm::vec3 p) { const water::WaterSample s = w.sampleBelow(p, sea); return s.height + s.velocity.x; }));
    }
    std::sort(heights.begin(), heights.end());
    std::sort(boths.begin(), boths.end());
    const double height = heights[4], both = boths[4];
    // A measurement, not a property: printed, never asserted.
    std::printf("sample %.1f ns, sampleBelow %.1f ns: %.2fx\n", height, both, both / height);
    // The same maps without the velocity bands' (one factor e^{k_c·z} a cascade).
    ocean::OceanFftCpu& fft = *sandbox.world().resource<game::OceanState>()->cpu;
    fft.setVelocityBands(false);
    fft.update(fft.time());
    std::vector<double> ones;
    for (int r = 0; r < 9; ++r)
        ones.push_back(round([&](glm::vec3 p) { const water::WaterSample s = w.sampleBelow(p, sea); return s.height + s.velocity.x; }));
    std::sort(ones.begin(), ones.end());
    std::printf("sampleBelow without the bands %.1f ns: %.2fx\n", ones[4], ones[4] / height);
    for (int c = 0; c < sandbox.world().resource<game::OceanState>()->cpu->cascadeCount(); ++c)
        std::printf("cascade %d: tile %g m, k_c %g rad/m (a wave of %g m)\n", c,
                    double(sandbox.world().resource<game::OceanState>()->cpu->patchSize(c)), double(w.cascadeWavenumber(c)),
                    2.0 * M_PI / double(w.cascadeWavenumber(c)));
}
