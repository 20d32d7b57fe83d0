// The player's controls: the frame's keys (pause P, step N, screenshot F12, camera mode C,
// overlay H, quit Esc) and the simulation's input (held keys and presses, per fixed step).
#pragma once
#include "behaviours/step_input.h"
#include "ecs/schedule.h"
#include "platform/input.h"

#include <vector>

namespace ob::game {


/// Scripted input events not yet queued (a resource; `run --input`).
struct ScriptedInput {
    std::vector<platform::InputEvent> events;  ///< in time order
    size_t next = 0;
};

/// Requests the frame's keys make of the simulation, and the overlay switch (a resource).
struct WindowControls {
    int spawnFish = 0;        ///< fish schools to spawn at the camera's focus next step
    int screenshotCount = 0;  ///< screenshots taken so far (names oceanbox_shot_NNN.png)
    bool showOverlay = true;  ///< H: the UI overlay is drawn
};

/// Creates the input queue, the frame's and the steps' input state, the controls and
/// SimControl resources.
void addControls(ecs::World& world);
/// Input phase: queues the scripted events due by this frame's clock, then gives the frame
/// its events (call after the platform's events are queued).
void frameInputSystem(ecs::World& world, const ecs::Tick& tick);
/// Input phase, after frameInputSystem: P, N, F12, H, C.
void controlsSystem(ecs::World& world, const ecs::Tick& tick);
/// Script phase, first: the events due by this step's clock time into StepInput; F asks for
/// a fish school.
void stepInputSystem(ecs::World& world, const ecs::Tick& tick);
/// Script phase: spawns the fish schools asked for.
void spawnRequestsSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
