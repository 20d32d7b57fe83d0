// The registration line of the goal modes: one entry per mode (its name, Def, checks and
// factory, all in its own folder goals/<mode>/). Adding a mode: its folder and one entry below.
#pragma once
#include "goals/goal_mode.h"
#include "goals/herd/herd_def.h"
#include "goals/race/race_def.h"
#include "goals/targets/targets_def.h"

namespace ob::game {

// --- the registration line. A new mode goes at the end: GameMode is 1 + its index here.
using GoalModes = GoalModeList<TargetsMode, RaceMode, HerdMode>;

} // namespace ob::game
