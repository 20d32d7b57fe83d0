// Buoyancy: Archimedes on sphere caps (checked against the cap formula's limits and a
// numerical integral) and floating equilibria of simulated bodies (draft = density ratio).
#include "ecs/components.h"
#include "sim/objects.h"
#include "physics/buoyancy.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

TEST_CASE("submerged sphere volume: 0 above, half at the centre, whole below, equal to a slice integral between", "[physics]") {
    const float r = 0.7f;
    const float full = 4.0f / 3.0f * float(M_PI) * r * r * r;
    CHECK(physics::submergedSphereVolume(r, -r - 0.01f) == 0.0f);
    CHECK(physics::submergedSphereVolume(r, 0.0f) == Approx(full / 2).epsilon(1e-6));
    CHECK(physics::submergedSphereVolume(r, r + 0.3f) == Approx(full).epsilon(1e-6));
    for (float depth : {-0.5f, -0.2f, 0.1f, 0.45f}) {
        // Integrate π (r² − y²) dy for y from −r up to the surface at y = depth (centre at 0).
        double v = 0.0, dy = 1e-5;
        for (double y = -r; y < std::min(double(depth), double(r)); y += dy) v += M_PI * (r * r - (y + dy / 2) * (y + dy / 2)) * dy;
        CHECK(physics::submergedSphereVolume(r, depth) == Approx(v).epsilon(1e-4));
    }
}

TEST_CASE("a probe at rest feels rho g V up, drag opposes motion relative to the water", "[physics]") {
    physics::PhysicsDef def;
    physics::ProbeState p;
    p.radius = 0.5f;
    p.centre = glm::vec3(0.0f, -2.0f, 0.0f);  // fully under
    physics::ProbeForce f = physics::probeForce(def, p);
    const float volume = 4.0f / 3.0f * float(M_PI) * 0.125f;
    CHECK(f.force.y == Approx(def.water_density * def.gravity * volume).epsilon(1e-5));
    CHECK(f.submergedFraction == Approx(1.0f));
    // The drag is the damping D = b − C·v the body's implicit solve takes (implicitDamping).
    const auto drag = [&](const physics::ProbeForce& g) { return g.dampingTarget - g.damping * p.velocity; };
    p.velocity = glm::vec3(0.0f, -1.0f, 0.0f);
    CHECK(drag(physics::probeForce(def, p)).y > 0.0f);  // sinking: drag pushes up
    p.waterVelocity = glm::vec3(0.0f, -1.0f, 0.0f);     // moving with the water: no drag
    CHECK(drag(physics::probeForce(def, p)).y == Approx(0.0f).margin(1e-4));
    CHECK(physics::probeForce(def, p).force.y == Approx(f.force.y).epsilon(1e-5));
}

namespace {

// Runs a scene of one body on calm water (no waves, no ripples) for `steps`; returns it. The
// calm sea's grid is the smallest (its heights are 0 at any size) and it has no foam to draw.
game::Body settle(const std::string& object, int steps, glm::vec3* position = nullptr) {
    game::SceneDef scene = game::parseScene(
        "[ocean]\namplitude = 0.0\nresolution = 16\n[foam]\nenabled = false\n[ripples]\nenabled = false\n[[objects]]\n" + object,
        "float.toml");
    game::Sandbox sandbox(scene);
    for (int i = 0; i < steps; ++i) sandbox.step();
    auto& bodies = sandbox.world().pool<game::Body>();
    REQUIRE(bodies.size() == 1);
    if (position) *position = sandbox.world().get<ecs::Transform>(bodies.entities()[0]).position;
    return bodies.components()[0];
}

} // namespace

TEST_CASE("Archimedes: a floating sphere settles with the submerged fraction equal to its density ratio", "[physics]") {
    for (float density : {300.0f, 500.0f, 800.0f}) {
        glm::vec3 pos;
        game::Body b = settle("type = \"sphere\"\nradius = 0.5\nposition = [0, 0.4, 0]\ndensity = " + std::to_string(density) + "\n",
                              1800, &pos);
        INFO("density " << density << " centre y " << pos.y);
        CHECK(b.submergedFraction == Approx(density / 1025.0f).margin(0.01));
    }
}

TEST_CASE("Archimedes: a floating box's draft is its density ratio times its height, a dense one sinks", "[physics]") {
    glm::vec3 pos;
    settle("type = \"box\"\nsize = [2.0, 1.0, 1.5]\nposition = [0, 1.0, 0]\ndensity = 400.0\n", 1800, &pos);
    // Draft d = 1.0 m · 400 / 1025: the centre sits at (1.0 / 2 − d) above the water.
    CHECK(pos.y == Approx(0.5f - 400.0f / 1025.0f).margin(0.03));
    settle("type = \"sphere\"\nradius = 0.3\nposition = [0, 0.0, 0]\ndensity = 2000.0\n", 300, &pos);
    CHECK(pos.y < -3.0f);
}
