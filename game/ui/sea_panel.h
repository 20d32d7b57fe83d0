// The Sea panel of the overlay: wind, choppiness, swell, ripple damping, time of day and the
// weather presets, applied live (each change a requestLiveSet: the next step applies it and
// the sea cross-fades, so a recording can replay it).
#pragma once
#include "ecs/world.h"
#include "world/scene.h"

namespace ob::game {

/// A slider over the live key `key` whose value in the scene is `current`: the value is
/// requested (requestLiveSet) when the slider is released, and shown until the step applied it.
void liveSlider(ecs::World& world, const char* label, const char* key, float current, float lo, float hi, const char* format,
                const char* tip);

/// Draws the panel (inside an ImGui window) for the live scene.
void seaPanel(ecs::World& world, const SceneDef& scene);

} // namespace ob::game
