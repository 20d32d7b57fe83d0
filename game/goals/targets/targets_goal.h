// The targets goal: every target touched by a cannonball counts once, floods and sinks; all hit
// wins (docs/games.md#targets).
#pragma once
#include "goals/goal.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ob::game {

/// A target.
struct GameTarget {
    ecs::Entity entity = ecs::Entity::None;
    std::string name;
    bool sphere = false;     ///< a sphere of `radius`, else a box of half extents `half`
    float radius = 0.0f;     ///< m
    glm::vec3 half{0.0f};    ///< m
    bool hit = false;        ///< a cannonball has touched it (it counts once, then floods and sinks)
    double hitTime = 0.0;    ///< goal-clock s of the hit
};

/// Marks a cannonball with where it was at the last game step (its path for the hit test).
struct BallTrace {
    glm::vec3 last{0.0f};
};

class TargetsGoal final : public Goal {
public:
    explicit TargetsGoal(const GoalSetup& setup);
    Verdict judge(ecs::World& world, double now, GoalEvents& events) override;
    int score() const override { return m_hits; }
    std::string count() const override;
    std::string summary() const override;
    void addStats(nlohmann::json& game) const override;
    std::vector<GoalMark> marks() const override;

    const std::vector<GameTarget>& targets() const { return m_targets; }

private:
    std::vector<GameTarget> m_targets;
    int m_hits = 0;
};

} // namespace ob::game
