// The window-mode panels: frame timings and live scene settings.
#pragma once
#include "ecs/schedule.h"
#include "scene.h"

namespace ob::game {

/// Draws the stats and settings windows (inside an ImGui frame).
void drawPanels(SceneDef& scene, const ecs::FrameTimer& timer);

} // namespace ob::game
