// The camera the player steers: right drag orbits at a constant radius, the wheel zooms by
// its stated factor, the fly camera stops above the crests unless the player holds Q against
// the surface (then it dives), and a follow camera never goes below the water, on a rough sea;
// a ripple patch that follows the ship stays under it wherever the camera is.
#include "world/camera.h"
#include "behaviours/ship.h"
#include "interaction/ripple_patch.h"
#include "world/controls.h"
#include "ecs/components.h"
#include "world/sandbox.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

using namespace ob;
using platform::InputEvent;
using T = InputEvent::Type;

namespace {

struct Rig {
    game::CameraRig* rig;
    ecs::Transform* transform;
};

Rig camera(game::Sandbox& sandbox) {
    auto& rigs = sandbox.world().pool<game::CameraRig>();
    return {&rigs.components()[0], &sandbox.world().get<ecs::Transform>(rigs.entities()[0])};
}

float waterAt(game::Sandbox& sandbox, glm::vec3 p) {
    return sandbox.world().resource<game::OceanState>()->water->sample(p.x, p.z).height;
}

void push(game::Sandbox& sandbox, InputEvent e) { sandbox.world().resource<platform::InputQueue>()->push(e); }

} // namespace

TEST_CASE("camera: right drag orbits the target at a constant radius, the wheel zooms by 0.9 a step", "[camera]") {
    game::Sandbox sandbox(game::parseScene("[ocean]\namplitude = 0.0\nresolution = 16\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                           "[camera]\nmode = \"orbit\"\norbit_speed_deg_s = 0.0\nposition = [0, 10, -30]\n"
                                           "target = [0, 0, 0]\n",
                                           "orbit.toml"));
    const float radius = glm::length(camera(sandbox).transform->position);
    push(sandbox, {T::ButtonDown, 0.0, platform::Key::W, platform::MouseButton::Right});
    push(sandbox, {T::Move, 0.0, platform::Key::W, platform::MouseButton::Right, {100.0f, 0.0f}});
    sandbox.frame(1.0 / 60.0);
    const glm::vec3 eye = camera(sandbox).transform->position;
    // 100 px at 0.005 rad/px about the vertical: the azimuth turned by 0.5 rad, the radius kept.
    CHECK(glm::length(eye) == Approx(radius).epsilon(1e-5));
    CHECK(eye.y == Approx(10.0f).epsilon(1e-5));
    const float turned = std::atan2(eye.x, eye.z) - std::atan2(0.0f, -30.0f);
    CHECK(std::abs(std::remainder(turned, 2.0f * float(M_PI))) == Approx(0.5f).epsilon(1e-4));
    // The camera still looks at the target.
    CHECK(camera(sandbox).rig->focus == glm::vec3(0.0f));
    push(sandbox, {T::Scroll, 1.5 / 60.0, platform::Key::W, platform::MouseButton::Left, {0.0f, 2.0f}});
    sandbox.frame(2.0 / 60.0);
    CHECK(glm::length(camera(sandbox).transform->position) == Approx(radius * 0.81f).epsilon(1e-4));
}

TEST_CASE("camera: flying down stops 0.5 m above the crests, holding Q against the surface dives", "[camera]") {
    game::Sandbox sandbox(game::parseScene("[ocean]\nwind_speed = 14.0\n[camera]\nmode = \"fly\"\nposition = [0, 3, 0]\n"
                                           "target = [0, 3, 20]\n",
                                           "fly.toml"));
    push(sandbox, {T::KeyDown, 0.0, platform::Key::Q});
    bool dived = false;
    double diveTime = 0.0;
    for (int f = 1; f <= 90; ++f) {
        const double now = f / 60.0;
        sandbox.frame(now);
        const Rig c = camera(sandbox);
        const float water = waterAt(sandbox, c.transform->position);
        if (!c.rig->underwater) {
            INFO("frame " << f);
            CHECK(c.transform->position.y >= water + game::FLY_CLEARANCE_M - 1e-4f);
        } else if (!dived) {
            dived = true;
            diveTime = now;
            CHECK(c.transform->position.y < water);
        }
    }
    // 3 m at 20 m/s reaches the surface in about 0.13 s; then DIVE_HOLD_S of holding Q.
    REQUIRE(dived);
    CHECK(diveTime == Approx(0.13 + game::DIVE_HOLD_S).margin(0.1));
}

TEST_CASE("camera: a follow camera never goes below the water behind a ship on a rough sea", "[camera]") {
    game::Sandbox sandbox(game::parseScene("[ocean]\nwind_speed = 30.0\n[camera]\nmode = \"follow\"\nfollow_height_m = 0.5\n"
                                           "follow_distance_m = 6.0\n[[objects]]\ntype = \"ship\"\nplayer = true\n"
                                           "position = [0, 0.1, 0]\n",
                                           "follow.toml"));
    float lowest = 1e9f;
    for (int f = 1; f <= 240; ++f) {
        sandbox.frame(f / 60.0);
        const Rig c = camera(sandbox);
        const float clearance = c.transform->position.y - waterAt(sandbox, c.transform->position);
        lowest = std::min(lowest, clearance);
    }
    CHECK(lowest >= game::CAMERA_CLEARANCE_M - 1e-3f);
}

TEST_CASE("camera: under water a right drag tilts the orbit camera up toward the surface, above it no further than 10°", "[camera]") {
    // A drag of −400 px raises the view by 2 rad: above the water the eye stops 10° below the
    // point looked at (the view up by 10°); under water it may pass under it, to 89°.
    for (float depth : {-6.0f, 12.0f}) {
        game::Sandbox sandbox(game::parseScene("[ocean]\namplitude = 0.0\nresolution = 16\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n"
                                               "[camera]\nmode = \"orbit\"\norbit_speed_deg_s = 0.0\nposition = [0, " +
                                                   std::to_string(depth) + ", -30]\ntarget = [0, " + std::to_string(depth) + ", 0]\n",
                                               "orbit.toml"));
        push(sandbox, {T::ButtonDown, 0.0, platform::Key::W, platform::MouseButton::Right});
        push(sandbox, {T::Move, 0.0, platform::Key::W, platform::MouseButton::Right, {0.0f, -400.0f}});
        sandbox.frame(1.0 / 60.0);
        const float pitch = glm::degrees(camera(sandbox).rig->pitch);
        INFO("eye " << depth << " m: pitch " << pitch << "°");
        if (depth < 0.0f) CHECK(pitch == Approx(89.0f).margin(0.1f));
        else CHECK(pitch == Approx(10.0f).margin(0.1f));
    }
}

TEST_CASE("camera: a ripple patch with follow = \"ship\" stays under the ship while the camera stays put", "[camera][ripples]") {
    const std::string text = "[camera]\nmode = \"fixed\"\nposition = [200, 50, 0]\ntarget = [0, 0, 0]\n"
                             "[ripples]\nmodel = \"ewave\"\nresolution = 64\ncell_size = 0.5\n"
                             "[[objects]]\ntype = \"ship\"\nname = \"boat\"\nposition = [10, 0.1, -20]\nspeed = 4.0\n"
                             "waypoints = [[10, 400]]\n";
    // The patch's centre (world m) after `steps` steps, and the ship's position then.
    auto run = [&](const std::string& follow, int steps) {
        game::Sandbox sandbox(game::parseScene(text, "follow_ship.toml", {"ripples.follow=" + follow}));
        for (int s = 0; s < steps; ++s) sandbox.step();
        const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
        const glm::vec3 ship = sandbox.world().get<ecs::Transform>(sandbox.world().pool<game::Ship>().entities()[0]).position;
        const glm::vec2 centre = patch->origin() + glm::vec2(0.5f * (64 - 1) * 0.5f);
        return std::make_pair(centre, glm::vec2(ship.x, ship.z));
    };
    const auto [centre, ship] = run("ship", 600);
    REQUIRE(ship.y > 0.0f);  // it has run 20 m and more
    CHECK(glm::length(centre - ship) <= 0.75f);  // within a cell and a half (the patch scrolls in whole cells)
    const auto [fixedCentre, fixedShip] = run("fixed", 600);
    CHECK(glm::length(fixedCentre - fixedShip) > 10.0f);  // the check can fail: a fixed patch stays at [0, 0]
}
