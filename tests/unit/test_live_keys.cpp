// Live keys come from the schema's LIVE marks: what is marked is accepted by a run-time `set`
// and reaches the running world; what is not is refused with the loader's message. The lists
// written out here are the product's promise (the Sea panel's sliders, the keys SPEC and the
// README call read once), independent of the marks they are checked against.
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "world/camera.h"
#include "world/live_keys.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/scene_settings.h"

#include "core/error.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
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

TEST_CASE("a live set reaches what keeps the section: physics in place, the ripple patch and camera by version", "[live_keys]") {
    const std::string text = "[ocean]\nresolution = 16\n[ripples]\nresolution = 32\n[[events]]\nat = 0.1\naction = \"set\"\n"
                             "key = \"physics.linear_drag\"\nvalue = 1200\n[[events]]\nat = 0.1\naction = \"set\"\n"
                             "key = \"ripples.damping\"\nvalue = 0.9\n[[events]]\nat = 0.1\naction = \"set\"\n"
                             "key = \"camera.fov_deg\"\nvalue = 75\n";
    game::Sandbox sandbox(game::parseScene(text, "live.toml"));
    ecs::World& world = sandbox.world();
    const game::SceneSettings& settings = game::sceneSettings(world);
    CHECK(settings.version(game::SceneSection::Physics) == 0);
    for (int k = 0; k < 12; ++k) sandbox.step();
    CHECK(settings.version(game::SceneSection::Physics) == 1);
    CHECK(settings.version(game::SceneSection::Ripples) == 1);
    CHECK(settings.version(game::SceneSection::Camera) == 1);
    CHECK(settings.version(game::SceneSection::Render) == 0);
    CHECK(game::physicsDef(world).linear_drag == 1200.0f);  // the physics system reads the scene's section itself
    CHECK(&game::physicsDef(world) == &sandbox.scene().physics);
    CHECK(world.resource<interaction::RipplePatch>()->def().damping == 0.9f);
    CHECK(world.pool<game::CameraRig>().components()[0].def.fov_deg == 75.0f);
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
