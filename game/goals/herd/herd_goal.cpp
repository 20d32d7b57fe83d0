// The herd goal (goals/herd/herd_goal.h) and its registration (herd_def.h).
#include "goals/herd/herd_goal.h"

#include "assets/model.h"
#include "ecs/components.h"
#include "goals/game_def.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace ob::game {

namespace {
constexpr float MARKER_RADIUS = 0.5f;  // m

glm::vec2 xz(glm::vec3 p) { return {p.x, p.z}; }
}

void HerdMode::check(const GoalSetup& setup, const GoalError& error) {
    const HerdGameDef& herd = setup.game;
    const auto herded = objectsNamed(setup.objects, herd.herd_prefix);
    if (herded.empty()) error("herd_prefix", "no object's name starts with '" + herd.herd_prefix + "' (the crates)");
    checkFloatingShapes(herded, "herd_prefix", "herded objects", error);
    if (herd.herd_count > int(herded.size()))
        error("herd_count", std::to_string(herd.herd_count) + " crates to win, but the scene has " + std::to_string(herded.size()));
}

std::unique_ptr<Goal> HerdMode::make(const GoalSetup& setup) { return std::make_unique<HerdGoal>(setup); }

HerdGoal::HerdGoal(const GoalSetup& setup)
    : m_prefix(setup.game.herd_prefix), m_centre(setup.game.zone_center), m_radius(setup.game.zone_radius) {
    ecs::World& world = *setup.world;
    const HerdGameDef& def = setup.game;
    for (const ObjectDef* o : objectsNamed(setup.objects, def.herd_prefix)) m_herded.push_back(findObject(world, o->name));
    m_inside.assign(m_herded.size(), false);
    m_needed = def.herd_count > 0 ? def.herd_count : int(m_herded.size());
    for (int k = 0; k < def.zone_markers; ++k) {
        const float a = 2.0f * float(M_PI) * float(k) / float(def.zone_markers);
        const ecs::Entity e = world.create();
        world.add<ecs::Transform>(e, {glm::vec3(m_centre.x + m_radius * std::cos(a), 0.0f, m_centre.y + m_radius * std::sin(a))});
        world.add<Renderable>(e, {gfx::MeshKind::Sphere, glm::vec3(MARKER_RADIUS), glm::vec3(0.8f), assets::projectModel("buoy")});
        m_markers.push_back(e);
    }
}

void HerdGoal::prepare(ecs::World& world, bool) {
    // The zone's edge floats ride the surface (drawn only: nothing collides with them).
    const OceanState* ocean = world.resource<OceanState>();
    if (!ocean || !ocean->water) return;
    for (ecs::Entity e : m_markers) {
        glm::vec3& p = world.get<ecs::Transform>(e).position;
        p.y = ocean->water->sample(p.x, p.z, {.ripples = false}).height;
    }
}

Verdict HerdGoal::judge(ecs::World& world, double now, GoalEvents& events) {
    m_score = 0;
    for (size_t i = 0; i < m_herded.size(); ++i) {
        const ecs::Transform* t = world.find<ecs::Transform>(m_herded[i]);
        const bool in = t && glm::dot(xz(t->position) - m_centre, xz(t->position) - m_centre) <= m_radius * m_radius;
        if (in != m_inside[i]) {
            events.add(world, m_herded[i], in ? MarkState::Inside : MarkState::Outside, now);
            m_inside[i] = in;
        }
        m_score += in ? 1 : 0;
    }
    if (m_score >= m_needed) return {GameResult::Won, std::to_string(m_score) + " " + m_prefix + "s in the ring"};
    return {};
}

std::string HerdGoal::count() const {
    return m_prefix + "s in the ring " + std::to_string(m_score) + " / " + std::to_string(m_needed);
}

std::string HerdGoal::summary() const {
    return std::to_string(m_score) + " in the ring, " + std::to_string(m_needed) + " needed";
}

void HerdGoal::addStats(nlohmann::json& j) const {
    j["crates"] = m_herded.size();
    j["inside"] = m_score;
    j["needed"] = m_needed;
}

std::vector<GoalMark> HerdGoal::marks() const {
    std::vector<GoalMark> marks;
    for (size_t i = 0; i < m_herded.size(); ++i) marks.push_back({m_herded[i], m_inside[i] ? MarkState::Inside : MarkState::Outside});
    for (ecs::Entity e : m_markers) marks.push_back({e, MarkState::Zone});
    return marks;
}

} // namespace ob::game
