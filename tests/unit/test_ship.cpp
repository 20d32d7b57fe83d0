// Ships: afloat and upright on the default sea; the paper's wake observation ([Kang2008]
// §V-3, fig. 16): at rest a standing deformation, slow a rebound behind the stern, five
// times faster a longer wake.
#include "ecs/components.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "world/sandbox.h"
#include "platform/platform.h"
#include "behaviours/ship.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

TEST_CASE("ships on the default sea stay afloat and upright (roll < 30 deg) for 60 simulated seconds", "[ship][long]") {
    // The default scene's sea with a coarser spectrum grid (same patch, wind and swell) and
    // no ripple patch, so the minute runs in a few seconds.
    game::SceneDef scene = game::loadScene(game::defaultScenePath(), {"ocean.resolution=64", "ripples.enabled=false"});
    game::Sandbox sandbox(scene);
    auto& ships = sandbox.world().pool<game::Ship>();
    REQUIRE(ships.size() >= 2);
    float maxRoll = 0.0f, maxPitch = 0.0f, minWet = 1.0f, lowest = 1e9f;
    for (int step = 0; step < 3600; ++step) {
        sandbox.step();
        for (size_t i = 0; i < ships.size(); ++i) {
            const ecs::Entity e = ships.entities()[i];
            const auto& t = sandbox.world().get<ecs::Transform>(e);
            glm::vec2 rp = game::rollPitchDeg(t.rotation);
            maxRoll = std::max(maxRoll, std::abs(rp.x));
            maxPitch = std::max(maxPitch, std::abs(rp.y));
            if (step > 120) minWet = std::min(minWet, sandbox.world().get<game::Body>(e).submergedFraction);
            lowest = std::min(lowest, t.position.y);
        }
    }
    INFO("max roll " << maxRoll << " deg, max pitch " << maxPitch << " deg, min submerged " << minWet << ", lowest centre " << lowest << " m");
    CHECK(maxRoll < 30.0f);
    CHECK(minWet > 0.05f);   // never thrown clear of the water
    CHECK(minWet < 0.95f);   // never under
    CHECK(lowest > -4.0f);   // the centre stays near the surface (swell of a few metres)
}

namespace {

// The field behind a ship that sailed along +z at `speed` for `seconds` on calm water, no wind
// and no current layer, as in the paper (windage would set a ship at rest drifting, and the
// current it drags along would change its speed over ground; the paper's ship setting: DF 0.96,
// six spheres SR 7, SHR 0.2, AF 0.3).
struct Wake {
    float length = 0.0f;       ///< m behind the stern where |Vh| on the track still exceeds the threshold
    float rebound = 0.0f;      ///< highest Vh within 3 m behind the stern, m (water rising where the hull left)
    float change = 0.0f;       ///< max |Vh(t) − Vh(t − 1 s)| over the patch, m
    float depth = 0.0f;        ///< deepest Vh under the hull, m (negative)
};

Wake sail(float speed, float seconds) {
    const std::string text =
        "[ocean]\namplitude = 0.0\nresolution = 16\nwind_speed = 0.0\n[gerstner]\ncount = 0\n[currents]\nenabled = false\n"
        "[ripples]\nmodel = \"kang2008\"\nresolution = 256\ncell_size = 0.2\ndamping = 0.96\n"
        "[[objects]]\ntype = \"ship\"\nposition = [0, 0.1, -20]\ndensity = 450\nspeed = " + std::to_string(speed) +
        "\nvelocity = [0, 0, " + std::to_string(speed) + "]\n";
    game::Sandbox sandbox(game::parseScene(text, "wake.toml"));
    const int steps = int(seconds * 60.0f);
    auto* patch = sandbox.world().resource<interaction::RipplePatch>();
    std::vector<float> before;
    for (int i = 0; i < steps; ++i) {
        if (i == steps - 60) before.assign(patch->solverAs<ob::interaction::Kang2008Solver>()->field().current().begin(), patch->solverAs<ob::interaction::Kang2008Solver>()->field().current().end());
        sandbox.step();
    }
    const ecs::Entity ship = sandbox.world().pool<game::Ship>().entities()[0];
    const glm::vec3 centre = sandbox.world().get<ecs::Transform>(ship).position;
    const float stern = centre.z - 0.5f * game::ShipDef{}.hull.z;
    // Threshold: 5% of the spheres' stamp depth SR·SHR·Δ (7 · 0.2 · 0.2 m).
    const float threshold = 0.05f * 7.0f * 0.2f * 0.2f;
    Wake w;
    for (float d = 0.0f; d < 45.0f; d += 0.1f) {
        float a = 0.0f;
        for (float x = -1.5f; x <= 1.5f; x += 0.1f) {
            const float h = patch->heightAt({x, stern - d});
            a = std::max(a, std::abs(h));
            if (d <= 3.0f) w.rebound = std::max(w.rebound, h);
        }
        if (a > threshold) w.length = d;
    }
    for (float z = stern; z <= stern + game::ShipDef{}.hull.z; z += 0.1f) w.depth = std::min(w.depth, patch->heightAt({0.0f, z}));
    auto now = patch->solverAs<ob::interaction::Kang2008Solver>()->field().current();
    for (size_t i = 0; i < now.size(); ++i) w.change = std::max(w.change, std::abs(now[i] - before[i]));
    REQUIRE(std::abs(sandbox.world().get<ecs::Motion>(ship).velocity.z - speed) < 0.05f * speed + 0.01f);  // held its speed
    return w;
}

} // namespace

TEST_CASE("[Kang2008] fig. 16: a ship at rest leaves a standing deformation, slow a rebound behind the stern, 5x faster a longer wake", "[ship]") {
    const Wake rest = sail(0.0f, 6.0f), slow = sail(1.0f, 6.0f), fast = sail(5.0f, 6.0f);
    INFO("wake length behind the stern (|Vh| > 1.4 cm): rest " << rest.length << " m, 1 m/s " << slow.length << " m, 5 m/s "
                                                              << fast.length << " m; rebound rest " << rest.rebound << " slow "
                                                              << slow.rebound << " m; change over 1 s at rest " << rest.change
                                                              << " m; hull hollow " << rest.depth << " m");
    // At rest: a hollow under the hull that does not move (the same field a second later)
    // and nothing behind the stern.
    CHECK(rest.depth < -0.1f);
    CHECK(rest.change < 1e-4f);
    CHECK(rest.length < 1.0f);
    // Slow: the water the hull leaves springs back up behind the stern.
    CHECK(slow.rebound > 0.005f);
    CHECK(slow.rebound > 5.0f * rest.rebound);
    CHECK(slow.length > rest.length + 0.5f);
    // Five times faster: the rebound is left behind sooner, the wake is longer.
    CHECK(fast.length > 2.0f * slow.length);
}

TEST_CASE("a ship's hull key sets its box: mass, and a draft of depth times the density ratio (Archimedes)", "[ship]") {
    // A hull twice the default in every direction, density 400 kg/m³ in water of 1025: it
    // weighs 400·(6·3·20) kg and floats at rest with 3·400/1025 m of its depth under water.
    game::Sandbox sandbox(game::parseScene("[ocean]\namplitude = 0.0\nresolution = 16\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                           "[[objects]]\ntype = \"ship\"\nposition = [0, 0.5, 0]\nspeed = 0.0\n"
                                           "density = 400.0\nhull = [6.0, 3.0, 20.0]\n",
                                           "big_hull.toml"));
    ecs::World& world = sandbox.world();
    const ecs::Entity ship = world.pool<game::Ship>().entities()[0];
    CHECK(world.get<ecs::Motion>(ship).mass == Approx(400.0 * 6 * 3 * 20).epsilon(1e-6));
    for (int i = 0; i < 1200; ++i) sandbox.step();  // 20 s: the heave has settled
    const float bottom = world.get<ecs::Transform>(ship).position.y - 1.5f;
    // The probe lattice resolves the draft to within its layer spacing's rounding (3 layers).
    CHECK(-bottom == Approx(3.0 * 400.0 / 1025.0).margin(0.05));
}

TEST_CASE("the player's ship: W opens the throttle and it settles at its top speed, D turns it to starboard", "[ship]") {
    // No wind: its leeway (about 0.1 m/s across in 10 m/s) is not what this checks.
    game::Sandbox sandbox(game::parseScene("[ocean]\namplitude = 0.0\nresolution = 16\nwind_speed = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                           "[[objects]]\ntype = \"ship\"\nplayer = true\nposition = [0, 0.1, 0]\nspeed = 6.0\n",
                                           "player.toml"));
    ecs::World& world = sandbox.world();
    // The keys go through the input queue as a window's events do, stamped in simulated time.
    auto* queue = world.resource<platform::InputQueue>();
    using T = platform::InputEvent::Type;
    const ecs::Entity ship = world.pool<game::Ship>().entities()[0];
    // Hold W for 3 s: the lever runs to full (0.5 per second).
    queue->push({T::KeyDown, 0.0, platform::Key::W});
    queue->push({T::KeyUp, 3.0, platform::Key::W});
    for (int i = 0; i < 180; ++i) sandbox.step();
    CHECK(world.get<game::Ship>(ship).throttle == 1.0f);
    for (int i = 0; i < 900; ++i) sandbox.step();
    // Thrust balances the hull's resistance at the top speed: 6 m/s along the bow (+z).
    glm::vec3 v = world.get<ecs::Motion>(ship).velocity;
    CHECK(v.z == Approx(6.0f).margin(0.15f));
    CHECK(std::abs(v.x) < 0.1f);
    // Full starboard rudder: the bow swings toward −x (starboard of a +z bow, y up) at about
    // the rudder's yaw rate, 0.21 rad/s at speed.
    queue->push({T::KeyDown, 18.0, platform::Key::D});
    const float heading0 = std::atan2(v.x, v.z);
    for (int i = 0; i < 120; ++i) sandbox.step();
    const glm::vec3 bow = world.get<ecs::Transform>(ship).rotation * glm::vec3(0, 0, 1);
    const float turned = std::atan2(bow.x, bow.z) - heading0;
    CHECK(turned < 0.0f);
    CHECK(turned / 2.0f == Approx(-0.21f).margin(0.06f));  // rad/s over the 2 s
}
