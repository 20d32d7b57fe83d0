// The timeline: event validation, and the actions (fire, spawn, set_speed, set, camera,
// screenshot) run in the script phase.
#include "world/script.h"

#include "behaviours/spawning.h"

#include "world/camera.h"
#include "behaviours/cannon.h"
#include "core/log.h"
#include "ecs/components.h"
#include "behaviours/fish.h"
#include "interaction/ripple_patch.h"
#include "world/scene.h"
#include "behaviours/ship.h"

#include <algorithm>
#include <cmath>
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

// Keys whose change reaches the running simulation (the rest are read once at start).
bool isLiveKey(const std::string& key) {
    static const std::set<std::string> PHYSICS{"physics.water_density", "physics.linear_drag", "physics.quadratic_drag",
                                               "physics.angular_damping", "physics.buoyancy_along_normal"};
    return key.rfind("render.", 0) == 0 || key.rfind("camera.", 0) == 0 || key == "ripples.damping" || PHYSICS.count(key);
}

// Checks `value` against the slot; "" when it fits.
std::string checkValue(const KeySlot& slot, float value) {
    if (slot.b) return value == 0.0f || value == 1.0f ? "" : "a switch takes 0 or 1";
    if (slot.i && value != std::floor(value)) return "this key takes an integer";
    if (!(value >= slot.limits.min && value <= slot.limits.max))
        return "value out of the key's range [" + std::to_string(slot.limits.min) + ", " + std::to_string(slot.limits.max) + "]";
    return "";
}

void setKey(ecs::World& world, ScriptState& script, const EventDef& e) {
    SceneDef& scene = *script.scene;
    KeySlot slot(e.key);
    describe(slot, scene);
    if (!slot.found()) return;  // validated at load
    if (slot.f) *slot.f = e.value;
    if (slot.i) *slot.i = int(e.value);
    if (slot.b) *slot.b = e.value != 0.0f;
    // Hand the change to the systems that keep their own copy.
    if (e.key.rfind("camera.", 0) == 0) {
        auto& rigs = world.pool<CameraRig>();
        for (size_t k = 0; k < rigs.size(); ++k) rigs.components()[k].def = scene.camera;
    }
    if (e.key == "ripples.damping")
        if (auto* patch = world.resource<interaction::RipplePatch>()) patch->setDamping(scene.ripples.damping);
    if (e.key.rfind("physics.", 0) == 0)
        if (auto* physics = world.resource<physics::PhysicsDef>()) *physics = scene.physics;
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
    case EventAction::Set: setKey(world, script, e); break;
    case EventAction::Camera: moveCamera(world, e); break;
    case EventAction::Screenshot: script.screenshots.push_back(e.file); break;
    }
    ++script.fired;
}

} // namespace

std::vector<std::string> validateEvents(SceneDef& scene, const std::string& source) {
    std::vector<std::string> errors;
    std::set<std::string> names;
    for (const ObjectDef& o : scene.objects) names.insert(o.name);
    for (const EventDef& e : scene.events)
        if (e.action == EventAction::Spawn) names.insert(e.object.name);
    for (size_t k = 0; k < scene.events.size(); ++k) {
        const EventDef& e = scene.events[k];
        const std::string where = source + ": events[" + std::to_string(k) + "].";
        if (e.action == EventAction::Set) {
            KeySlot slot(e.key);
            describe(slot, scene);
            if (!slot.found()) errors.push_back(where + "key: '" + e.key + "' is not a number or switch of the scene");
            else if (!isLiveKey(e.key))
                errors.push_back(where + "key: '" + e.key + "' is read once at start; live keys: render.*, camera.*, ripples.damping, " +
                                 "physics.water_density, physics.linear_drag, physics.quadratic_drag, physics.angular_damping, " +
                                 "physics.buoyancy_along_normal");
            else if (std::string m = checkValue(slot, e.value); !m.empty())
                errors.push_back(where + "value: " + m);
        }
        const bool named = e.action == EventAction::Fire || e.action == EventAction::SetSpeed || e.action == EventAction::Camera;
        if (named && !e.target.empty() && !names.count(e.target))
            errors.push_back(where + "target: no object is named '" + e.target + "'");
        if (e.action == EventAction::SetSpeed && !(e.value >= 0.0f && e.value <= 100.0f))
            errors.push_back(where + "value: a speed in [0, 100] m/s, got " + std::to_string(e.value));
        if (e.action == EventAction::Screenshot && e.file.empty()) errors.push_back(where + "file: a screenshot needs a file name");
    }
    return errors;
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
}

} // namespace ob::game
