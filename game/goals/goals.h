// The goal of a scene ([game], goals/game_def.h) as a system at the fixed step: targets hit by
// cannonballs, gates sailed in order, crates herded into a zone, the time limit and [sim]
// end_time. Once the result is known the run is over: no more steps (SimControl::stopped),
// the result panel shows, a headless run ends. Rules: docs/games.md.
#pragma once
#include "ecs/schedule.h"
#include "goals/game_def.h"

#include <functional>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ob::game {

struct SceneDef;

/// Where a goal stands.
enum class GameResult : uint8_t { Running, Won, Lost, Ended };
/// "ended": a scene without a goal reached [sim] end_time.
constexpr std::array<const char*, 4> names(GameResult) { return {"running", "won", "lost", "ended"}; }

/// A target (mode "targets").
struct GameTarget {
    ecs::Entity entity = ecs::Entity::None;
    std::string name;
    bool sphere = false;     ///< a sphere of `radius`, else a box of half extents `half`
    float radius = 0.0f;     ///< m
    glm::vec3 half{0.0f};    ///< m
    bool hit = false;        ///< a cannonball has touched it (it counts once)
    double hitTime = 0.0;    ///< simulated s of the hit
};

/// Where a gate of the race stands.
enum class GateState : uint8_t { Ahead, Passed, Missed };

/// A gate (mode "race"): two objects, the ship passes between them.
struct GameGate {
    ecs::Entity port = ecs::Entity::None, starboard = ecs::Entity::None;
    GateState state = GateState::Ahead;
    double time = 0.0;       ///< simulated s it was passed or missed
};

/// A body held near where it started (targets, gate buoys).
struct Mooring {
    ecs::Entity entity = ecs::Entity::None;
    glm::vec3 anchor{0.0f};  ///< start position, world m (its y is not held)
};

/// Something the goal saw happen (a hit, a gate, a crate in or out): the view marks it.
struct GoalEvent {
    glm::vec3 at{0.0f};       ///< where, world m
    double time = 0.0;        ///< goal-clock s
    glm::vec3 color{1.0f};    ///< the state's colour (linear RGB)
};

/// The goal's state (a resource of every sandbox; mode "none" keeps the time and end_time).
struct GameState {
    GameDef def;
    float endTime = 0.0f;          ///< [sim] end_time, s (0: none)
    GameResult result = GameResult::Running;
    std::string reason;            ///< why it ended ("all 5 targets hit", "time is up", ...)
    double time = 0.0;             ///< the goal clock: simulated s since it started, held at the end
    bool waitsForPlayer = false;   ///< the clock starts at the first step with input acting in the world (play)
    bool started = false;          ///< the clock runs (from the first step, or the player's first input)
    double startedAt = 0.0;        ///< simulated s when it started
    int score = 0;                 ///< targets: hits; race: gates passed; herd: crates in the zone
    // --- targets
    std::vector<GameTarget> targets;
    // --- race
    ecs::Entity racer = ecs::Entity::None;  ///< the player's ship (else the first ship)
    glm::vec2 racerLast{0.0f};     ///< its (x, z) at the last step
    std::vector<GameGate> gates;
    size_t nextGate = 0;           ///< index of the gate to pass next
    int missed = 0;                ///< gates missed
    std::string lastMissed;        ///< "gate 2 missed" while the HUD shows it
    double lastMissedTime = -1e9;  ///< when it was missed, s
    // --- herd
    std::vector<ecs::Entity> crates;
    std::vector<bool> inside;      ///< per crate: its centre is in the zone now
    std::vector<glm::vec3> crateColors;  ///< per crate: its own colour (shown outside the zone)
    int needed = 0;                ///< crates in the zone at once that win
    std::vector<ecs::Entity> markers;  ///< the zone's edge floats (drawn only)
    std::vector<Mooring> moorings;
    std::vector<GoalEvent> events;  ///< the latest events, oldest first (the view's cues)

    /// The race's time: the time plus the missed gates' penalty (s).
    double raceTime() const;
    bool over() const { return result != GameResult::Running; }
};

/// Marks a cannonball with where it was at the last game step (its path for the hit test).
struct BallTrace {
    glm::vec3 last{0.0f};
};

/// Checks what the reader cannot: the objects the mode names exist and suit it (targets are
/// spheres or boxes, a targets game has a cannon, a race a ship and gates of two different
/// objects, a herd enough crates). `where(key)` gives "file:line:column" of a key.
std::vector<std::string> validateGame(const SceneDef& scene, const std::function<std::string(const std::string&)>& where);
/// Creates the GameState resource for the spawned scene (call after its objects exist).
void addGame(ecs::World& world, const SceneDef& scene);
/// Script phase, after the behaviours: moorings pull, the goal is judged on the poses of the
/// last physics step, the time limit and end_time end it; at the end the steps stop.
void gameSystem(ecs::World& world, const ecs::Tick& tick);
/// The goal's state (null in a world without one).
const GameState* gameState(ecs::World& world);
/// The goal clock waits for the player's first input acting in the world (play; a recording
/// of play replays with it).
void goalClockWaitsForPlayer(ecs::World& world);

} // namespace ob::game
