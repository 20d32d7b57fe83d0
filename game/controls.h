// Window controls: pause (P), single step while paused (N), a new fish school at the point
// the camera looks at (F), a screenshot (F12).
#pragma once
#include "ecs/schedule.h"

namespace ob::game {

/// Requests the input phase collects for the simulation (a resource).
struct WindowControls {
    int spawnFish = 0;        ///< fish schools to spawn at the camera's focus next step
    int screenshotCount = 0;  ///< screenshots taken so far (names oceanbox_shot_NNN.png)
};

/// Creates the controls and SimControl resources.
void addControls(ecs::World& world);
/// Input phase, after the platform's events: P, N, F, F12.
void controlsSystem(ecs::World& world, const ecs::Tick& tick);
/// Script phase: spawns the fish schools asked for.
void spawnRequestsSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
