// The scene timeline ([[events]]): each action runs in the step nearest its time, in order,
// and changes what it names.
#include "world/camera.h"
#include "behaviours/cannon.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "world/sandbox.h"
#include "world/script.h"
#include "behaviours/ship.h"

#include <catch2/catch.hpp>

using namespace ob;

namespace {

const char* TIMELINE = R"(
[ocean]
amplitude = 0.0
resolution = 16
[gerstner]
count = 0
[ripples]
resolution = 64
cell_size = 0.2
[[objects]]
type = "ship"
name = "boat"
position = [0.0, 0.1, 0.0]
speed = 0.0
[[objects]]
type = "cannon"
name = "gun"
position = [0.0, 5.0, -20.0]
[[events]]
at = 1.0
action = "spawn"
object = { type = "sphere", name = "buoy", position = [3.0, 1.0, 3.0], radius = 0.4 }
[[events]]
at = 0.5
action = "set_speed"
target = "boat"
value = 3.0
[[events]]
at = 1.5
action = "fire"
target = "gun"
[[events]]
at = 2.0
action = "set"
key = "ripples.damping"
value = 0.9
[[events]]
at = 2.0
action = "set"
key = "render.exposure"
value = 2.5
[[events]]
at = 2.5
action = "camera"
mode = "fixed"
position = [10.0, 3.0, 0.0]
look_at = [0.0, 0.0, 0.0]
[[events]]
at = 3.0
action = "camera"
mode = "follow"
target = "boat"
)";

} // namespace

TEST_CASE("timeline: events run in the step nearest their time and act on the objects they name", "[events]") {
    game::Sandbox sandbox(game::parseScene(TIMELINE, "timeline.toml"));
    ecs::World& world = sandbox.world();
    auto stepTo = [&](double seconds) {
        while (sandbox.schedule().simTime() < seconds - 1e-9) sandbox.step();
    };
    const ecs::Entity boat = game::findObject(world, "boat");
    REQUIRE(boat != ecs::Entity::None);
    stepTo(0.5);  // steps 0..29 ran: the set_speed at 0.5 s (step 30) has not
    CHECK(world.get<game::Ship>(boat).speed == 0.0f);
    sandbox.step();
    CHECK(world.get<game::Ship>(boat).speed == 3.0f);
    stepTo(1.0);
    CHECK(game::findObject(world, "buoy") == ecs::Entity::None);
    sandbox.step();
    const ecs::Entity buoy = game::findObject(world, "buoy");
    REQUIRE(buoy != ecs::Entity::None);
    CHECK(world.get<game::ObjectTag>(buoy).type == game::ObjectType::Sphere);
    stepTo(1.5);
    CHECK(world.pool<game::Cannon>().components()[0].shots == 0);
    sandbox.step();
    CHECK(world.pool<game::Cannon>().components()[0].shots == 1);
    CHECK(world.pool<game::Cannonball>().size() == 1);
    stepTo(2.1);
    CHECK(world.resource<interaction::RipplePatch>()->def().damping == 0.9f);
    CHECK(sandbox.scene().render.exposure == 2.5f);
    stepTo(2.6);
    const auto& rig = world.pool<game::CameraRig>().components()[0];
    CHECK(rig.def.mode == game::CameraMode::Fixed);
    CHECK(world.get<ecs::Transform>(world.pool<game::CameraRig>().entities()[0]).position == glm::vec3(10, 3, 0));
    stepTo(3.1);
    // The camera moves once per frame (the render phase), not per step: one frame's update.
    game::cameraSystem(world, ecs::Tick{sandbox.schedule().simTime(), 1.0 / 60.0, sandbox.schedule().steps(), 0.0});
    CHECK(rig.def.mode == game::CameraMode::Follow);
    CHECK(rig.focus.z > world.get<ecs::Transform>(boat).position.z);  // looks ahead of the boat
    CHECK(world.resource<game::ScriptState>()->fired == 7);
    // The boat took up its new speed (3 m/s, within the engine's settling).
    CHECK(world.get<ecs::Motion>(boat).velocity.z > 2.0f);
}

TEST_CASE("pause: frames run no simulation steps, each step request runs exactly one", "[events]") {
    game::Sandbox sandbox(game::parseScene(TIMELINE, "timeline.toml"));
    auto* control = sandbox.world().resource<ecs::SimControl>();
    REQUIRE(control);
    for (int f = 0; f < 3; ++f) sandbox.frame(f / 60.0);
    const uint64_t before = sandbox.schedule().steps();
    CHECK(before == 3);
    control->paused = true;
    for (int f = 3; f < 10; ++f) sandbox.frame(f / 60.0);
    CHECK(sandbox.schedule().steps() == before);
    control->stepRequests = 2;
    sandbox.frame(10 / 60.0);
    CHECK(sandbox.schedule().steps() == before + 2);
    CHECK(control->stepRequests == 0);
    control->paused = false;
    sandbox.frame(11 / 60.0);
    sandbox.frame(12 / 60.0);
    CHECK(sandbox.schedule().steps() == before + 4);  // one step per frame again: the paused time is not caught up
}
