// The timeline: event validation, and the actions (fire, spawn, set_speed, set, camera,
// screenshot) run in the script phase.
#include "world/script.h"

#include "behaviours/spawning.h"

#include "world/camera.h"
#include "behaviours/cannon.h"
#include "core/log.h"
#include "core/printable.h"
#include "core/toml_reader.h"
#include "ecs/components.h"
#include "behaviours/fish.h"
#include "world/live_keys.h"
#include "world/scene.h"
#include "behaviours/ship.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace ob::game {

namespace {

// The one function through which a live key changes the running world: the timeline's `set`
// events and requestLiveSet alike, inside the fixed step's script phase (the sea's keys take
// effect at its end, finishSeaChange). The key and value are checked already.
void applyLiveSet(ecs::World& world, ScriptState& script, const std::string& key, float value) {
    SceneSettings& settings = sceneSettings(world);
    const bool sea = key.rfind("ocean.", 0) == 0 || key.rfind("gerstner.", 0) == 0;
    if (sea && !script.seaChanged) {  // the sea as the step found it, should its changes be refused
        script.seaChanged = true;
        script.oceanBefore = settings.def.ocean;
        script.gerstnerBefore = settings.def.gerstner;
    }
    // The sea's sections are handed on once per step (finishSeaChange); the others by their
    // version (settingsSystem, the view).
    settings.changed(setLiveKey(settings.def, key, value));
}

// The step's changes of [ocean] and [gerstner], all keys together: one new swell drawn and
// checked, one cross-fade. A swell that would fold (a generated wave with k·a ≥ 1) refuses the
// step's sea changes as a whole (logged), the scene keeping the sea it had.
void finishSeaChange(ecs::World& world, ScriptState& script, double now) {
    if (!script.seaChanged) return;
    script.seaChanged = false;
    SceneDef& scene = sceneSettings(world).def;
    std::vector<ocean::GerstnerWave> waves = ocean::resolveWaves(scene.gerstner, scene.ocean);
    for (size_t i = scene.gerstner.waves.size(); i < waves.size(); ++i) {
        const double ka = std::hypot(double(waves[i].kx), double(waves[i].kz)) * double(waves[i].amplitude);
        if (!(ka < 1.0)) {
            logWarn("live change of the sea refused: generated Gerstner wave %zu would fold (k·a = %.3g ≥ 1); lower "
                    "gerstner.amplitude_scale", i - scene.gerstner.waves.size(), ka);
            scene.ocean = script.oceanBefore;
            scene.gerstner = script.gerstnerBefore;
            return;
        }
    }
    changeSea(world, scene.ocean, scene.gerstner, std::move(waves), now);
}

void fireCannons(ecs::World& world, const std::string& target) {
    auto& cannons = world.pool<Cannon>();
    const ecs::Entity named = findObject(world, target);
    for (size_t k = 0; k < cannons.size(); ++k)
        if (target.empty() || cannons.entities()[k] == named) cannons.components()[k].fireRequested = true;
}

void setSpeed(ecs::World& world, const std::string& target, float speed) {
    const ecs::Entity named = findObject(world, target);
    auto& ships = world.pool<Ship>();
    for (size_t k = 0; k < ships.size(); ++k)
        if (target.empty() ? !ships.components()[k].def.player : ships.entities()[k] == named) ships.components()[k].speed = speed;
    if (named != ecs::Entity::None)
        if (FishSchool* school = world.find<FishSchool>(named)) school->speed = speed;
}

void moveCamera(ecs::World& world, const EventDef& e) {
    auto& rigs = world.pool<CameraRig>();
    for (size_t k = 0; k < rigs.size(); ++k) {
        CameraRig& rig = rigs.components()[k];
        ecs::Transform& t = world.get<ecs::Transform>(rigs.entities()[k]);
        rig.def.mode = e.mode;
        if (e.mode == CameraMode::Follow) {
            rig.def.follow = e.target;
            rig.placed = false;
        } else {
            rig.def.position = e.position;
            rig.def.target = e.look_at;
            placeCamera(rig, t, e.position, e.look_at);
        }
    }
}

void run(ecs::World& world, ScriptState& script, const EventDef& e, size_t index) {
    switch (e.action) {
    case EventAction::Fire: fireCannons(world, e.target); break;
    case EventAction::Spawn: spawnObject(world, e.object, script.seed * 7919ull + 1000000007ull + index); break;
    case EventAction::SetSpeed: setSpeed(world, e.target, e.value); break;
    case EventAction::Set: applyLiveSet(world, script, e.key, e.value); break;
    case EventAction::Camera: moveCamera(world, e); break;
    case EventAction::Screenshot: script.screenshots.push_back(e.file); break;
    }
    ++script.fired;
}

} // namespace

std::vector<std::string> validateEvents(SceneDef& scene, const std::string& source, const TomlDocument* doc) {
    std::vector<std::string> errors;
    std::set<std::string> names;
    for (const ObjectDef& o : scene.objects) names.insert(o.name);
    for (const EventDef& e : scene.events)
        if (e.action == EventAction::Spawn) names.insert(e.object.name);
    for (size_t k = 0; k < scene.events.size(); ++k) {
        const EventDef& e = scene.events[k];
        const std::string path = "events[" + std::to_string(k) + "].";
        // "file:line:column: events[k].field: " where the document has the field, else "file: …".
        const auto at = [&](const std::string& field) { return (doc ? doc->where(path + field, source) : source) + ": " + path; };
        if (e.action == EventAction::Set)
            if (std::string m = checkLiveSet(e.key, e.value); !m.empty()) errors.push_back(at(m.substr(0, m.find(':'))) + m);
        const bool named = e.action == EventAction::Fire || e.action == EventAction::SetSpeed || e.action == EventAction::Camera;
        if (named && !e.target.empty() && !names.count(e.target))
            errors.push_back(at("target") + "target: no object is named " + quotedValue(e.target));
        if (e.action == EventAction::SetSpeed && !(e.value >= 0.0f && e.value <= 100.0f))
            errors.push_back(at("value") + "value: a speed in [0, 100] m/s, got " + std::to_string(e.value));
        if (e.action == EventAction::Screenshot && e.file.empty()) errors.push_back(at("file") + "file: a screenshot needs a file name");
    }
    return errors;
}

std::string requestLiveSet(ecs::World& world, const std::string& key, float value) {
    auto* script = world.resource<ScriptState>();
    if (!script) return "no timeline in this world";
    if (std::string m = checkLiveSet(key, value); !m.empty()) return m;
    script->requested.push_back({0.0, key, value});
    return "";
}

void addScript(ecs::World& world) {
    const SceneDef& scene = sceneSettings(world).def;
    auto script = std::make_unique<ScriptState>();
    script->events = scene.events;
    std::stable_sort(script->events.begin(), script->events.end(), [](const EventDef& a, const EventDef& b) { return a.at < b.at; });
    script->seed = scene.sim.seed;
    world.setResource(std::move(script));
}

void scriptSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* script = world.resource<ScriptState>();
    if (!script) return;
    // An event runs in the step whose start time is nearest to its time.
    const double due = tick.time + 0.5 * tick.dt;
    while (script->next < script->events.size() && double(script->events[script->next].at) < due) {
        const size_t index = script->next++;
        run(world, *script, script->events[index], index);
    }
    // The changes asked for from outside the step (the UI) since the last one, in order.
    for (LiveChange& change : script->requested) {
        change.time = tick.time;
        applyLiveSet(world, *script, change.key, change.value);
        script->liveChanges.push_back(std::move(change));
    }
    script->requested.clear();
    finishSeaChange(world, *script, tick.time);
}

} // namespace ob::game
