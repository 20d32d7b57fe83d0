// The goal of a scene ([game], goals/game_def.h) as a system at the fixed step: the mode's Goal
// (goals/goal.h, one per mode, registered in goals/goal_modes.h) judged each step, the goal
// clock, the time limit and [sim] end_time. Once the result is known the run is over: no more
// steps (SimControl::stopped), the result panel shows, a headless run ends. Rules: docs/games.md.
#pragma once
#include "ecs/schedule.h"
#include "goals/game_def.h"
#include "goals/goal.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ob::game {

/// The goal's state (a resource of every sandbox; mode "none" keeps the clock and end_time).
struct GameState {
    GameDef def;
    float endTime = 0.0f;          ///< [sim] end_time, s (0: none)
    GameResult result = GameResult::Running;
    std::string reason;            ///< why it ended ("all 5 targets hit", "time is up", ...)
    double time = 0.0;             ///< the goal clock: simulated s since it started, held at the end
    bool waitsForPlayer = false;   ///< the clock starts at the first step with input acting in the world (play)
    bool started = false;          ///< the clock runs (from the first step, or the player's first input)
    double startedAt = 0.0;        ///< simulated s when it started
    std::unique_ptr<Goal> goal;    ///< the mode's rules and state (null: mode "none")
    GoalEvents events;             ///< what the goal saw happen (the view's cues)

    bool over() const { return result != GameResult::Running; }
};

/// Checks what the reader cannot: the objects the mode names exist and suit it (each mode's
/// check). `where(key)` gives "file:line:column" of a [game] key.
std::vector<std::string> validateGame(const GameDef& game, const std::vector<ObjectDef>& objects,
                                      const std::function<std::string(const std::string&)>& where);
/// Creates the GameState resource for the spawned scene (call after its objects exist).
void addGame(ecs::World& world, const GameDef& game, const std::vector<ObjectDef>& objects, float endTime);
/// Script phase, after the behaviours: the goal judged on the poses of the last physics step
/// once its clock runs (from the first step, or from the step `playerActed` first: see
/// goalClockWaitsForPlayer), then the time limit and end_time; at the end the steps stop.
void gameStep(ecs::World& world, const ecs::Tick& tick, bool playerActed);
/// The goal's state (null in a world without one).
const GameState* gameState(ecs::World& world);
/// The mode's goal as its own type (null when the world's goal is another mode or none).
template <class G> const G* goalAs(ecs::World& world) {
    const GameState* game = gameState(world);
    return game ? dynamic_cast<const G*>(game->goal.get()) : nullptr;
}
/// The goal clock waits for the player's first input acting in the world (play; a recording
/// of play replays with it).
void goalClockWaitsForPlayer(ecs::World& world);

} // namespace ob::game
