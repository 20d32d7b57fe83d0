// Every legal value keeps bodies finite and near the water: a sweep over the legal ranges of
// what sets a body's time scales — its density (1 to 10,000 kg/m³) and size, the drags at their
// maxima, the slowest step rate, the strongest gravity, the lightest and heaviest water, a
// 1000 m/s impact, a body born inside a fixed box, the stiffest mooring — each 60 simulated s.
// Checked every step: every body finite; no floating body more than its own size plus 1 m above
// the local surface once it has touched the water (a dropped one is free until then), none
// below 100 m (there is no sea floor; a body heavier than water sinks, as it should); and the
// soak's invariants (checkSoakInvariants: bounded fields, floating bodies afloat).
#include "ecs/components.h"
#include "physics/buoyancy.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "tools/cmd_soak.h"
#include "water/composite_water.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

using namespace ob;

namespace {

// A small open sea (64 m, 32², a 6 m/s wind along +z) without ripples: the bodies' forces are what
// is swept. The bodies stand in a row across the wind, 6 m apart, each drifting in its own lane.
const std::string SEA = "[ocean]\nresolution = 32\npatch_size = 64.0\nwind_speed = 6.0\nwind_direction = [0.0, 1.0]\ncascades = 1\n"
                        "[gerstner]\ncount = 0\n"
                        "[ripples]\nenabled = false\n";

std::string sphere(float x, float y, float radius, float density, const std::string& extra = "") {
    std::ostringstream o;
    o << "[[objects]]\ntype = \"sphere\"\nposition = [" << x << ", " << y << ", 0.0]\nradius = " << radius << "\ndensity = " << density
      << "\n" << extra;
    return o.str();
}

std::string box(float x, float y, float size, float density, const std::string& extra = "") {
    std::ostringstream o;
    o << "[[objects]]\ntype = \"box\"\nposition = [" << x << ", " << y << ", 0.0]\nsize = [" << size << ", " << size << ", " << size
      << "]\ndensity = " << density << "\n" << extra;
    return o.str();
}

// How deep a sphere's centre floats (m, negative: above the surface) at density ρ_b.
float restDepth(float radius, float density, float water) {
    const float want = std::min(density / water, 1.0f) * 4.0f / 3.0f * float(M_PI) * radius * radius * radius;
    float lo = -radius, hi = radius;
    for (int k = 0; k < 40; ++k) (physics::submergedSphereVolume(radius, 0.5f * (lo + hi)) < want ? lo : hi) = 0.5f * (lo + hi);
    return 0.5f * (lo + hi);
}

// Every density of the sweep on spheres (at rest at their draft) and boxes (dropped from 2 m) of a
// few sizes, in a row along x.
std::string densityRow(float water = physics::PhysicsDef{}.water_density) {
    std::string s;
    float x = -126.0f;
    for (float density : {1.0f, 10.0f, 50.0f, 300.0f, 1000.0f, 3000.0f, 10000.0f})
        for (float size : {0.05f, 0.5f, 2.0f}) {
            s += sphere(x, -restDepth(size, density, water), size, density);
            s += box(x + 6.0f, 2.0f, size, density);
            x += 12.0f;
        }
    return s;
}

// Runs `text` for `seconds` and returns what broke ("" if nothing). `sinking`: the soak's check
// that nothing lighter than water is far under it applies (it does not where the water holds a
// body under by a legal extreme: a drag of 1e6 N·s/m per m² lets a 5 cm box rise at 0.4 mm/s; a
// 1000 m/s entry runs ln(1000)/k ≈ 7 m under a quadratic drag before it slows to 1 m/s; a 1 s
// step moves the surface a second's waves at once).
std::string sweep(const std::string& text, double seconds, const std::vector<std::string>& sets = {}, bool sinking = true) {
    game::SceneDef scene = game::parseScene(text, "extremes.toml", sets);
    game::Sandbox sandbox(scene);
    ecs::World& world = sandbox.world();
    const auto* ocean = world.resource<game::OceanState>();
    const game::SoakBounds bounds = game::soakBounds(sandbox);
    game::SoakReport report;
    std::map<uint32_t, bool> wet;
    const int steps = int(std::lround(seconds / sandbox.schedule().stepSeconds()));
    for (int step = 0; step < steps; ++step) {
        sandbox.step();
        try {
            checkSoakInvariants(sandbox, bounds, report);
        } catch (const std::exception& e) {
            if (sinking || std::string(e.what()).find("has sunk") == std::string::npos) return e.what();
        }
        auto& bodies = world.pool<game::Body>();
        for (size_t i = 0; i < bodies.size(); ++i) {
            const ecs::Entity e = bodies.entities()[i];
            const game::Body& body = bodies.components()[i];
            const glm::vec3 x = world.get<ecs::Transform>(e).position, v = world.get<ecs::Motion>(e).velocity;
            std::ostringstream where;
            where << "body " << uint32_t(e) << " at step " << step << " (" << x.x << ", " << x.y << ", " << x.z << "), v ("
                  << v.x << ", " << v.y << ", " << v.z << ")";
            if (!std::isfinite(x.x + x.y + x.z + v.x + v.y + v.z)) return "not finite: " + where.str();
            if (body.probes.empty()) continue;
            const float density = world.get<ecs::Motion>(e).mass / body.volume;
            if (density >= world.resource<game::PhysicsSettings>()->def->water_density) continue;  // it sinks, as it should
            if (x.y < -100.0f) return "below 100 m: " + where.str();
            if (body.submergedFraction > 0.0f) wet[uint32_t(e)] = true;
            if (!wet[uint32_t(e)]) continue;
            float size = 0.0f;
            for (const game::Probe& p : body.probes) size = std::max(size, glm::length(p.offset) + p.radius);
            const float surface = ocean ? ocean->water->sample(x.x, x.z, {.orbital = true}).height : 0.0f;
            if (x.y - surface > size + 1.0f) return "launched: " + where.str() + ", size " + std::to_string(size);
        }
    }
    return "";
}

} // namespace

TEST_CASE("legal extremes: densities 1 to 10,000 kg/m³ on spheres and boxes of 0.05 to 2 m stay near the water for 60 s",
          "[physics][extremes][long]") {
    CHECK(sweep(SEA + densityRow(), 60.0) == "");
}

TEST_CASE("legal extremes: the drags at their maxima, no added mass or the most, the slowest step, the strongest gravity, "
          "the lightest and heaviest water keep every body finite and near the water", "[physics][extremes][long]") {
    struct Case {
        std::vector<std::string> sets;
        bool sinking = true;
    };
    for (const Case& c : {Case{{"physics.linear_drag=1e6"}, false}, Case{{"physics.quadratic_drag=100"}}, Case{{"physics.added_mass=0"}},
                          Case{{"physics.added_mass=2", "physics.angular_damping=1"}}, Case{{"sim.step_hz=1"}, false},
                          Case{{"environment.gravity=100"}}, Case{{"environment.water_density=1"}},
                          Case{{"environment.water_density=20000"}}}) {
        std::string label;
        float water = physics::PhysicsDef{}.water_density;
        for (const std::string& s : c.sets) {
            label += s + " ";
            if (s.rfind("environment.water_density=", 0) == 0) water = std::stof(s.substr(s.find('=') + 1));
        }
        INFO(label);
        CHECK(sweep(SEA + densityRow(water), 60.0, c.sets, c.sinking) == "");
    }
}

TEST_CASE("legal extremes: a 1000 m/s impact, a body born inside a fixed box, a fixed box larger than the sea", "[physics][extremes][long]") {
    CHECK(sweep(SEA + sphere(0.0f, 20.0f, 0.3f, 500.0f, "velocity = [0.0, -1000.0, 0.0]\n") +
                    sphere(5.0f, 20.0f, 0.3f, 7800.0f, "velocity = [300.0, -1000.0, 0.0]\n"),
                60.0, {}, false) == "");
    CHECK(sweep(SEA + box(0.0f, 0.0f, 4.0f, 500.0f, "fixed = true\n") + sphere(0.0f, 0.0f, 0.5f, 500.0f) +
                    box(0.5f, 0.5f, 1.0f, 300.0f),
                60.0) == "");
    CHECK(sweep(SEA + "[[objects]]\ntype = \"box\"\nfixed = true\nposition = [0.0, -5.0, 0.0]\nsize = [1000.0, 9.0, 1000.0]\n" +
                    sphere(3.0f, 0.0f, 0.5f, 500.0f) + box(-3.0f, 0.0f, 1.0f, 300.0f),
                60.0) == "");
}

TEST_CASE("legal extremes: the stiffest mooring (game.mooring_period 0.001 s) holds targets finite", "[physics][extremes][long]") {
    const std::string scene = SEA + "[game]\nmode = \"targets\"\ntime_limit = 60.0\ntarget_prefix = \"target\"\nmooring_period = 0.001\n" +
                              "[[objects]]\ntype = \"cannon\"\nposition = [0.0, 2.0, -20.0]\n" +
                              sphere(0.0f, 0.0f, 0.5f, 400.0f, "name = \"target1\"\n") +
                              box(4.0f, 0.0f, 1.0f, 400.0f, "name = \"target2\"\n");
    CHECK(sweep(scene, 60.0) == "");
}
