// Render interpolation (render.interpolate): each step first keeps every pose it starts from,
// so a frame whose clock lies between two steps draws the bodies and the camera between them.
// Only what is drawn moves: the simulation, its recordings and its state hash are untouched.
#pragma once
#include "ecs/schedule.h"
#include "ecs/world.h"

namespace ob::game {

/// Script phase, the first step row: with render.interpolate on, every transform as the step
/// finds it (sim/step_poses.h); off, none.
void rememberPosesSystem(ecs::World& world, const ecs::Tick& tick);
/// Render phase, the first row: the weight this frame draws with, the schedule's Tick::alpha
/// with render.interpolate on, else 1 (the latest step).
void drawnAlphaSystem(ecs::World& world, const ecs::Tick& tick);
/// The weight the latest frame draws with (1 before the first step or with interpolation off):
/// what the view and the marks the UI projects onto the scene pass to cameraView and objectDraws.
float drawnAlpha(ecs::World& world);

} // namespace ob::game
