// A hull's buoyancy from its own shape (physics::hullBuoyancy): the centre of buoyancy of a
// heeled wall-sided box moves as the textbook's closed forms say, and the default ship heels
// under a known moment to tan φ = M/(Δ·GM) with GM = KB + BM − KG of its box (Rawson & Tupper,
// "Basic Ship Theory" ch. 4: for a box of beam B and draft T, KB = T/2, BM = I/V = B²/(12·T);
// KG is the ship's ballasted centre of mass, cg_height·D).
#include "ecs/components.h"
#include "behaviours/ship.h"
#include "physics/buoyancy.h"
#include "sim/objects.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace ob;

namespace {

// Flat water at y = 0 under every node.
std::vector<float> flat(const physics::HullGrid& hull) { return std::vector<float>(size_t(hull.nodeCount()), 0.0f); }

} // namespace

TEST_CASE("hull hydrostatics: a heeled wall-sided box's centre of buoyancy moves by BM·tanφ across and ½BM·tan²φ up",
          "[physics][hull]") {
    physics::PhysicsDef def;
    const physics::HullGrid hull{{3.0f, 1.5f, 10.0f}, {4, 8}};
    const float draft = 0.6f, B = hull.size.x, D = hull.size.y;
    const double bm = B * B / (12.0 * draft);  // I/V = L·B³/12 / (L·B·T)
    for (float deg : {0.0f, 5.0f, 15.0f, 20.0f}) {  // wall-sided: the deck edge dry and the keel wet up to atan(2T/B) = 21.8°
        const float phi = glm::radians(deg);
        const glm::quat heel = glm::angleAxis(phi, glm::vec3(0, 0, 1));
        // The keel's centre at depth T below the waterline upright: the hull's centre at T − D/2 up.
        // Heeled about its waterline centre (the centroid of a wall-sided waterplane), the volume stays.
        const glm::vec3 centre = heel * glm::vec3(0.0f, 0.5f * D - draft, 0.0f);
        const physics::HullBuoyancy b = physics::hullBuoyancy(def, hull, centre, heel, flat(hull));
        INFO("heel " << deg << " deg");
        CHECK(b.volume == Approx(B * draft * hull.size.z).epsilon(1e-4));
        CHECK(b.force.y == Approx(def.water_density * def.gravity * b.volume).epsilon(1e-6));
        // The centre of buoyancy in the hull's frame, from the keel's centre line.
        const glm::vec3 local = glm::conjugate(heel) * (b.point - centre) + glm::vec3(0.0f, 0.5f * D, 0.0f);
        const double t = std::tan(phi);
        CHECK(-local.x == Approx(bm * t).margin(1e-4));  // towards the low side (+z heel lowers −x)
        CHECK(local.y == Approx(0.5 * draft + 0.5 * bm * t * t).margin(1e-4));
        CHECK(local.z == Approx(0.0).margin(1e-4));
    }
}

TEST_CASE("hull hydrostatics: capsized, the box floats on its deck with the same volume", "[physics][hull]") {
    physics::PhysicsDef def;
    const physics::HullGrid hull{{3.0f, 1.5f, 10.0f}, {4, 8}};
    const glm::quat over = glm::angleAxis(float(M_PI), glm::vec3(0, 0, 1));
    const physics::HullBuoyancy b = physics::hullBuoyancy(def, hull, glm::vec3(0.0f, 0.15f, 0.0f), over, flat(hull));
    CHECK(b.volume == Approx(3.0 * 10.0 * 0.6).epsilon(1e-4));  // 0.75 − 0.15 m of the (now lower) deck side wet
    CHECK(b.point.y == Approx(-0.3).margin(1e-4));
}

TEST_CASE("the default ship under a steady heeling moment heels to tan φ = M/(Δ·GM), GM the box's (within 5%)", "[ship][hull][long]") {
    game::Sandbox sandbox(game::parseScene("[ocean]\namplitude = 0.0\nresolution = 16\nwind_speed = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                           "[[objects]]\ntype = \"ship\"\nposition = [0, 0.0, 0]\nspeed = 0.0\n",
                                           "heel.toml"));
    ecs::World& world = sandbox.world();
    const ecs::Entity e = world.pool<game::Ship>().entities()[0];
    const game::ShipDef ship;  // 3 × 1.5 × 10 m, 500 kg/m³
    const double rho = physics::PhysicsDef{}.water_density, g = physics::PhysicsDef{}.gravity;
    const double B = ship.hull.x, D = ship.hull.y, L = ship.hull.z, T = D * ship.density / rho;
    const double gm = T / 2 + B * B / (12 * T) - ship.cg_height * D;  // KB + BM − KG
    const double displacement = ship.density * B * D * L * g;  // Δ, N
    const double moment = displacement * gm * std::tan(glm::radians(5.0));  // aimed at 5°
    double sum = 0.0;
    int n = 0;
    for (int step = 0; step < 1800; ++step) {  // 30 s: the roll (period ≈ 3 s) has settled under its damping
        const auto& t = world.get<ecs::Transform>(e);
        const glm::vec3 side = t.rotation * glm::vec3(1, 0, 0), deck = t.rotation * glm::vec3(0, 1, 0);
        // A couple of vertical forces ±F a beam apart: F·B = M about the keel, lowering +x (starboard).
        const glm::vec3 f = deck * float(moment / B);
        auto& body = world.get<game::Body>(e);
        body.forces.push_back({-f, t.position + side * float(0.5 * B), false});
        body.forces.push_back({f, t.position - side * float(0.5 * B), false});
        sandbox.step();
        if (step >= 1200) sum += game::rollPitchDeg(world.get<ecs::Transform>(e).rotation).x, ++n;
    }
    const double heel = std::abs(sum / n);
    INFO("GM " << gm << " m, heel " << heel << " deg (aimed at 5)");
    CHECK(std::tan(glm::radians(heel)) == Approx(moment / (displacement * gm)).epsilon(0.05));
}

TEST_CASE("the default ship, ballasted, heeled to 120° on calm water rights itself within 30 s", "[ship][hull][long]") {
    // Its righting arm GZ = (KB' − KG)-lever of its box stays positive to about 125° with
    // KG = 0.2·D (a uniform box's, KG = D/2, vanishes at 90°: it would turn turtle instead).
    game::Sandbox sandbox(game::parseScene("[ocean]\namplitude = 0.0\nresolution = 16\nwind_speed = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                           "[[objects]]\ntype = \"ship\"\nposition = [0, 0.0, 0]\nspeed = 0.0\n",
                                           "capsize.toml"));
    ecs::World& world = sandbox.world();
    const ecs::Entity e = world.pool<game::Ship>().entities()[0];
    auto& physicsWorld = *world.resource<physics::PhysicsWorld>();
    physics::BodyState s = physicsWorld.state(world.get<game::Body>(e).id);
    s.rotation = glm::angleAxis(glm::radians(120.0f), glm::vec3(0, 0, 1));
    physicsWorld.setState(world.get<game::Body>(e).id, s);
    float roll = 120.0f;
    for (int step = 0; step < 1800; ++step) {
        sandbox.step();
        roll = game::rollPitchDeg(world.get<ecs::Transform>(e).rotation).x;
    }
    INFO("roll after 30 s " << roll << " deg");
    CHECK(std::abs(roll) < 10.0f);
}
