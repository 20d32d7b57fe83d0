// The goal's states as colours (view/goal_looks.h).
#include "view/goal_looks.h"

#include "goals/goals.h"

#include <glm/common.hpp>
#include <unordered_map>

namespace ob::game {

StateLook lookOf(MarkState state) {
    switch (state) {
    case MarkState::Next: return {{1.0f, 0.75f, 0.05f}, {1.7f, 1.3f, 0.1f}};        // the gate to pass next: bright yellow
    case MarkState::Passed:                                                           // a gate passed, a crate in the zone: green
    case MarkState::Inside: return {{0.1f, 0.6f, 0.15f}, {0.2f, 1.4f, 0.3f}};
    case MarkState::Missed: return {{0.8f, 0.05f, 0.05f}, {1.7f, 0.12f, 0.08f}};    // a gate missed: red
    case MarkState::Spent: return {{0.25f, 0.25f, 0.25f}, {0.22f, 0.22f, 0.25f}};   // a target hit: spent, dark grey
    case MarkState::Outside: return {{1.0f, 1.0f, 1.0f}, {0.5f, 0.8f, 1.7f}, true}; // a herded crate outside: blue over its own
    case MarkState::Zone: return {{1.0f, 0.45f, 0.05f}, {1.0f, 1.0f, 1.0f}};       // the zone's edge: orange (a buoy model: its own)
    }
    return {};
}

glm::vec3 cueColor(MarkState state) {
    const StateLook look = lookOf(state);
    return glm::clamp(look.keepColor ? look.tint : look.color, 0.0f, 1.0f);
}

std::function<void(ecs::Entity, gfx::ObjectDraw&)> goalRestyle(ecs::World& world) {
    const GameState* game = gameState(world);
    if (!game || !game->goal) return {};
    std::unordered_map<uint32_t, MarkState> states;
    for (const GoalMark& m : game->goal->marks()) states[uint32_t(m.entity)] = m.state;
    return [states = std::move(states)](ecs::Entity e, gfx::ObjectDraw& d) {
        const auto it = states.find(uint32_t(e));
        if (it == states.end()) return;
        const StateLook look = lookOf(it->second);
        if (!look.keepColor) d.color = look.color;
        d.modelTint = look.tint;
    };
}

} // namespace ob::game
