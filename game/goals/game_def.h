// A scene's goal, section [game]: what the player plays for (hit targets, sail a race, herd
// crates into a ring), its time limit, and what each mode needs. Rules: docs/games.md.
#pragma once
#include "core/schema.h"
#include "world/tool_kind.h"

#include <glm/vec2.hpp>
#include <string>
#include <utility>
#include <vector>

namespace ob::game {

/// What the player plays for.
enum class GameMode : uint8_t {
    None,     ///< a sandbox: no goal ([sim] end_time still ends a run)
    Targets,  ///< hit every target with the cannon
    Race,     ///< sail the ship through the gates in order
    Herd,     ///< push crates into the zone
};
constexpr std::array<const char*, 4> names(GameMode) { return {"none", "targets", "race", "herd"}; }

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

/// mode = "targets": floating targets hit with the cannon.
struct TargetsGameDef {
    std::string target_prefix = "target";  ///< every object whose name starts with this is a target (at least one)
};

template <class V> void describe(V& v, TargetsGameDef& d) {
    v.field("target_prefix", d.target_prefix, "objects whose name starts with this are the targets");
}

/// mode = "race": the player's ship through buoy gates in order.
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

/// mode = "herd": drifting crates pushed into a circle on the water.
struct HerdGameDef {
    std::string herd_prefix = "crate";  ///< every object whose name starts with this is herded
    glm::vec2 zone_center{0.0f};        ///< the zone's centre [x, z], world m
    float zone_radius = 8.0f;           ///< m, [0.5, 10000]; a crate is in when its centre is
    int herd_count = 0;                 ///< crates in the zone at once that win, [0, 10000] (0: every herded crate)
    int zone_markers = 16;              ///< small floats drawn round the zone's edge (drawn only), [0, 256]
};

template <class V> void describe(V& v, HerdGameDef& d) {
    v.field("herd_prefix", d.herd_prefix, "objects whose name starts with this are herded");
    v.field("zone_center", d.zone_center, any(), "the zone's centre [x, z], m");
    v.field("zone_radius", d.zone_radius, range(0.5, 10000), "the zone's radius, m");
    v.field("herd_count", d.herd_count, range(0, 10000), "crates in the zone at once that win (0: all)");
    v.field("zone_markers", d.zone_markers, range(0, 256), "floats drawn round the zone's edge");
}

/// The goal, section [game]; the mode's own keys are read only in that mode.
struct GameDef {
    GameMode mode = GameMode::None;  ///< "none", "targets", "race" or "herd"
    float time_limit = 60.0f;        ///< s of simulated time to reach the goal, [0, 1e6] (0: none); lost when it runs out
    float mooring_period = 3.0f;     ///< targets and gate buoys are moored where they start: a horizontal spring of this
                                     ///< period, critically damped (s, [0, 1000]; 0: they drift free)
    std::vector<Tool> tools;         ///< the tools the player may take (empty: every tool; a goal scene: all but grab and drop)
    std::string intro;               ///< the start card's line: the goal or what to try ("" = the scene file's first comment)
    // The tool the player holds at start is [tools] tool (world/tools.h), else the first allowed.
    TargetsGameDef targets;
    RaceGameDef race;
    HerdGameDef herd;
};

/// The tools a scene with this [game] allows (its `tools`, else the default for its mode).
std::vector<Tool> allowedTools(const GameDef& game);

/// The keys of the modes other than `mode` that `mode` does not read, each with its error.
std::vector<std::pair<std::string, std::string>> gameKeysNotReadBy(GameMode mode);

template <class V> void describe(V& v, GameDef& d) {
    v.field("mode", d.mode, "the goal: none, targets, race or herd");
    v.field("time_limit", d.time_limit, range(0, 1e6), "seconds to reach the goal (0: none)");
    v.field("mooring_period", d.mooring_period, range(0, 1000), "targets and gate buoys held where they start (s; 0: free)");
    v.field("tools", d.tools, "the tools the player may take (default: all; in a goal scene all but grab and drop)");
    v.field("intro", d.intro, "the start card's line: the goal or what to try (default: the scene file's first comment)");
    switch (d.mode) {  // a reader has read `mode` by now
    case GameMode::None: break;
    case GameMode::Targets: v.fields(d.targets); break;
    case GameMode::Race: v.fields(d.race); break;
    case GameMode::Herd: v.fields(d.herd); break;
    }
    if constexpr (requires { v.refuse("", std::string()); })
        for (const auto& [key, why] : gameKeysNotReadBy(d.mode)) v.refuse(key.c_str(), why);
}

} // namespace ob::game
