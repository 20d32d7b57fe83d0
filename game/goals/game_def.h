// A scene's goal, section [game]: what the player plays for (hit targets, sail a race, herd
// crates into a ring), its time limit, and the mode's own keys (each mode's Def, in its folder
// goals/<mode>/, registered in goals/goal_modes.h). Rules: docs/games.md.
#pragma once
#include "behaviours/tool_kind.h"
#include "core/schema.h"
#include "goals/goal_modes.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ob::game {

/// What the player plays for: None (a sandbox: no goal; [sim] end_time still ends a run), else
/// 1 + the mode's index in GoalModes; its words "none" and the modes' NAMEs.
enum class GameMode : uint8_t { None };
constexpr std::array<const char*, GoalModes::COUNT + 1> names(GameMode) { return GoalModes::WORDS; }

/// The mode whose word is `name` (a compile error when no mode has it).
consteval GameMode gameMode(std::string_view name) {
    for (std::size_t i = 0; i < GoalModes::WORDS.size(); ++i)
        if (name == GoalModes::WORDS[i]) return GameMode(i);
    throw "no goal mode has this name";
}

/// The goal, section [game]; each mode's keys (its Def, a base) are read only in that mode.
struct GameDef : GoalModes::Defs {
    GameMode mode = GameMode::None;  ///< "none" or a registered mode's NAME
    float time_limit = 60.0f;        ///< s of simulated time to reach the goal, [0, 1e6] (0: none); lost when it runs out
    float mooring_period = 3.0f;     ///< targets and gate buoys are moored where they start: a horizontal spring of this
                                     ///< period, critically damped (s, [0, 1000]; 0: they drift free)
    std::vector<Tool> tools;         ///< the tools the player may take (empty: every tool; a goal scene: all but grab and drop)
    std::string intro;               ///< the start card's line: the goal or what to try ("" = the scene file's first comment)
    // The tool the player holds at start is [tools] tool (world/tools.h), else the first allowed.
};

/// The tools a scene with this [game] allows (its `tools`, else the default for its mode).
std::vector<Tool> allowedTools(const GameDef& game);

/// The keys of the modes other than `mode` that `mode` does not read, each with its error.
std::vector<std::pair<std::string, std::string>> gameKeysNotReadBy(GameMode mode);

template <class V> void describe(V& v, GameDef& d) {
    v.field("mode", d.mode, "the goal: none, or a registered mode's name (goals/goal_modes.h)");
    v.field("time_limit", d.time_limit, range(0, 1e6), "seconds to reach the goal (0: none)");
    v.field("mooring_period", d.mooring_period, range(0, 1000), "targets and gate buoys held where they start (s; 0: free)");
    v.field("tools", d.tools, "the tools the player may take (default: all; in a goal scene all but grab and drop)");
    v.field("intro", d.intro, "the start card's line: the goal or what to try (default: the scene file's first comment)");
    if (d.mode != GameMode::None)  // a reader has read `mode` by now
        GoalModes::visit(std::size_t(d.mode) - 1, [&]<class Mode>() { v.fields(static_cast<typename Mode::Def&>(d)); });
    if constexpr (requires { v.refuse("", std::string()); })
        for (const auto& [key, why] : gameKeysNotReadBy(d.mode)) v.refuse(key.c_str(), why);
}

} // namespace ob::game
