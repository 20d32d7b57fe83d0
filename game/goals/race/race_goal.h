// The race goal: the player's ship through the gates in order; a gate skipped is missed (a time
// penalty, or the race lost); the last gate within the time limit wins (docs/games.md#race).
#pragma once
#include "goals/goal.h"
#include "goals/race/race_def.h"

#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace ob::game {

/// Where a gate of the race stands.
enum class GateState : uint8_t { Ahead, Passed, Missed };

/// A gate: two objects, the ship passes between them.
struct GameGate {
    ecs::Entity port = ecs::Entity::None, starboard = ecs::Entity::None;
    GateState state = GateState::Ahead;
    double time = 0.0;       ///< goal-clock s it was passed or missed
};

class RaceGoal final : public Goal {
public:
    explicit RaceGoal(const GoalSetup& setup);
    void prepare(ecs::World& world, bool clockRuns) override;
    Verdict judge(ecs::World& world, double now, GoalEvents& events) override;
    int score() const override { return m_passed; }
    std::string count() const override;
    std::string note(double now) const override;
    std::string summary() const override;
    void addStats(nlohmann::json& game) const override;
    std::vector<GoalMark> marks() const override;

    const std::vector<GameGate>& gates() const { return m_gates; }
    int missed() const { return m_missed; }
    /// The race's time at goal-clock `time`: it plus the missed gates' penalty (s).
    double raceTime(double time) const;

private:
    void miss(ecs::World& world, size_t gate, double now, GoalEvents& events);
    MissedGate m_rule;
    float m_penalty;
    float m_timeLimit;
    ecs::Entity m_racer = ecs::Entity::None;  ///< the player's ship (else the first ship)
    glm::vec2 m_racerLast{0.0f};  ///< its (x, z) at the last step
    std::vector<GameGate> m_gates;
    size_t m_next = 0;            ///< index of the gate to pass next
    int m_passed = 0;
    int m_missed = 0;
    double m_lastTime = 0.0;       ///< the goal clock at the last judged step
    std::string m_lastMissed;      ///< "gate 2 missed", while the HUD shows it
    double m_lastMissedTime = -1e9;  ///< when it was missed, goal-clock s
};

} // namespace ob::game
