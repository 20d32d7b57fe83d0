// Render interpolation (render.interpolate, docs/frame.md#render-interpolation): a display
// faster than the fixed step draws the bodies and the camera between the last two steps, so
// what it shows moves every frame at the speed the simulation moves it; the simulation itself
// does not change by a bit.
#include "sim/objects.h"
#include "world/camera.h"
#include "world/interpolation.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace ob;

namespace {

constexpr double DISPLAY_HZ = 144.0;  // the display
constexpr double STEP_HZ = 60.0;      // the steps: [sim] step_hz's default
constexpr float ORBIT_DEG_S = 30.0f;
constexpr float ORBIT_RADIUS_M = 40.0f;

// An orbit camera high above a small sea (no crest lifts it: it stays on its circle) and a
// ball falling from 20 m (in free fall for the whole second).
std::string sceneText(bool interpolate) {
    return std::string("[ocean]\nresolution = 16\n[ripples]\nresolution = 32\n[render]\ninterpolate = ") +
           (interpolate ? "true" : "false") +
           "\n[camera]\nmode = \"orbit\"\nposition = [0.0, 30.0, -40.0]\ntarget = [0.0, 0.0, 0.0]\norbit_speed_deg_s = 30.0\n"
           "[[objects]]\ntype = \"sphere\"\nname = \"ball\"\nposition = [0.0, 20.0, 0.0]\nradius = 0.5\n";
}

struct Drawn {
    std::vector<glm::vec3> eye;   // the camera's eye as each frame draws it
    std::vector<glm::vec3> ball;  // the ball's centre as each frame draws it
    std::vector<glm::vec3> latestEye;  // where the latest step left the eye
    uint64_t hash = 0;
};

// One second of frames on a fake clock at DISPLAY_HZ; what each frame draws.
Drawn drawnFrames(bool interpolate) {
    game::Sandbox sandbox(game::parseScene(sceneText(interpolate), "interpolate.toml"));
    ecs::World& world = sandbox.world();
    Drawn d;
    for (int k = 1; k <= int(DISPLAY_HZ); ++k) {
        sandbox.frame(double(k) / DISPLAY_HZ);
        const float alpha = game::drawnAlpha(world);
        d.eye.push_back(game::cameraView(world, {640, 360}, alpha).position);
        d.latestEye.push_back(game::cameraView(world, {640, 360}).position);
        const std::vector<gfx::ObjectDraw> draws = game::objectDraws(world, ecs::Entity::None, alpha);
        REQUIRE(draws.size() == 1);
        d.ball.push_back(glm::vec3(draws[0].model[3]));
    }
    d.hash = sandbox.stateHash();
    return d;
}

// The orbit turns from the second step on (its first step's clock interval is empty), so the
// eye moves from the frames drawn past it: frame i draws the clock i/144 s minus one step.
constexpr size_t MOVING = 4;

// Frames from MOVING on that draw the same point as the frame before them.
size_t repeats(const std::vector<glm::vec3>& p) {
    size_t n = 0;
    for (size_t i = MOVING; i < p.size(); ++i) n += p[i] == p[i - 1] ? 1 : 0;
    return n;
}

} // namespace

TEST_CASE("render interpolation: at 144 Hz of display and 60 Hz steps the camera and a body move every frame", "[interpolation][render]") {
    const Drawn on = drawnFrames(true);
    const Drawn off = drawnFrames(false);
    // The simulation is the same bits either way.
    CHECK(on.hash == off.hash);
    // Interpolated, no frame repeats the one before it while the orbit and the fall go on...
    CHECK(repeats(on.eye) == 0);
    CHECK(repeats(on.ball) == 0);
    // ...and the eye moves the same distance every frame: the chord of a step's arc times the
    // frame's share of a step, (60/144)·2r·sin(ωh/2) (a frame across a step bends by ωh = 0.5°).
    const double h = 1.0 / STEP_HZ, omega = glm::radians(double(ORBIT_DEG_S));
    const double perFrame = STEP_HZ / DISPLAY_HZ * 2.0 * ORBIT_RADIUS_M * std::sin(omega * h / 2.0);
    for (size_t i = MOVING; i < on.eye.size(); ++i) {
        INFO("frame " << i << ": moved " << glm::length(on.eye[i] - on.eye[i - 1]) << " m, expected " << perFrame << " m");
        CHECK(glm::length(on.eye[i] - on.eye[i - 1]) == Approx(perFrame).epsilon(0.01));
        // drawn at most one step behind the latest step
        CHECK(glm::length(on.eye[i] - on.latestEye[i]) <= perFrame * DISPLAY_HZ / STEP_HZ * 1.01);
    }
    // Negative control: drawn at the latest step, a frame that runs no step (1 − 60/144 of
    // them: 81 of the 139 compared) shows the frame before it again.
    const size_t still = repeats(off.eye);
    INFO("frames that repeat the one before, interpolation off: " << still);
    CHECK(still >= 75);
    CHECK(repeats(off.ball) >= 75);
}

TEST_CASE("render interpolation: a fixed camera looking straight down draws one view between steps and at them", "[interpolation][render]") {
    // A millimetre off the vertical from 4 m: the pitch rounds to −π/2 in float, where a look-at
    // with the world's up has no cross product (glm's quatLookAtRH gave a quaternion of length
    // 0.71 there, and the frames between steps looked 27° off the frames at them).
    game::Sandbox sandbox(game::parseScene("[ocean]\nresolution = 16\n[ripples]\nresolution = 32\n"
                                           "[camera]\nmode = \"fixed\"\nposition = [0.0, 4.0, -0.001]\ntarget = [0.0, 0.0, 0.0]\n",
                                           "down.toml"));
    ecs::World& world = sandbox.world();
    sandbox.frame(sandbox.schedule().stepSeconds());
    const glm::mat4 between = game::cameraView(world, {640, 360}, 0.5f).view;
    const glm::mat4 at = game::cameraView(world, {640, 360}, 1.0f).view;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            INFO("view[" << c << "][" << r << "]: " << between[c][r] << " between steps, " << at[c][r] << " at one");
            CHECK(between[c][r] == Approx(at[c][r]).margin(1e-6));
        }
}
