// The targets goal (goals/targets/targets_goal.h) and its registration (targets_def.h).
#include "goals/targets/targets_goal.h"

#include "behaviours/cannon.h"
#include "behaviours/mooring.h"
#include "ecs/components.h"
#include "goals/game_def.h"
#include "goals/goal_geometry.h"
#include "sim/objects.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace ob::game {

namespace {
constexpr float TOUCH_SLACK = 0.05f;  // m a ball may stay off a target and still touch it (Bullet's contact margin)
}

void TargetsMode::check(const GoalSetup& setup, const GoalError& error) {
    const std::string& prefix = setup.game.target_prefix;
    const auto targets = objectsNamed(setup.objects, prefix);
    if (targets.empty()) error("target_prefix", "no object's name starts with '" + prefix + "' (the targets)");
    checkFloatingShapes(targets, "target_prefix", "targets", error);
    if (std::none_of(setup.objects.begin(), setup.objects.end(), [](const ObjectDef& o) { return o.type == ObjectType::Cannon; }))
        error("mode", "a targets game needs a cannon in [[objects]]");
}

std::unique_ptr<Goal> TargetsMode::make(const GoalSetup& setup) { return std::make_unique<TargetsGoal>(setup); }

TargetsGoal::TargetsGoal(const GoalSetup& setup) {
    ecs::World& world = *setup.world;
    for (const ObjectDef* o : objectsNamed(setup.objects, setup.game.target_prefix)) {
        GameTarget target;
        target.entity = findObject(world, o->name);
        target.name = o->name;
        target.sphere = o->type == ObjectType::Sphere;
        target.radius = o->sphere.radius;
        target.half = 0.5f * o->box.size;
        m_targets.push_back(target);
        moor(world, target.entity, setup.game.mooring_period);
    }
}

Verdict TargetsGoal::judge(ecs::World& world, double now, GoalEvents& events) {
    auto& balls = world.pool<Cannonball>();
    for (size_t i = 0; i < balls.size(); ++i) {
        const ecs::Entity ball = balls.entities()[i];
        const glm::vec3 position = world.get<ecs::Transform>(ball).position;
        BallTrace* trace = world.find<BallTrace>(ball);
        if (!trace) {
            // Fired since the last step: its path starts where it is now.
            world.add<BallTrace>(ball, {position});
            trace = world.find<BallTrace>(ball);
        }
        const float r = world.get<Body>(ball).probes[0].radius + TOUCH_SLACK;
        for (GameTarget& target : m_targets) {
            const ecs::Transform* t = target.hit ? nullptr : world.find<ecs::Transform>(target.entity);
            if (!t) continue;
            const bool touched = target.sphere ? sweptSphereTouchesSphere(trace->last, position, r, t->position, target.radius)
                                               : sweptSphereTouchesBox(trace->last, position, r, t->position, t->rotation, target.half);
            if (!touched) continue;
            target.hit = true;
            target.hitTime = now;
            ++m_hits;
            events.add(world, target.entity, MarkState::Spent, now);
            hole(world, target.entity);  // it floods and sinks: gone from play, seen going
        }
        trace->last = position;
    }
    if (m_hits == int(m_targets.size())) return {GameResult::Won, "all " + std::to_string(m_targets.size()) + " targets hit"};
    return {};
}

std::string TargetsGoal::count() const { return "hits " + std::to_string(m_hits) + " / " + std::to_string(m_targets.size()); }

std::string TargetsGoal::summary() const {
    return std::to_string(m_hits) + " of " + std::to_string(m_targets.size()) + " targets hit";
}

void TargetsGoal::addStats(nlohmann::json& j) const {
    j["targets"] = m_targets.size();
    j["hits"] = m_hits;
    j["hit"] = nlohmann::json::array();
    for (const GameTarget& t : m_targets)
        if (t.hit) j["hit"].push_back({{"name", t.name}, {"time_s", t.hitTime}});
}

std::vector<GoalMark> TargetsGoal::marks() const {
    std::vector<GoalMark> marks;
    for (const GameTarget& t : m_targets)
        if (t.hit) marks.push_back({t.entity, MarkState::Spent});
    return marks;
}

} // namespace ob::game
