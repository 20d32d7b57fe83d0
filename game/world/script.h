// The scene's timeline ([[events]]): actions at simulated times, run first in the script
// phase, so a scene plays the same headless and in a window.
#pragma once
#include "core/schema.h"
#include "ecs/schedule.h"
#include "sim/objects.h"
#include "world/camera.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_def.h"

#include <string>
#include <vector>

namespace ob {
class TomlDocument;
}

namespace ob::game {

struct SceneDef;

/// What an event does.
enum class EventAction : uint8_t {
    Fire,        ///< fires a cannon (`target`) or every cannon
    Spawn,       ///< adds `object`
    SetSpeed,    ///< sets a ship's or fish school's speed (`target`, `value`)
    Set,         ///< sets a live scene key (`key`, `value`)
    Camera,      ///< moves the camera (`mode`, `position`, `look_at`, `target`)
    Screenshot,  ///< writes the next frame to `file`
};
constexpr std::array<const char*, 6> names(EventAction) { return {"fire", "spawn", "set_speed", "set", "camera", "screenshot"}; }

/// One [[events]] entry: `action` at `at` seconds; the other keys are read by the actions
/// that name them.
struct EventDef {
    float at = 0.0f;                    ///< simulated time, s, [0, 1e6]; runs in the step that starts nearest to it
    EventAction action = EventAction::Fire;  ///< fire | spawn | set_speed | set | camera | screenshot
    std::string target;                 ///< fire: cannon ("" = every cannon); set_speed: ship or fish school ("" = every scripted
                                        ///< ship); camera: object to follow
    std::string key;                    ///< set: a live scene key (the keys marked LIVE: world/live_keys.h)
    float value = 0.0f;                 ///< set_speed: m/s; set: the key's new value (switches: 0 or 1; ocean.wind_direction_deg: degrees)
    CameraMode mode = CameraMode::Orbit;  ///< camera: "fixed", "orbit", "fly" or "follow"
    glm::vec3 position{0.0f, 6.0f, -40.0f};  ///< camera: eye, world m (fixed, orbit, fly)
    glm::vec3 look_at{0.0f};            ///< camera: point looked at, world m (fixed, orbit, fly)
    std::string file = "event.png";     ///< screenshot: PNG written after the frame that follows (window or headless)
    ObjectDef object;                   ///< spawn: the object, as an [[objects]] entry
};

template <class V> void describe(V& v, EventDef& d) {
    v.field("at", d.at, range(0, 1e6), "simulated time of the action (s)");
    v.field("action", d.action, "what happens");
    v.field("target", d.target, "object name: the cannon fired, ship or school sped, object followed");
    v.field("key", d.key, "set: live scene key, e.g. render.exposure, ocean.wind_speed or ripples.damping");
    v.field("value", d.value, any(), "set_speed: m/s; set: the new value");
    v.field("mode", d.mode, "camera: mode");
    v.field("position", d.position, any(), "camera: eye (world m)");
    v.field("look_at", d.look_at, any(), "camera: point looked at (world m)");
    v.field("file", d.file, "screenshot: PNG path");
    v.section("object", d.object);
}

/// A live change of one key (a `set`), as requested or applied.
struct LiveChange {
    double time = 0.0;  ///< start time of the step that applied it, s (0 while queued)
    std::string key;    ///< a live key (world/live_keys.h)
    float value = 0.0f; ///< its new value
};

/// The timeline's state (a resource of the world).
struct ScriptState {
    std::vector<EventDef> events;          ///< stable-sorted by time
    size_t next = 0;                       ///< first event not yet run
    uint64_t seed = 1;                     ///< feeds spawned objects
    std::vector<std::string> screenshots;  ///< PNGs asked for since the last frame was drawn
    int fired = 0;                         ///< events run so far
    std::vector<LiveChange> requested;     ///< requestLiveSet calls not yet applied (the next step applies them, in order)
    /// Every requestLiveSet change applied, in order, stamped with the start time of its step:
    /// as `set` events at those times they replay the session (the timeline's own `set`
    /// events are not listed: the scene holds them).
    std::vector<LiveChange> liveChanges;
    bool seaChanged = false;               ///< an [ocean] or [gerstner] key was set in this step (applied at its script phase's end)
    ocean::OceanDef oceanBefore;           ///< [ocean] as the step found it (restored if the step's sea is refused)
    ocean::GerstnerDef gerstnerBefore;     ///< [gerstner] likewise
};

/// Checks what the reader cannot: `set` keys are live numeric keys with values in range,
/// targets name objects of the scene (or spawned by it). One message per problem, prefixed
/// with where the field is written ("file:line:column", from `doc` when given) or `source`.
std::vector<std::string> validateEvents(SceneDef& scene, const std::string& source, const TomlDocument* doc = nullptr);
/// Asks for a live change from outside the fixed step (the UI): checked (world/live_keys.h), queued,
/// applied at the start of the next step's script phase, after that step's timeline events,
/// through the same function as a `set` event, and logged in ScriptState::liveChanges. Returns
/// "" or why it was refused (nothing is queued then).
std::string requestLiveSet(ecs::World& world, const std::string& key, float value);
/// Creates the timeline resource from the world's scene (world/scene_settings.h).
void addScript(ecs::World& world);
/// Script phase, first: runs every event due in this step, in order, then the queued
/// requestLiveSet changes.
void scriptSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
