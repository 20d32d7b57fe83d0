// How the view shows a goal's state (goals/goal.h's MarkState) on the bodies it names and in
// its cues on the water: the goal says what a body is (the next gate, a target hit, a crate in
// the ring), this says what colour that is. Rules and colours in words: docs/games.md.
#pragma once
#include "ecs/world.h"
#include "goals/goal.h"
#include "view_data/scene_view.h"

#include <functional>
#include <glm/vec3.hpp>

namespace ob::game {

/// A body's look in a goal state: `color` for a built-in mesh, `tint` over a model's own
/// colours (bright multipliers, so a red-and-white buoy turns yellow, green or red where it is
/// white). `keepColor`: the body's own colour stays (a herded crate outside the zone).
struct StateLook {
    glm::vec3 color{1.0f}, tint{1.0f};
    bool keepColor = false;
};

/// The look of a state.
StateLook lookOf(MarkState state);
/// The colour of a cue on the water for an event that brought `state` (linear RGB, in [0, 1]).
glm::vec3 cueColor(MarkState state);
/// What objectDraws calls on each draw: the world's goal's marks as colours (nothing without a goal).
std::function<void(ecs::Entity, gfx::ObjectDraw&)> goalRestyle(ecs::World& world);

} // namespace ob::game
