// The interface every goal mode implements (targets, race, herd, ...): its own state, its rules
// judged each fixed step, its HUD line, its result and the state of the bodies it names, which
// the view reads as colours. A mode is registered once, in goals/goal_modes.h.
#pragma once
#include "ecs/world.h"

#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace ob::game {

struct GameDef;
struct ObjectDef;

/// Where a goal stands.
enum class GameResult : uint8_t { Running, Won, Lost, Ended };
/// "ended": a scene without a goal reached [sim] end_time.
constexpr std::array<const char*, 4> names(GameResult) { return {"running", "won", "lost", "ended"}; }

/// What a goal says about a body it names (the view's colours read it: goals colour nothing).
enum class MarkState : uint8_t {
    Next,     ///< the gate to pass next
    Passed,   ///< a gate passed
    Missed,   ///< a gate skipped
    Spent,    ///< a target hit (it floods and sinks)
    Outside,  ///< a herded body outside the zone
    Inside,   ///< a herded body inside the zone
    Zone,     ///< a float marking the zone's edge
};

/// A body and what the goal says about it.
struct GoalMark {
    ecs::Entity entity = ecs::Entity::None;
    MarkState state = MarkState::Next;
};

/// Something the goal saw happen (a hit, a gate, a crate in or out): the view marks it.
struct GoalEvent {
    glm::vec3 at{0.0f};               ///< where, world m
    double time = 0.0;                ///< goal-clock s
    MarkState state = MarkState::Passed;  ///< the state it brought (the cue's colour)
};

/// The goal's latest events, oldest first (the view's cues).
class GoalEvents {
public:
    /// An event where `entity` is now (none when it has no position).
    void add(ecs::World& world, ecs::Entity entity, MarkState state, double time);
    const std::vector<GoalEvent>& latest() const { return m_events; }

private:
    std::vector<GoalEvent> m_events;
};

/// What a step of the rules decided: Running while undecided, else the result and why.
struct Verdict {
    GameResult result = GameResult::Running;
    std::string reason;  ///< "all 5 targets hit", "gate 2 missed", ...
};

/// What a mode gets to set itself up (after the scene's objects exist) or to check a scene.
struct GoalSetup {
    ecs::World* world = nullptr;               ///< null when only checking
    const GameDef& game;                       ///< [game], the mode's keys included
    const std::vector<ObjectDef>& objects;     ///< the scene's [[objects]]
};

/// The scene's objects whose name starts with `prefix` (none for an empty prefix), in order.
std::vector<const ObjectDef*> objectsNamed(const std::vector<ObjectDef>& objects, const std::string& prefix);
/// Checks that the objects `key` names are spheres or boxes (what a goal can judge by its shape).
void checkFloatingShapes(const std::vector<const ObjectDef*>& named, const std::string& key, const std::string& what,
                         const std::function<void(const std::string&, const std::string&)>& error);

/// A goal mode's rules and state.
class Goal {
public:
    virtual ~Goal() = default;
    /// Every step before the judge, whether the clock runs or not (what it draws rides the
    /// sea; a race keeps its ship's last position while the clock waits).
    virtual void prepare(ecs::World& /*world*/, bool /*clockRuns*/) {}
    /// One step of the rules on the poses of the last physics step, at goal-clock time `now`.
    virtual Verdict judge(ecs::World& world, double now, GoalEvents& events) = 0;
    /// Targets hit, gates passed, bodies in the zone.
    virtual int score() const = 0;
    /// The HUD's count: "hits 2 / 5".
    virtual std::string count() const = 0;
    /// A passing note under it at goal-clock `now` ("gate 2 missed (+10 s)"; "" for none).
    virtual std::string note(double /*now*/) const { return ""; }
    /// The result panel's line: "3 of 5 targets hit".
    virtual std::string summary() const = 0;
    /// Its counts in `run --stats` (docs/games.md lists them).
    virtual void addStats(nlohmann::json& game) const = 0;
    /// The bodies it names and their state.
    virtual std::vector<GoalMark> marks() const = 0;
};

} // namespace ob::game
