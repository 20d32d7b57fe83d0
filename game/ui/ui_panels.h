// The window-mode panels: frame timings, what the player steers, live scene settings, and
// saving the scene.
#pragma once
#include "ecs/schedule.h"
#include "world/scene_settings.h"

#include <optional>
#include <string>
#include <vector>

namespace ob::game {

/// Draws the panels (inside an ImGui frame); `dynamicScale`: the resolution scale dynamic
/// resolution holds now, when it is on. [render] keys apply live; the other sections are
/// edited on a copy that "restart with these settings" hands to `restart` once valid.
void drawPanels(ecs::World& world, SceneSettings& settings, const ecs::FrameTimer& timer, std::optional<float> dynamicScale,
                std::optional<SceneDef>& restart, double now);

/// The keys and mouse actions that do something in this world now (the overlay's help).
std::vector<std::string> keyHelp(ecs::World& world);

} // namespace ob::game
