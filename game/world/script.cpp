// The timeline: event validation, and the actions (fire, spawn, set_speed, set, camera,
// screenshot) run in the script phase.
#include "world/script.h"

#include "behaviours/spawning.h"

#include "world/camera.h"
#include "behaviours/cannon.h"
#include "core/log.h"
#include "core/toml_reader.h"
#include "ecs/components.h"
#include "behaviours/fish.h"
#include "interaction/ripple_patch.h"
#include "world/scene.h"
#include "behaviours/ship.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace ob::game {

namespace {

// Finds a number or switch of the scene by key path ("render.exposure") through describe().
struct KeySlot {
    explicit KeySlot(std::string key) : wanted(std::move(key)) {}
    std::string wanted;
    std::string prefix;
    float* f = nullptr;
    int* i = nullptr;
    bool* b = nullptr;
    Limits limits;

    bool match(const char* key) const { return prefix + key == wanted; }
    void field(const char* key, bool& v, const char*) {
        if (match(key)) b = &v;
    }
    void field(const char* key, int& v, Limits l, const char*) {
        if (match(key)) i = &v, limits = l;
    }
    void field(const char* key, float& v, Limits l, const char*) {
        if (match(key)) f = &v, limits = l;
    }
    void field(const char*, uint64_t&, const char*) {}
    void field(const char*, glm::vec2&, Limits, const char*) {}
    void field(const char*, glm::vec3&, Limits, const char*) {}
    void field(const char*, std::string&, const char*) {}
    template <NamedEnum E> void field(const char*, E&, const char*) {}
    void field(const char*, std::vector<glm::vec2>&, Limits, const char*) {}
    template <class Def> void section(const char* key, Def& def) {
        const std::string saved = prefix;
        prefix += std::string(key) + ".";
        describe(*this, def);
        prefix = saved;
    }
    template <class Item> void list(const char*, std::vector<Item>&, const char*) {}
    template <class Def> void fields(Def&) {}
    bool found() const { return f || i || b; }
};

// Keys whose change reaches the running world (the rest are read once at start). The sea's
// keys cross-fade (changeSea); ripple damping and physics keys apply from the next step.
const std::set<std::string> LIVE_KEYS{
    "physics.water_density", "physics.linear_drag", "physics.quadratic_drag", "physics.angular_damping",
    "physics.buoyancy_along_normal", "ripples.damping", "ripples.decay_time", "ripples.viscosity",
    "ocean.wind_speed", "ocean.amplitude", "ocean.choppiness", "ocean.small_wave_cutoff", "ocean.fetch",
    "ocean.peak_enhancement", "gerstner.amplitude_scale", "gerstner.count"};

// A live-only key: the wind's heading in degrees, counter-clockwise from +x toward +z (a `set`
// carries one number; ocean.wind_direction is a vector). It writes ocean.wind_direction =
// [cos, sin].
constexpr const char* WIND_DIRECTION_DEG = "ocean.wind_direction_deg";
constexpr double WIND_DIRECTION_LIMIT = 3600.0;

bool isLiveKey(const std::string& key) {
    return key.rfind("render.", 0) == 0 || key.rfind("camera.", 0) == 0 || LIVE_KEYS.count(key) || key == WIND_DIRECTION_DEG;
}

// Checks `value` against the slot; "" when it fits.
std::string checkValue(const KeySlot& slot, float value) {
    if (slot.b) return value == 0.0f || value == 1.0f ? "" : "a switch takes 0 or 1";
    if (slot.i && value != std::floor(value)) return "this key takes an integer";
    if (!(value >= slot.limits.min && value <= slot.limits.max))
        return "value out of the key's range [" + std::to_string(slot.limits.min) + ", " + std::to_string(slot.limits.max) + "]";
    return "";
}

// The one function through which a live key changes the running world: the timeline's `set`
// events and requestLiveSet alike, inside the fixed step's script phase (the sea's keys take
// effect at its end, finishSeaChange). The key and value are checked already.
void applyLiveSet(ecs::World& world, ScriptState& script, const std::string& key, float value) {
    SceneDef& scene = *script.scene;
    const bool sea = key.rfind("ocean.", 0) == 0 || key.rfind("gerstner.", 0) == 0;
    if (sea && !script.seaChanged) {  // the sea as the step found it, should its changes be refused
        script.seaChanged = true;
        script.oceanBefore = scene.ocean;
        script.gerstnerBefore = scene.gerstner;
    }
    if (key == WIND_DIRECTION_DEG) {
        const double rad = double(value) * std::numbers::pi / 180.0;
        scene.ocean.wind_direction = {float(std::cos(rad)), float(std::sin(rad))};
    } else {
        KeySlot slot(key);
        describe(slot, scene);
        if (!slot.found()) return;  // checked before
        if (slot.f) *slot.f = value;
        if (slot.i) *slot.i = int(value);
        if (slot.b) *slot.b = value != 0.0f;
    }
    // Hand the change to the systems that keep their own copy (the sea: once per step,
    // finishSeaChange).
    if (key.rfind("camera.", 0) == 0) {
        auto& rigs = world.pool<CameraRig>();
        for (size_t k = 0; k < rigs.size(); ++k) rigs.components()[k].def = scene.camera;
    }
    if (key.rfind("ripples.", 0) == 0)
        if (auto* patch = world.resource<interaction::RipplePatch>())
            patch->setDamping(scene.ripples.damping, scene.ripples.decay_time, scene.ripples.viscosity);
    if (key.rfind("physics.", 0) == 0)
        if (auto* physics = world.resource<physics::PhysicsDef>()) *physics = scene.physics;
}

// The step's changes of [ocean] and [gerstner], all keys together: one new swell drawn and
// checked, one cross-fade. A swell that would fold (a generated wave with k·a ≥ 1) refuses the
// step's sea changes as a whole (logged), the scene keeping the sea it had.
void finishSeaChange(ecs::World& world, ScriptState& script, double now) {
    if (!script.seaChanged) return;
    script.seaChanged = false;
    SceneDef& scene = *script.scene;
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
        if (target.empty() ? !ships.components()[k].player : ships.entities()[k] == named) ships.components()[k].speed = speed;
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
            if (std::string m = checkLiveSet(scene, e.key, e.value); !m.empty()) errors.push_back(at(m.substr(0, m.find(':'))) + m);
        const bool named = e.action == EventAction::Fire || e.action == EventAction::SetSpeed || e.action == EventAction::Camera;
        if (named && !e.target.empty() && !names.count(e.target))
            errors.push_back(at("target") + "target: no object is named '" + e.target + "'");
        if (e.action == EventAction::SetSpeed && !(e.value >= 0.0f && e.value <= 100.0f))
            errors.push_back(at("value") + "value: a speed in [0, 100] m/s, got " + std::to_string(e.value));
        if (e.action == EventAction::Screenshot && e.file.empty()) errors.push_back(at("file") + "file: a screenshot needs a file name");
    }
    return errors;
}

std::string liveKeyHelp() {
    std::string keys = "render.*, camera.*, " + std::string(WIND_DIRECTION_DEG);
    for (const std::string& k : LIVE_KEYS) keys += ", " + k;
    return keys;
}

std::string checkLiveSet(SceneDef& scene, const std::string& key, float value) {
    if (key == WIND_DIRECTION_DEG)
        return std::abs(value) <= WIND_DIRECTION_LIMIT
                   ? ""
                   : "value: " + key + " takes degrees in [-3600, 3600], got " + std::to_string(value);
    KeySlot slot(key);
    describe(slot, scene);
    if (!slot.found()) return "key: '" + key + "' is not a number or switch of the scene";
    if (!isLiveKey(key)) return "key: '" + key + "' is read once at start; live keys: " + liveKeyHelp();
    if (std::string m = checkValue(slot, value); !m.empty()) return "value: " + m + " (" + key + ")";
    return "";
}

std::string requestLiveSet(ecs::World& world, const std::string& key, float value) {
    auto* script = world.resource<ScriptState>();
    if (!script) return "no timeline in this world";
    if (std::string m = checkLiveSet(*script->scene, key, value); !m.empty()) return m;
    script->requested.push_back({0.0, key, value});
    return "";
}

void addScript(ecs::World& world, SceneDef& scene) {
    auto script = std::make_unique<ScriptState>();
    script->scene = &scene;
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
