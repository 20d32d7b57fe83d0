// The player's controls: the frame's keys (pause P, step N, screenshot F12, overlay H, restart
// R, quit Esc) and the simulation's input (held keys and presses, per fixed step; camera mode C).
#pragma once
#include "behaviours/step_input.h"
#include "core/schema.h"
#include "ecs/schedule.h"
#include "platform/input.h"
#include "sim/objects.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ob::game {

/// What the player's keys make, section [controls]: the fish school F spawns at the
/// camera's focus (swimming on a circle; a fish_school object's keys).
struct ControlsDef {
    int fish_count = 12;                         ///< fish in the school, [1, 10000]
    float fish_radius = 6.0f;                    ///< radius of the circle they swim on, m, [0.5, 1000]
    float fish_speed = 3.0f;                     ///< swimming speed, m/s, [0, 100]
    float fish_jump_interval = 2.0f;             ///< mean time between one fish's jumps, s, [0.1, 1e6]
    float fish_length = 0.7f;                    ///< body length, m, [0.01, 100]
    glm::vec3 fish_color{0.55f, 0.6f, 0.65f};    ///< base colour (linear RGB)
};

template <class V> void describe(V& v, ControlsDef& d) {
    v.field("fish_count", d.fish_count, range(1, 10000), "F: fish in the school spawned at the camera's focus");
    v.field("fish_radius", d.fish_radius, range(0.5, 1000), "F: radius of the circle the school swims on, m");
    v.field("fish_speed", d.fish_speed, range(0, 100), "F: swimming speed, m/s");
    v.field("fish_jump_interval", d.fish_jump_interval, range(0.1, 1e6), "F: mean time between one fish's jumps, s");
    v.field("fish_length", d.fish_length, range(0.01, 100), "F: body length of a fish, m");
    v.field("fish_color", d.fish_color, range(0, 1), "F: the school's colour (linear RGB)");
}


/// Scripted input events not yet queued (a resource; `run --input`).
struct ScriptedInput {
    std::vector<platform::InputEvent> events;  ///< in time order
    size_t next = 0;
};

/// The input the simulation steps consumed (a resource while `play --record` records), each
/// event stamped with the middle of its step's simulated interval, so `run --input` feeds it
/// to the same step. The window's own keys (Esc, P, N, H, F12) are left out: a recording
/// replays the steps, not the pauses.
struct InputRecorder {
    std::vector<platform::InputEvent> events;
};

/// How much of the overlay is drawn (H: folded <-> full).
enum class OverlayLevel : uint8_t {
    Folded,  ///< the compact HUD: fps, tool, the goal's state, the start card while it shows
    Full,    ///< every panel
    Hidden,  ///< nothing (a picture of the world alone)
};

/// Requests the frame's keys make of the simulation, and the overlay switch (a resource).
struct WindowControls {
    ControlsDef def;          ///< the scene's [controls]
    int spawnFish = 0;        ///< fish schools to spawn at the camera's focus next step
    int screenshotCount = 0;  ///< screenshots taken so far (names oceanbox_shot_NNN.png)
    OverlayLevel overlay = OverlayLevel::Folded;  ///< H: folded <-> full (kept across R and a scene switch)
    bool card = false;        ///< the start card shows (play), until the first input
    std::string cardText;     ///< its line: the goal or what to try
    std::string cardKeys;     ///< its keys
    bool pickerOpen = false;  ///< the scene picker is open: no steps run (the goal clock holds)
    bool restart = false;     ///< R: the run loop rebuilds the world from the scene it started with (taken once)
    std::string sceneSwitch;  ///< the scene picker's file, whose scene the UI's restart request holds ("" = none)
};

/// The window's own keys (Esc, P, N, H, F12, R): they act on the run, not in the world.
bool isWindowKey(platform::Key key);
/// Whether the steps' input this step acts in the world: a key other than the window's, a
/// button, the wheel (what starts a goal clock that waits for the player).
bool actsInWorld(const platform::InputState& input);
/// Whether the frame's input has any press, click or wheel turn (what dismisses the start card).
bool anyPress(const platform::InputState& input);

/// Creates the input queue, the frame's and the steps' input state, the controls and
/// SimControl resources.
void addControls(ecs::World& world, const ControlsDef& def);
/// Input phase: queues the scripted events due by this frame's clock, then gives the frame
/// its events (call after the platform's events are queued).
void frameInputSystem(ecs::World& world, const ecs::Tick& tick);
/// Input phase, after frameInputSystem: P, N, F12, H, R (and C while paused); any press
/// dismisses the start card; the open picker holds the steps.
void controlsSystem(ecs::World& world, const ecs::Tick& tick);
/// Script phase, first: the events due by this step's clock time into StepInput; C cycles the
/// camera's mode, F asks for a fish school.
void stepInputSystem(ecs::World& world, const ecs::Tick& tick);
/// The school F spawns (and the drop tool drops), at the origin.
ObjectDef fishSchoolOf(const ControlsDef& def);
/// Script phase: spawns the fish schools asked for.
void spawnRequestsSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
