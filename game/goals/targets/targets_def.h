// mode = "targets": floating targets hit with the cannon; a target hit floods and sinks
// (goals/targets/targets_goal.h). Rules: docs/games.md#targets.
#pragma once
#include "core/schema.h"
#include "goals/goal_mode.h"

#include <string>

namespace ob::game {

/// The targets' keys of [game].
struct TargetsGameDef {
    std::string target_prefix = "target";  ///< every object whose name starts with this is a target (at least one)
};

template <class V> void describe(V& v, TargetsGameDef& d) {
    v.field("target_prefix", d.target_prefix, "objects whose name starts with this are the targets");
}

/// The registration of the mode (goals/goal_modes.h).
struct TargetsMode {
    static constexpr const char* NAME = "targets";
    using Def = TargetsGameDef;
    static void check(const GoalSetup& setup, const GoalError& error);
    static std::unique_ptr<Goal> make(const GoalSetup& setup);
};

} // namespace ob::game
