// Live keys come from the schema's LIVE marks: what is marked is accepted by a run-time `set`
// and reaches the running world; what is not is refused with the loader's message. The lists
// written out here are the product's promise (the Sea panel's sliders, the keys SPEC and the
// README call read once), independent of the marks they are checked against.
#include "currents/current_layer.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "world/camera.h"
#include "world/live_keys.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/scene_settings.h"
#include "world/tools.h"

#include "core/error.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>

using namespace ob;

namespace {

std::string sceneError(const std::string& text) {
    try {
        game::parseScene(text, "bad.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool isLive(const std::string& key) {
    const std::vector<std::string> live = game::liveKeys();
    return std::find(live.begin(), live.end(), key) != live.end();
}

// A value inside the key's range (its middle; switches 1; 0 where 0 means auto).
float valueIn(const game::SceneKey& k) {
    if (k.switch_) return 1.0f;
    if (k.limits.orZero) return 0.0f;
    const bool lo = std::isfinite(k.limits.min), hi = std::isfinite(k.limits.max);
    const double v = lo && hi ? 0.5 * (k.limits.min + k.limits.max) : lo ? k.limits.min + 1.0 : hi ? k.limits.max - 1.0 : 0.0;
    return float(k.integer ? std::floor(v) : v);
}

// A value of the key's range other than `now`: valueIn's, else a quarter of the way up the range,
// else one more (switches: the other side).
float movedValue(const game::SceneKey& k, float now) {
    if (k.switch_) return now == 0.0f ? 1.0f : 0.0f;
    float v = valueIn(k);
    if (v == now && std::isfinite(k.limits.min) && std::isfinite(k.limits.max))
        v = float(k.limits.min + 0.25 * (k.limits.max - k.limits.min));
    if (k.integer) v = std::floor(v);
    return v == now ? now + 1.0f : v;
}

// The scene as the world's parts run it: each live section from what keeps it, where that is
// not the scene itself (physics is read in place; [render] and [sky] go to the view, absent here).
game::SceneDef runningScene(ecs::World& world) {
    game::SceneDef running = game::sceneSettings(world).def;
    running.camera = world.pool<game::CameraRig>().components().at(0).def;
    running.ripples = world.resource<interaction::RipplePatch>()->def();
    running.currents = world.resource<currents::CurrentLayer>()->def();
    running.physics = game::physicsDef(world);
    running.tools = world.resource<game::PlayerTools>()->def;
    running.ocean = world.resource<game::OceanState>()->def;
    running.gerstner = world.resource<game::OceanState>()->gerstner;
    return running;
}

} // namespace

TEST_CASE("the keys the Sea panel and the presets set, and every [render] key the live panel shows, are live", "[live_keys][config]") {
    for (const char* key : {"ocean.wind_speed", "ocean.wind_direction_deg", "ocean.choppiness", "gerstner.amplitude_scale",
                            "gerstner.count", "ripples.damping", "ripples.decay_time", "render.time_of_day", "render.exposure",
                            "render.grid_resolution", "render.reflections", "physics.linear_drag", "camera.fov_deg"})
        CHECK(isLive(key));
    // the live panel shows [render] through the LIVE marks: every number and switch there is marked
    for (const game::SceneKey& k : game::sceneKeys())
        if (k.path.rfind("render.", 0) == 0) CHECK(k.change == Change::Live);
}

TEST_CASE("keys that size or seed the world are not live, and a run-time set of one is refused with the live list", "[live_keys][config]") {
    for (const char* key : {"ocean.resolution", "ocean.patch_size", "ocean.cascades", "environment.gravity", "ripples.resolution",
                            "ripples.cell_size", "environment.water_density", "physics.substeps", "sim.step_hz", "window.width",
                            "splash.max_particles", "foam.resolution"}) {
        INFO(key);
        CHECK_FALSE(isLive(key));
        const std::string m = game::checkLiveSet(key, 1.0f);
        CHECK(m.rfind("key: '" + std::string(key) + "' is read once at start; live keys: ", 0) == 0);
    }
    CHECK(game::checkLiveSet("render.nope", 1.0f) == "key: 'render.nope' is not a number or switch of the scene");
}

TEST_CASE("every key marked LIVE is accepted by a run-time set and refused below its range", "[live_keys][config]") {
    size_t live = 0;
    for (const game::SceneKey& k : game::sceneKeys()) {
        INFO(k.path);
        const std::string m = game::checkLiveSet(k.path, valueIn(k));
        if (k.change != Change::Live) {
            CHECK(m.find("is read once at start") != std::string::npos);
            continue;
        }
        ++live;
        CHECK(m.empty());
        if (std::isfinite(k.limits.min) && !k.switch_)
            CHECK(game::checkLiveSet(k.path, float(k.limits.min) - 1.0f).rfind("value: ", 0) == 0);
    }
    CHECK(live > 30);  // [render], [camera], the sea's, [physics] drag, ripple damping
}

TEST_CASE("every live key, set in a running world, moves what keeps its section", "[live_keys]") {
    // One small world, every live key set in its fourth step to a value other than its own.
    const std::string text = "[ocean]\nresolution = 16\n[ripples]\nresolution = 32\n[currents]\nresolution = 16\n";
    game::SceneDef scene = game::parseScene(text, "live.toml");
    const game::SceneDef before = scene;
    std::map<std::string, float> set;
    for (const game::SceneKey& k : game::sceneKeys())
        if (k.change == Change::Live) set[k.path] = movedValue(k, *game::keyValue(before, k.path));
    // A swell that would fold is refused with all of the step's sea changes: half the waves' height.
    set["gerstner.amplitude_scale"] = 0.5f;
    set[game::WIND_DIRECTION_DEG] = 60.0f;
    set[game::CURRENT_SPEED] = 0.5f;
    set[game::CURRENT_DIRECTION_DEG] = 30.0f;  // after the speed: the uniform current is 0.5·[cos 30°, sin 30°]
    for (const std::string& key : game::liveKeys()) {
        game::EventDef e;
        e.at = 0.05;
        e.action = game::EventAction::Set;
        e.key = key;
        e.value = set.at(key);
        scene.events.push_back(e);
    }
    game::Sandbox sandbox(scene);
    ecs::World& world = sandbox.world();
    for (int k = 0; k < 6; ++k) sandbox.step();

    const game::SceneDef running = runningScene(world);
    size_t checked = 0;
    for (const game::SceneKey& k : game::sceneKeys()) {
        if (k.change != Change::Live || k.path == "ocean.wind_direction" || k.path == "currents.uniform") continue;
        INFO(k.path << ": set to " << set.at(k.path) << ", was " << *game::keyValue(before, k.path));
        CHECK(*game::keyValue(running, k.path) == Approx(set.at(k.path)));
        ++checked;
    }
    const glm::vec2 wind = running.ocean.wind_direction, current = running.currents.uniform;
    CHECK(wind.x == Approx(0.5f).margin(1e-6));
    CHECK(wind.y == Approx(std::sqrt(3.0f) / 2.0f).margin(1e-6));
    CHECK(current.x == Approx(0.5f * std::sqrt(3.0f) / 2.0f).margin(1e-6));
    CHECK(current.y == Approx(0.25f).margin(1e-6));
    CHECK(checked + 3 == game::liveKeys().size());
    // What the view takes per frame ([render], [sky]) is told by the sections' versions; the sea
    // cross-fades to its new spectrum.
    const game::SceneSettings& settings = game::sceneSettings(world);
    for (game::SceneSection section : {game::SceneSection::Render, game::SceneSection::Sky})
        CHECK(settings.version(section) > 0);
    CHECK(world.resource<game::OceanState>()->fade != nullptr);
    CHECK(&game::physicsDef(world) == &sandbox.scene().physics);
}

TEST_CASE("render.grid_resolution is 0 (auto) or in [16, 2048]: anything else is an error naming file, line and key", "[live_keys][config]") {
    CHECK(sceneError("[render]\ngrid_resolution = 0\n").empty());
    CHECK(sceneError("[render]\ngrid_resolution = 16\n").empty());
    CHECK(sceneError("[render]\ngrid_resolution = 2048\n").empty());
    CHECK(sceneError("[render]\ngrid_resolution = 8\n") == "bad.toml:2:19: render.grid_resolution: must be 0 (auto) or in [16, 2048], got 8");
    CHECK(sceneError("[render]\ngrid_resolution = 2049\n").find("render.grid_resolution: must be 0 (auto) or in [16, 2048]") != std::string::npos);
    CHECK(sceneError("[render]\ngrid_resolution = -1\n").find("render.grid_resolution") != std::string::npos);
    CHECK(game::checkLiveSet("render.grid_resolution", 15.0f) == "value: value out of the key's range: 0 (auto) or in [16, 2048] (render.grid_resolution)");
    CHECK(game::checkLiveSet("render.grid_resolution", 0.0f).empty());
}
