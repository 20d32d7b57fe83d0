// The herd goal: floating bodies (crates, balls) brought into a ring on the water; enough of
// them inside at once wins (docs/games.md#herd).
#pragma once
#include "goals/goal.h"

#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace ob::game {

class HerdGoal final : public Goal {
public:
    explicit HerdGoal(const GoalSetup& setup);
    void prepare(ecs::World& world, bool clockRuns) override;
    Verdict judge(ecs::World& world, double now, GoalEvents& events) override;
    int score() const override { return m_score; }
    std::string count() const override;
    std::string summary() const override;
    void addStats(nlohmann::json& game) const override;
    std::vector<GoalMark> marks() const override;

    const std::vector<ecs::Entity>& herded() const { return m_herded; }
    /// Per herded body: its centre is in the zone now.
    const std::vector<bool>& inside() const { return m_inside; }
    int needed() const { return m_needed; }

private:
    std::string m_prefix;             ///< what is herded, by name ("crate", "ball")
    glm::vec2 m_centre{0.0f};         ///< the zone's centre (x, z), m
    float m_radius = 0.0f;            ///< m
    std::vector<ecs::Entity> m_herded;
    std::vector<bool> m_inside;
    int m_needed = 0;                 ///< in the zone at once that win
    int m_score = 0;                  ///< in the zone now
    std::vector<ecs::Entity> m_markers;  ///< the zone's edge floats (drawn only)
};

} // namespace ob::game
