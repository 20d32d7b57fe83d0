// Ripple patch placement, world sampling and per-sphere stamping; the solver from the table.
#include "interaction/ripple_patch.h"

#include <cassert>
#include <glm/geometric.hpp>

namespace ob::interaction {

std::vector<RippleDefError> validate(const RippleDef& def) {
    return RippleModels::visit(size_t(def.model), [&]<class Model>() { return Model::validate(def); });
}

static std::unique_ptr<RippleSolver> makeSolver(const RippleDef& def) {
    assert(validate(def).empty());
    return RippleModels::visit(size_t(def.model), [&]<class Model>() { return Model::make(def); });
}

RipplePatch::RipplePatch(const RippleDef& def) : RipplePatch(def, makeSolver(def)) {}

RipplePatch::RipplePatch(const RippleDef& def, std::unique_ptr<RippleSolver> solver)
    : m_def(def), m_grid(ScrollingGrid::centredOn(def.center, def.cell_size, def.resolution)), m_solver(std::move(solver)) {
    assert(m_solver && m_solver->rows() == def.resolution && m_solver->cols() == def.resolution);
}

RipplePatch::~RipplePatch() = default;

void RipplePatch::retune(const RippleDef& def) {
    static_cast<RippleModels::Defs&>(m_def) = def;
    m_solver->retune(m_def);
}

void RipplePatch::centerOn(glm::vec2 worldCenter) {
    const glm::ivec2 shift = m_grid.centreOn(worldCenter);
    if (shift != glm::ivec2(0)) m_solver->scroll(shift);
}

// No obstacles, and none before: the solver is not told, so its step is what it always was.
// Hulls only where ripples.hulls_obstruct is on and the model takes them (obstructsHulls).
void RipplePatch::step(float dt) {
    if (!m_def.hulls_obstruct || !m_solver->obstructsHulls())
        std::erase_if(m_obstacles, [](const ObstacleShape& s) { return s.displaces; });
    if (!m_obstacles.empty() || !m_obstruction.empty()) {
        rasteriseObstacles(m_obstacles, rows(), cols(), m_def.cell_size, [this](glm::vec2 w) { return toGrid(w); },
                           m_obstruction);
        m_solver->setObstruction(m_obstruction);
    }
    m_solver->step(dt);
}

float RipplePatch::heightAt(glm::vec2 world) const { return bilinear(height(), rows(), cols(), toGrid(world)); }

bool RipplePatch::stampSphere(const BoundingSphere& sphere, SphereContact& contact, const glm::vec3& centre,
                              const glm::vec3& velocity, float mass, float surfaceY) {
    const glm::vec2 g = toGrid(glm::vec2(centre.x, centre.z));
    SphereMotion motion;
    motion.gridX = g.x;
    motion.gridZ = g.y;
    motion.centreY = centre.y;
    motion.verticalVelocity = velocity.y;
    motion.speed = glm::length(velocity);
    motion.mass = mass;
    motion.surfaceY = surfaceY;
    return m_solver->addSphere(sphere, contact, motion);
}

} // namespace ob::interaction
