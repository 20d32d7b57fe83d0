// The play loop's controls: the open scene picker holds the game (no steps, the goal clock
// stands still); the goal clock waits for the player's first input when asked; T rights a
// capsized ship on its heading; the fixed camera of targets.toml in a storm stays above the
// water under it for 60 s (its eye is held over the crests near it).
#include "ecs/components.h"
#include "goals/goals.h"
#include "physics/physics_world.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/camera.h"
#include "world/controls.h"
#include "world/righting.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/script.h"
#include "world/tools.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;
using namespace ob::game;

namespace {

// Still water, no ripples: only the objects move.
const std::string CALM = "[ocean]\nresolution = 32\namplitude = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n";

const std::string TARGETS = CALM + R"(
[game]
mode = "targets"
time_limit = 30.0
[[objects]]
type = "cannon"
name = "gun"
position = [0.0, 0.6, 0.0]
[[objects]]
type = "box"
name = "target_a"
position = [0.0, 0.2, 20.0]
size = [2.0, 1.2, 2.0]
density = 400.0
)";

void press(Sandbox& sandbox, platform::Key key, double at) {
    auto& queue = *sandbox.world().resource<platform::InputQueue>();
    queue.push({platform::InputEvent::Type::KeyDown, at, key});
    queue.push({platform::InputEvent::Type::KeyUp, at + 0.05, key});
}

} // namespace

TEST_CASE("the open scene picker holds the game: no steps run, the goal clock stands still", "[goals][input]") {
    Sandbox sandbox(parseScene(TARGETS, "targets.toml"));
    auto& controls = *sandbox.world().resource<WindowControls>();
    for (int f = 1; f <= 30; ++f) sandbox.frame(f / 60.0);
    REQUIRE(sandbox.schedule().steps() == 30);
    const double before = gameState(sandbox.world())->time;
    CHECK(before == Approx(0.5));
    controls.pickerOpen = true;
    for (int f = 31; f <= 90; ++f) sandbox.frame(f / 60.0);
    CHECK(sandbox.schedule().steps() == 30);
    CHECK(gameState(sandbox.world())->time == before);
    controls.pickerOpen = false;
    for (int f = 91; f <= 120; ++f) sandbox.frame(f / 60.0);
    CHECK(sandbox.schedule().steps() == 60);
    CHECK(gameState(sandbox.world())->time == Approx(1.0));
}

TEST_CASE("a goal clock that waits for the player reads 0 until the first input acting in the world", "[goals][input]") {
    Sandbox sandbox(parseScene(TARGETS, "targets.toml"));
    goalClockWaitsForPlayer(sandbox.world());
    press(sandbox, platform::Key::P, 0.2);  // a window key: P pauses and resumes, it does not play
    press(sandbox, platform::Key::P, 0.3);
    for (int f = 1; f <= 60; ++f) sandbox.frame(f / 60.0);
    CHECK(gameState(sandbox.world())->time == 0.0);
    CHECK_FALSE(gameState(sandbox.world())->started);
    press(sandbox, platform::Key::Left, 1.0);  // aims the cannon: the clock starts
    for (int f = 61; f <= 120; ++f) sandbox.frame(f / 60.0);
    CHECK(gameState(sandbox.world())->started);
    const double steps = double(sandbox.schedule().steps());
    CHECK(gameState(sandbox.world())->time == Approx(steps / 60.0 - gameState(sandbox.world())->startedAt));
    // Pressed at 1.0 s of clock; the 0.1 s paused put the steps 0.1 s behind it.
    CHECK(gameState(sandbox.world())->startedAt == Approx(0.9).margin(1.0 / 60.0 + 1e-6));
}

TEST_CASE("T rights a capsized ship upright on its heading, an upright ship is left alone", "[ship][input]") {
    Sandbox sandbox(parseScene(CALM + R"(
[[objects]]
type = "ship"
name = "hull"
position = [0.0, 0.3, 0.0]
yaw_deg = 30.0
)", "ship.toml"));
    ecs::World& world = sandbox.world();
    const ecs::Entity ship = findObject(world, "hull");
    REQUIRE(ship != ecs::Entity::None);
    for (int f = 1; f <= 30; ++f) sandbox.frame(f / 60.0);
    // Rolled 170° about its bow: capsized.
    ecs::Transform& t = world.get<ecs::Transform>(ship);
    const glm::quat heading = t.rotation;
    const glm::quat rolled = heading * glm::angleAxis(glm::radians(170.0f), glm::vec3(0, 0, 1));
    auto& physicsWorld = *world.resource<physics::PhysicsWorld>();
    physics::BodyState state = physicsWorld.state(world.get<Body>(ship).id);
    state.rotation = rolled;
    physicsWorld.setState(world.get<Body>(ship).id, state);
    t.rotation = rolled;
    REQUIRE(capsized(t.rotation));
    press(sandbox, platform::Key::T, 31.0 / 60.0);
    for (int f = 31; f <= 36; ++f) sandbox.frame(f / 60.0);
    const glm::quat now = world.get<ecs::Transform>(ship).rotation;
    CHECK_FALSE(capsized(now));
    CHECK((now * glm::vec3(0, 1, 0)).y > 0.95f);
    const glm::vec3 bowBefore = heading * glm::vec3(0, 0, 1), bowNow = now * glm::vec3(0, 0, 1);
    CHECK(std::atan2(bowNow.x, bowNow.z) == Approx(std::atan2(bowBefore.x, bowBefore.z)).margin(0.1));
    CHECK_FALSE(capsized(uprightOnHeading(rolled)));
}

TEST_CASE("storm: the camera of targets.toml (orbit at 0 deg/s) with the wind at the panel's maximum stays above the water under it for 60 s",
          "[camera][storm][long]") {
    Sandbox sandbox(loadScene(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/targets.toml",
                              {"ocean.wind_speed=30", "ocean.resolution=64", "ripples.enabled=false", "game.time_limit=0"}));
    ecs::World& world = sandbox.world();
    auto& rigs = world.pool<CameraRig>();
    REQUIRE(rigs.size() == 1);
    REQUIRE(rigs.components()[0].def.mode == CameraMode::Orbit);  // at 0 deg/s: a fixed eye the player may turn
    const water::WaterQuery& water = *world.resource<OceanState>()->water;
    float closest = 1e9f, highestLift = 0.0f;
    for (int step = 0; step < 3600; ++step) {
        sandbox.step();
        const glm::vec3 eye = world.get<ecs::Transform>(rigs.entities()[0]).position;
        closest = std::min(closest, eye.y - water.sample(eye.x, eye.z).height);
        highestLift = std::max(highestLift, rigs.components()[0].lift);
    }
    INFO("closest " << closest << " m above the water under it; lifted up to " << highestLift << " m");
    CHECK(closest >= CAMERA_CLEARANCE_M - 1e-3f);
}

TEST_CASE("a palette slider is a live set of a tools.* key: the recording's set replays to the same state hash", "[tools][record]") {
    const std::string text = CALM + "[tools]\ntool = \"drop\"\n";
    using T = platform::InputEvent::Type;
    // A click at the view's centre at 1.0 s drops a ball where the camera looks.
    const auto click = [](Sandbox& sandbox) {
        auto& queue = *sandbox.world().resource<platform::InputQueue>();
        queue.push({T::Move, 0.95, platform::Key::W, platform::MouseButton::Left, glm::vec2(0.0f), true, glm::vec2(640.0f, 360.0f)});
        queue.push({T::ButtonDown, 1.0, platform::Key::W, platform::MouseButton::Left, glm::vec2(0.0f), true, glm::vec2(640.0f, 360.0f)});
        queue.push({T::ButtonUp, 1.05, platform::Key::W, platform::MouseButton::Left, glm::vec2(0.0f), true, glm::vec2(640.0f, 360.0f)});
    };
    // The session: the slider released at 0.5 s (what the overlay does), then the click.
    Sandbox played(parseScene(text, "slider.toml"));
    click(played);
    for (int f = 1; f <= 30; ++f) played.frame(f / 60.0);
    REQUIRE(requestLiveSet(played.world(), "tools.ball_radius", 1.5f).empty());
    for (int f = 31; f <= 120; ++f) played.frame(f / 60.0);
    CHECK(played.world().resource<PlayerTools>()->def.ball_radius == 1.5f);
    const auto& changes = played.world().resource<ScriptState>()->liveChanges;
    REQUIRE(changes.size() == 1);  // what the recording writes as a [[set]]
    CHECK(changes[0].key == "tools.ball_radius");

    // The replay: the recorded set as a timeline `set` at its time, the same click.
    SceneDef scene = parseScene(text, "slider.toml");
    EventDef set;
    set.at = float(changes[0].time);
    set.action = EventAction::Set;
    set.key = changes[0].key;
    set.value = changes[0].value;
    scene.events.push_back(set);
    Sandbox replayed(scene);
    click(replayed);
    for (int f = 1; f <= 120; ++f) replayed.frame(f / 60.0);
    CHECK(replayed.world().resource<PlayerTools>()->def.ball_radius == 1.5f);
    CHECK(replayed.world().resource<PlayerTools>()->drops == 1);
    CHECK(replayed.stateHash() == played.stateHash());
    // Without the set, the ball is the default's: another state.
    Sandbox plain(parseScene(text, "slider.toml"));
    click(plain);
    for (int f = 1; f <= 120; ++f) plain.frame(f / 60.0);
    CHECK(plain.stateHash() != played.stateHash());
}
