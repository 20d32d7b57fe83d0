// mode = "race": the player's ship through buoy gates in order (goals/race/race_goal.h).
// Rules: docs/games.md#race.
#pragma once
#include "core/schema.h"
#include "goals/goal_mode.h"

#include <string>
#include <vector>

namespace ob::game {

/// What a race does about a gate skipped (the next one crossed before it).
enum class MissedGate : uint8_t {
    Penalty,  ///< the race goes on; each missed gate adds `miss_penalty` seconds to the time
    Lose,     ///< the race is lost at once
};
constexpr std::array<const char*, 2> names(MissedGate) { return {"penalty", "lose"}; }

/// One [[game.gates]] entry: two [[objects]] (buoys) the ship sails between.
struct GateDef {
    std::string port;       ///< the object on the ship's left (port) hand when it passes the gate the right way
    std::string starboard;  ///< the object on its right (starboard) hand
};

template <class V> void describe(V& v, GateDef& d) {
    v.field("port", d.port, "object on the ship's left hand passing the right way");
    v.field("starboard", d.starboard, "object on the ship's right hand passing the right way");
}

/// The race's keys of [game].
struct RaceGameDef {
    std::vector<GateDef> gates;                ///< [[game.gates]] in the order they are sailed (at least one)
    MissedGate missed_gate = MissedGate::Penalty;  ///< "penalty" or "lose"
    float miss_penalty = 10.0f;                ///< penalty: seconds added per missed gate, [0, 1e6]
};

template <class V> void describe(V& v, RaceGameDef& d) {
    v.list("gates", d.gates, "the gates in the order they are sailed");
    v.field("missed_gate", d.missed_gate, "a skipped gate: a time penalty, or the race is lost");
    v.field("miss_penalty", d.miss_penalty, range(0, 1e6), "seconds added per missed gate");
}

/// The registration of the mode (goals/goal_modes.h).
struct RaceMode {
    static constexpr const char* NAME = "race";
    using Def = RaceGameDef;
    static void check(const GoalSetup& setup, const GoalError& error);
    static std::unique_ptr<Goal> make(const GoalSetup& setup);
};

} // namespace ob::game
