// [environment]: every part reads the scene's g and ρ. Each law is checked against its closed
// form written here: a splash drop's ballistic flight, the Cauchy–Poisson similarity of a drop's
// rings in the ewave layer, a body's free fall, a hull's Archimedes draft; moved keys are errors.
#include "core/error.h"
#include "ecs/components.h"
#include "interaction/ewave/ewave_solver.h"
#include "interaction/ripple_patch.h"
#include "behaviours/ship.h"
#include "sim/objects.h"
#include "splash/splash_particles.h"
#include "water/water_query.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace ob;

namespace {

// The loader's message for a scene text, "" when it loads.
std::string sceneError(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
        game::parseScene(text, "env.toml", overrides);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Drops of one splash impact flown without drag over still water at y = 0 under gravity g:
// y(t) = y0 + v0·t − g·t²/2 for every drop until the first lands; the highest point any drop
// reaches is max(y0 + v0²/(2g)) (within g·dt²/8, the most a sampled parabola misses its apex
// by); by every step's end the drops with flight time T = (v0 + sqrt(v0² + 2·g·y0))/g before it
// have landed, those after it not.
void checkBallisticFlight(float g) {
    splash::SplashDef def;
    def.drag = 0.0f;
    def.max_life = 1000.0f;
    def.environment.gravity = g;
    splash::SplashParticles p(def, 7);
    splash::Impact impact;
    impact.velocity = glm::vec3(0.0f, -8.0f, 0.0f);
    impact.radius = 0.3f;
    impact.mass = 20.0f;
    const int n = p.emitImpact(impact);
    REQUIRE(n > 20);
    std::vector<double> y0(p.y().begin(), p.y().end()), v0(p.vy().begin(), p.vy().end()), landAt;
    double apex = -1e9;
    for (int i = 0; i < n; ++i) {
        REQUIRE(v0[size_t(i)] > 0.0);
        apex = std::max(apex, y0[size_t(i)] + v0[size_t(i)] * v0[size_t(i)] / (2.0 * g));
        landAt.push_back((v0[size_t(i)] + std::sqrt(v0[size_t(i)] * v0[size_t(i)] + 2.0 * g * y0[size_t(i)])) / g);
    }
    // No drop outflies the crown: H = R·sqrt(Fr) above the launch height is the fastest drop's apex.
    CHECK(apex <= *std::max_element(y0.begin(), y0.end()) + splash::crownHeight(impact, g) * (1.0 + 1e-5));
    const water::FlatWater sea(0.0f);
    const float dt = 1.0f / 240.0f;
    double highest = -1e9, t = 0.0;
    int landed = 0, checkedSteps = 0;
    while (p.size() > 0 && t < 60.0) {
        const bool allAlive = p.size() == n;
        p.step(dt, sea);
        t += double(dt);
        if (allAlive && p.landings().empty()) {
            for (int i = 0; i < n; ++i) {
                const double yTheory = y0[size_t(i)] + v0[size_t(i)] * t - 0.5 * g * t * t;
                REQUIRE(p.y()[size_t(i)] == Approx(yTheory).margin(1e-4));
            }
            ++checkedSteps;
        }
        for (float y : p.y()) highest = std::max(highest, double(y));
        landed += int(p.landings().size());
        const auto before = [&](double s) { return int(std::count_if(landAt.begin(), landAt.end(), [&](double T) { return T <= s; })); };
        INFO("g " << g << ", t " << t << " s");
        REQUIRE(landed >= before(t - 1e-4));
        REQUIRE(landed <= before(t + 1e-4));
    }
    CHECK(landed == n);
    CHECK(checkedSteps > 10);
    CHECK(highest <= apex + 1e-4);
    CHECK(highest >= apex - g * dt * dt / 8.0 - 1e-4);
    const double tMax = *std::max_element(landAt.begin(), landAt.end());
    CHECK(t == Approx(tMax).margin(dt));
}

// Zero crossings of h along the +x ray from cell (cx, cz), in metres from the centre.
std::vector<double> crossingsAlongX(const interaction::RipplePatch& patch, int cx, int cz, double cell, int stopBefore) {
    const std::span<const double> h = patch.solverAs<interaction::EWaveSolver>()->field().heightState();
    const double* row = h.data() + size_t(cz) * size_t(patch.cols());
    std::vector<double> out;
    for (int x = cx + 1; x < patch.cols() - stopBefore; ++x)
        if ((row[x] > 0.0) != (row[x + 1] > 0.0)) out.push_back((x - cx + row[x] / (row[x] - row[x + 1])) * cell);
    return out;
}

// A drop's crater, a Gaussian dip of σ = 0.03 m (smooth: it rings no grid-scale noise), at the
// centre of a 512² ewave patch of 0.02 m cells under gravity g; after t s the crossings of h = 0
// along +x (inside the absorbing band).
std::vector<double> ringsAfter(float g, double t) {
    interaction::RippleDef def;
    def.model = interaction::rippleModel("ewave");
    def.backend = Backend::Cpu;
    def.resolution = 512;
    def.cell_size = 0.02f;
    def.sponge_width = 24;
    def.decay_time = 0.0f;  // no damping: amplitudes only, but a superposition's crossings would feel them
    def.viscosity = 0.0f;
    def.environment.gravity = g;
    interaction::RipplePatch patch(def);
    const int cx = patch.cols() / 2, cz = patch.rows() / 2;
    const double sigma = 0.03;
    for (int z = cz - 8; z <= cz + 8; ++z)
        for (int x = cx - 8; x <= cx + 8; ++x) {
            const double r2 = (double(x - cx) * (x - cx) + double(z - cz) * (z - cz)) * def.cell_size * def.cell_size;
            patch.solver().addHeight(x, z, -1e-3 * std::exp(-r2 / (2.0 * sigma * sigma)));
        }
    const int steps = int(std::lround(t * 60.0));
    const float dt = float(t / steps);  // ewave's step is exact per mode for any dt
    for (int s = 0; s < steps; ++s) patch.step(dt);
    return crossingsAlongX(patch, cx, cz, def.cell_size, def.sponge_width + 8);
}

} // namespace

TEST_CASE("environment.gravity sets a splash drop's flight: y = y0 + v0 t - g t^2/2, apex, time of flight", "[environment][splash]") {
    checkBallisticFlight(9.81f);
    checkBallisticFlight(3.7f);
}

TEST_CASE("environment.gravity scales a drop's ewave rings as Cauchy-Poisson: r ~ g t^2", "[environment][ewave]") {
    // Deep-water gravity waves from a drop: the phase at radius r and time t is g·t²/(4r)
    // (stationary phase), so the pattern is self-similar in r/(g·t²): under g' at
    // t' = t·sqrt(g/g') every crossing sits where it sat under g at t. The Gaussian crater has a
    // real spectrum (no phase of its own: it sets amplitudes, not crossings), and ewave steps
    // each mode exactly, so the grid breaks the law only through the modes it cannot hold. Compared where
    // the law holds for both: resolved (k <= k_Nyquist/4), far field (k·r >= 5), and
    // capillarity small under the weaker gravity: with ε = (σ/ρ)·k²/g', ω = sqrt(g'·k)·(1 + ε/2)
    // and ω·t = 2φ, so the phase φ = g·t²/(4r) is off by about ε·φ; kept <= 0.05π. A crossing
    // must lie within a tenth of the local half wavelength π/k (0.1π of phase) of its twin;
    // under g' at the same t (the control: k is 0.38× there, crossings 2.6× as far apart) most
    // must not.
    const double g = 9.81, gLow = 3.7, t = 4.0, tLow = t * std::sqrt(g / gLow);
    const double capillarity = environment::capillarity({});
    const double q = g * t * t / 4.0;  // phase·r
    const std::vector<double> a = ringsAfter(float(g), t), b = ringsAfter(float(gLow), tLow);
    const std::vector<double> sameTime = ringsAfter(float(gLow), t);
    const auto offset = [](const std::vector<double>& list, double r) {
        double best = 1e9;
        for (double x : list) best = std::min(best, std::abs(x - r));
        return best;
    };
    int checked = 0, matchedAtSameTime = 0;
    double worst = 0.0;
    for (size_t i = 0; i + 1 < a.size(); ++i) {
        const double r = std::sqrt(a[i] * a[i + 1]), k = q / (r * r), halfWave = a[i + 1] - a[i];
        if (k > std::numbers::pi / 0.02 / 4.0 || k * r < 5.0 || capillarity * k * k / gLow * q / r > 0.05 * std::numbers::pi) continue;
        INFO("crossing at " << a[i] << " m under g = 9.81 at 4 s, k " << k << " rad/m, half wave " << halfWave << " m");
        CHECK(offset(b, a[i]) <= 0.1 * halfWave);
        worst = std::max(worst, offset(b, a[i]) / halfWave);
        matchedAtSameTime += offset(sameTime, a[i]) <= 0.1 * halfWave;
        ++checked;
    }
    INFO("ring similarity: " << checked << " crossings, worst offset " << worst << " of a half wave (measured 0.028); at the same t "
                             << matchedAtSameTime << " within 0.1 (measured 0)");
    CHECK(checked >= 5);
    CHECK(matchedAtSameTime <= checked / 3);
}

TEST_CASE("environment.gravity: a body falls y0 - g t^2/2 (symplectic Euler within g dt t/2)", "[environment][physics]") {
    for (float g : {9.81f, 3.7f}) {
        game::Sandbox sandbox(game::parseScene("[environment]\ngravity = " + std::to_string(g) +
                                               "\n[ocean]\namplitude = 0.0\nresolution = 16\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                               "[[objects]]\ntype = \"sphere\"\nposition = [0, 40, 0]\n",
                                               "fall.toml"));
        ecs::World& world = sandbox.world();
        const ecs::Entity body = world.pool<game::Body>().entities()[0];
        for (int i = 0; i < 60; ++i) sandbox.step();  // 1 s at 60 Hz, far above the water
        const double t = 1.0, dt = 1.0 / 60.0;
        INFO("g " << g);
        CHECK(world.get<ecs::Transform>(body).position.y == Approx(40.0 - 0.5 * g * t * t).margin(0.5 * g * dt * t + 1e-3));
    }
}

TEST_CASE("environment.water_density sets a hull's draft: depth times rho_hull/rho_water (Archimedes)", "[environment][physics]") {
    // The [ship] Archimedes case in water of 1500 kg/m³: 3·400/1500 m under water (1025: 1.17 m).
    game::Sandbox sandbox(game::parseScene("[environment]\nwater_density = 1500.0\n[ocean]\namplitude = 0.0\nresolution = 16\n[gerstner]\ncount = 0\n"
                                           "[ripples]\nenabled = false\n[[objects]]\ntype = \"ship\"\nposition = [0, 0.5, 0]\n"
                                           "speed = 0.0\ndensity = 400.0\nhull = [6.0, 3.0, 20.0]\n",
                                           "dense_water.toml"));
    ecs::World& world = sandbox.world();
    const ecs::Entity ship = world.pool<game::Ship>().entities()[0];
    for (int i = 0; i < 1200; ++i) sandbox.step();  // 20 s: the heave has settled
    const float bottom = world.get<ecs::Transform>(ship).position.y - 1.5f;
    CHECK(-bottom == Approx(3.0 * 400.0 / 1500.0).margin(0.05));  // the probe lattice's layer rounding, as for 1025
}

TEST_CASE("keys moved to [environment] are errors naming the new key, file, line and key", "[environment][config]") {
    const std::string p = sceneError("[physics]\ngravity = 3.7\n");
    CHECK(p.find("env.toml:2:") != std::string::npos);
    CHECK(p.find("physics.gravity: moved to environment.gravity") != std::string::npos);
    CHECK(sceneError("[physics]\nwater_density = 1000.0\n").find("physics.water_density: moved to environment.water_density") !=
          std::string::npos);
    CHECK(sceneError("[ocean]\ngravity = 9.81\n").find("ocean.gravity: moved to environment.gravity") != std::string::npos);
    CHECK(sceneError("", {"physics.gravity=3.7"}).find("physics.gravity: moved to environment.gravity") != std::string::npos);
    CHECK(sceneError("[environment]\ngravity = 3.7\nwater_density = 1000.0\nsurface_tension = 0.0728\n").empty());
    CHECK(sceneError("[environment]\ngravity = 0.0\n").find("environment.gravity") != std::string::npos);
}

TEST_CASE("[environment] reaches every part's Def when the scene is read", "[environment][config]") {
    const game::SceneDef s = game::parseScene("[environment]\ngravity = 3.7\nwater_density = 1000.0\nsurface_tension = 0.05\n", "env.toml");
    CHECK(s.physics.gravity == 3.7f);
    CHECK(s.physics.water_density == 1000.0f);
    CHECK(s.ocean.gravity == 3.7f);
    CHECK(s.ripples.environment.gravity == 3.7f);
    CHECK(s.ripples.environment.surface_tension == 0.05f);
    CHECK(s.splash.environment.gravity == 3.7f);
    CHECK(s.splash.environment.water_density == 1000.0f);
    // ewave's dispersion: ω² = g·k + (σ/ρ)·k³ with the scene's g, σ and ρ
    interaction::RipplePatch patch(s.ripples);
    const auto* ewave = patch.solverAs<interaction::EWaveSolver>();
    REQUIRE(ewave);
    const double k = 40.0;
    CHECK(ewave->field().omega(k) == Approx(std::sqrt(3.7 * k + 0.05 / 1000.0 * k * k * k)).epsilon(1e-6));
}
