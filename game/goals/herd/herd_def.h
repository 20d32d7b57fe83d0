// mode = "herd": floating bodies brought into a ring on the water, by the ship's bow or by the
// water the stir sets moving (goals/herd/herd_goal.h). Rules: docs/games.md#herd.
#pragma once
#include "core/schema.h"
#include "goals/goal_mode.h"

#include <glm/vec2.hpp>
#include <string>

namespace ob::game {

/// The herd's keys of [game].
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

/// The registration of the mode (goals/goal_modes.h).
struct HerdMode {
    static constexpr const char* NAME = "herd";
    using Def = HerdGameDef;
    static void check(const GoalSetup& setup, const GoalError& error);
    static std::unique_ptr<Goal> make(const GoalSetup& setup);
};

} // namespace ob::game
