// The race goal (goals/race/race_goal.h) and its registration (race_def.h).
#include "goals/race/race_goal.h"

#include "behaviours/mooring.h"
#include "behaviours/ship.h"
#include "ecs/components.h"
#include "goals/game_def.h"
#include "goals/goal_geometry.h"
#include "sim/objects.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace ob::game {

namespace {
constexpr double MISSED_SHOWN_S = 4.0;  // how long "gate N missed" stays on the HUD (goal-clock s)

glm::vec2 xz(glm::vec3 p) { return {p.x, p.z}; }
}

void RaceMode::check(const GoalSetup& setup, const GoalError& error) {
    const RaceGameDef& race = setup.game;
    const auto& objects = setup.objects;
    if (race.gates.empty()) error("mode", "a race needs [[game.gates]]");
    if (std::none_of(objects.begin(), objects.end(), [](const ObjectDef& o) { return o.type == ObjectType::Ship; }))
        error("mode", "a race needs a ship in [[objects]]");
    for (size_t g = 0; g < race.gates.size(); ++g) {
        const GateDef& gate = race.gates[g];
        const std::string at = "gates[" + std::to_string(g) + "].";
        for (const auto& [key, name] : {std::pair{"port", gate.port}, std::pair{"starboard", gate.starboard}}) {
            const std::string& wanted = name;  // a structured binding cannot be captured (C++17; clang refuses it)
            const bool exists = std::any_of(objects.begin(), objects.end(), [&](const ObjectDef& o) {
                return !wanted.empty() && o.name == wanted && (o.type == ObjectType::Sphere || o.type == ObjectType::Box);
            });
            if (!exists) error(at + key, "no sphere or box object is named '" + name + "'");
        }
        if (gate.port == gate.starboard && !gate.port.empty()) error(at + "starboard", "the same object as port");
    }
}

std::unique_ptr<Goal> RaceMode::make(const GoalSetup& setup) { return std::make_unique<RaceGoal>(setup); }

RaceGoal::RaceGoal(const GoalSetup& setup)
    : m_rule(setup.game.missed_gate), m_penalty(setup.game.miss_penalty), m_timeLimit(setup.game.time_limit) {
    ecs::World& world = *setup.world;
    auto& ships = world.pool<Ship>();
    for (size_t i = 0; i < ships.size() && m_racer == ecs::Entity::None; ++i)
        if (ships.components()[i].def.player) m_racer = ships.entities()[i];
    if (m_racer == ecs::Entity::None && ships.size() > 0) m_racer = ships.entities()[0];
    if (const ecs::Transform* t = world.find<ecs::Transform>(m_racer)) m_racerLast = xz(t->position);
    for (const GateDef& g : setup.game.gates) {
        m_gates.push_back({findObject(world, g.port), findObject(world, g.starboard)});
        moor(world, m_gates.back().port, setup.game.mooring_period);
        moor(world, m_gates.back().starboard, setup.game.mooring_period);
    }
}

void RaceGoal::prepare(ecs::World& world, bool clockRuns) {
    // While the clock waits the ship's position is kept fresh, so no crossing is seen later.
    if (!clockRuns)
        if (const ecs::Transform* ship = world.find<ecs::Transform>(m_racer)) m_racerLast = xz(ship->position);
}

void RaceGoal::miss(ecs::World& world, size_t gate, double now, GoalEvents& events) {
    m_gates[gate].state = GateState::Missed;
    m_gates[gate].time = now;
    ++m_missed;
    events.add(world, m_gates[gate].port, MarkState::Missed, now);
    m_lastMissed = "gate " + std::to_string(gate + 1) + " missed";
    m_lastMissedTime = now;
}

Verdict RaceGoal::judge(ecs::World& world, double now, GoalEvents& events) {
    m_lastTime = now;
    const ecs::Transform* ship = world.find<ecs::Transform>(m_racer);
    if (!ship) return {};
    const glm::vec2 from = m_racerLast, to = xz(ship->position);
    m_racerLast = to;
    // The first gate ahead (from the next one on) that the path crosses the right way: the
    // gates before it are missed.
    for (size_t g = m_next; g < m_gates.size(); ++g) {
        GameGate& gate = m_gates[g];
        const ecs::Transform* port = world.find<ecs::Transform>(gate.port);
        const ecs::Transform* starboard = world.find<ecs::Transform>(gate.starboard);
        if (!port || !starboard || gateCrossing(xz(port->position), xz(starboard->position), from, to) <= 0) continue;
        for (size_t m = m_next; m < g; ++m) miss(world, m, now, events);
        gate.state = GateState::Passed;
        gate.time = now;
        ++m_passed;
        events.add(world, m_racer, MarkState::Passed, now);
        m_next = g + 1;
        break;
    }
    if (m_missed > 0 && m_rule == MissedGate::Lose) return {GameResult::Lost, m_lastMissed};
    if (m_next < m_gates.size()) return {};
    char text[96];
    if (m_timeLimit > 0.0f && raceTime(now) > double(m_timeLimit)) {
        std::snprintf(text, sizeof text, "finished in %.1f s with penalties, over the %.0f s limit", raceTime(now), double(m_timeLimit));
        return {GameResult::Lost, text};
    }
    std::snprintf(text, sizeof text, "all %zu gates in %.1f s", m_gates.size(), raceTime(now));
    return {GameResult::Won, text};
}

double RaceGoal::raceTime(double time) const {
    return time + (m_rule == MissedGate::Penalty ? double(m_missed) * double(m_penalty) : 0.0);
}

std::string RaceGoal::count() const {
    return "gate " + std::to_string(std::min(m_next + 1, m_gates.size())) + " / " + std::to_string(m_gates.size());
}

std::string RaceGoal::note(double now) const {
    if (now - m_lastMissedTime >= MISSED_SHOWN_S) return "";
    char text[64];
    std::snprintf(text, sizeof text, "  (+%.0f s)", double(m_penalty));
    return m_lastMissed + (m_rule == MissedGate::Penalty ? text : "");
}

std::string RaceGoal::summary() const {
    char text[128];
    std::snprintf(text, sizeof text, "%d of %zu gates passed, %d missed; race time %.1f s", m_passed, m_gates.size(), m_missed,
                  raceTime(m_lastTime));
    return text;
}

void RaceGoal::addStats(nlohmann::json& j) const {
    j["gates"] = m_gates.size();
    j["passed"] = m_passed;
    j["next_gate"] = m_next + 1;  // numbered from 1, as the HUD shows them
    j["missed_gates"] = nlohmann::json::array();
    for (size_t g = 0; g < m_gates.size(); ++g)
        if (m_gates[g].state == GateState::Missed) j["missed_gates"].push_back(g + 1);
    j["race_time_s"] = raceTime(m_lastTime);
}

std::vector<GoalMark> RaceGoal::marks() const {
    std::vector<GoalMark> marks;
    for (size_t g = 0; g < m_gates.size(); ++g) {
        const GateState s = m_gates[g].state;
        if (s == GateState::Ahead && g != m_next) continue;
        const MarkState look = s == GateState::Passed ? MarkState::Passed : s == GateState::Missed ? MarkState::Missed : MarkState::Next;
        marks.push_back({m_gates[g].port, look});
        marks.push_back({m_gates[g].starboard, look});
    }
    return marks;
}

} // namespace ob::game
