// A scene: every Def of the sandbox, read from a TOML file in config/scenes/.
#pragma once
#include "world/camera.h"
#include "goals/game_def.h"
#include "world/controls.h"
#include "sim/objects.h"
#include "ecs/schedule.h"
#include "currents/currents_def.h"
#include "environment/environment_def.h"
#include "foam/foam_def.h"
#include "view_data/render_def.h"
#include "view_data/sky_def.h"
#include "interaction/ripple_def.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_def.h"
#include "platform/window_def.h"
#include "world/script.h"
#include "world/tools.h"
#include "splash/splash_def.h"
#include "core/file_identity.h"

#include <string>
#include <vector>

namespace ob::game {

/// What a scene is for.
enum class ScenePurpose : uint8_t { Play, Benchmark };
constexpr std::array<const char*, 2> names(ScenePurpose) { return {"play", "benchmark"}; }

/// What a scene is for, section [scene].
struct SceneInfoDef {
    ScenePurpose purpose = ScenePurpose::Play;  ///< "play" (a sight to play) or "benchmark" (a measurement; `play` says so)
    std::string note;              ///< one line `play` prints when it opens the scene ("" = none)
};

template <class V> void describe(V& v, SceneInfoDef& d) {
    v.field("purpose", d.purpose, "a scene to play, or a benchmark (play says so)");
    v.field("note", d.note, "one line play prints when it opens the scene");
}

/// Everything a scene file can say; every section and key is optional.
struct SceneDef {
    SceneInfoDef info;            ///< [scene]
    ecs::SimDef sim;              ///< [sim]
    environment::EnvironmentDef environment;  ///< [environment]: g, ρ, σ… every part below reads (applyEnvironment)
    platform::WindowDef window;   ///< [window]
    CameraDef camera;             ///< [camera]
    ControlsDef controls;         ///< [controls]
    ToolsDef tools;               ///< [tools]
    gfx::RenderDef render;        ///< [render]
    gfx::SkyDef sky;              ///< [sky]: the weather of the sky
    ocean::OceanDef ocean;        ///< [ocean]
    ocean::GerstnerDef gerstner;  ///< [gerstner]
    interaction::RippleDef ripples; ///< [ripples]
    physics::PhysicsDef physics;  ///< [physics]
    splash::SplashDef splash;     ///< [splash]
    foam::FoamDef foam;           ///< [foam]
    currents::CurrentsDef currents; ///< [currents]: the surface current layer
    GameDef game;                 ///< [game]: the goal
    std::vector<ObjectDef> objects; ///< [[objects]]
    std::vector<EventDef> events;   ///< [[events]]: the timeline
};

template <class V> void describe(V& v, SceneDef& s) {
    v.section("scene", s.info);
    v.section("sim", s.sim);
    v.section("environment", s.environment);
    v.section("window", s.window);
    v.section("camera", s.camera);
    v.section("controls", s.controls);
    v.section("tools", s.tools);
    v.section("render", s.render);
    v.section("sky", s.sky);
    v.section("ocean", s.ocean);
    v.section("gerstner", s.gerstner);
    v.section("ripples", s.ripples);
    v.section("physics", s.physics);
    v.section("splash", s.splash);
    v.section("foam", s.foam);
    v.section("currents", s.currents);
    v.section("game", s.game);
    v.list("objects", s.objects, "bodies, ships, cannons, fish schools");
    v.list("events", s.events, "timeline: actions at simulated times");
}

/// Copies [environment] into every part's Def that uses it (physics, ocean, ripples, splash):
/// the one place the world's constants are handed out. loadScene and the sandbox call it.
void applyEnvironment(SceneDef& scene);

/// Loads a scene file and applies `--set key.path=value` overrides (in order). Each
/// objects[i].model is resolved (absolute as is; relative: next to the scene file, then the
/// current folder, then the source tree), stored back as an absolute path, and loaded once
/// to check it. A screenshot event's `file` must be relative, stay in the scene's folder or
/// below and not be the scene; it is stored absolute (a `--set` file is kept as typed). Names
/// (camera.follow, event targets, goal objects, ripples.follow's ship) must resolve. Throws
/// ob::InputError listing every problem (file:line:column: key: message).
SceneDef loadScene(const std::string& path, const std::vector<std::string>& overrides = {});

/// The files a run of the scene reads: the scene file, every model and its far twin (the
/// keys that name them in messages; core/file_identity.h compares them with the outputs).
std::vector<NamedPath> sceneInputs(const SceneDef& scene, const std::string& scenePath);

/// The files the scene writes of its own accord: its screenshot events' (loadScene keeps
/// those of a scene file in its folder or below: docs/reliability.md#hostile-input).
std::vector<NamedPath> sceneOutputs(const SceneDef& scene);

/// As loadScene, from text (`sourceName` names it in messages; relative model paths start
/// at the current folder; event files are kept as given: the text is the program's own, the
/// editor's, or a test's).
SceneDef parseScene(const std::string& text, const std::string& sourceName, const std::vector<std::string>& overrides = {});

/// The ship the drop tool drops: the scene's first ship (its model and hull), else one with
/// the project's ship model when it is found; scripted, cruising at 3 m/s.
ObjectDef droppedShip(const SceneDef& scene);

/// The scene `play` opens with no argument: config/scenes/default.toml (from the current
/// folder if it has one, else from the source tree).
std::string defaultScenePath();

/// Checks an edited scene as a scene file would be checked (written as TOML, read back):
/// "" when valid, else the loader's messages.
std::string checkEditedScene(SceneDef& scene);

/// Writes the scene as TOML (the keys that differ from the defaults) to `path`, whole or
/// not at all, model paths relative to the file's folder; returns "" or what went wrong.
std::string saveScene(SceneDef scene, const std::string& path);

} // namespace ob::game
