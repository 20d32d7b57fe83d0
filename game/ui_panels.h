// The window-mode panels: frame timings, what the player steers, live scene settings, and
// saving the scene.
#pragma once
#include "ecs/schedule.h"
#include "scene.h"

#include <string>

namespace ob::game {

/// Draws the panels (inside an ImGui frame).
void drawPanels(ecs::World& world, SceneDef& scene, const ecs::FrameTimer& timer);

/// Writes the scene as TOML (the keys that differ from the defaults) to `path`; returns ""
/// or what went wrong.
std::string saveScene(SceneDef& scene, const std::string& path);

} // namespace ob::game
