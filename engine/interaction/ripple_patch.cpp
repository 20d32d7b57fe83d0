// Ripple patch placement, world sampling and per-sphere stamping; the solver from the table.
#include "interaction/ripple_patch.h"

#include "interaction/ripple_arrays.h"
#include "interaction/ripple_levels.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace ob::interaction {

std::vector<RippleDefError> validate(const RippleDef& def) {
    return RippleModels::visit(size_t(def.model), [&]<class Model>() { return Model::validate(def); });
}

void stepRippleArrays(std::string_view model, RippleArrays& arrays) {
    RippleModels::forEach([&]<class Model>() {
        if (model == Model::NAME) Model::stepArrays(arrays);
    });
}

static std::unique_ptr<RippleSolver> makeSolver(const RippleDef& def) {
    assert(validate(def).empty());
    return RippleModels::visit(size_t(def.model), [&]<class Model>() { return Model::make(def); });
}

RipplePatch::RipplePatch(const RippleDef& def) : RipplePatch(def, makeSolver(def)) {}

RipplePatch::RipplePatch(const RippleDef& def, std::unique_ptr<RippleSolver> solver)
    : m_def(def), m_grid(ScrollingGrid::centredOn(def.center, def.cell_size, def.resolution)), m_solver(std::move(solver)) {
    assert(m_solver && m_solver->rows() == def.resolution && m_solver->cols() == def.resolution);
    if (def.levels <= 1) return;
    if (const char* why = m_solver->levelRefusal()) throw std::invalid_argument(std::string("ripples.levels: ") + why);
    m_levels = std::make_unique<RippleLevels>(def, *m_solver);
}

int RipplePatch::levelCount() const { return m_levels ? m_levels->count() : 1; }

// The levels' grids move in centerOn only (on this thread, their step waited for).
const ScrollingGrid& RipplePatch::levelGrid(int L) const { return L == 0 ? m_grid : m_levels->grid(L); }

LevelDraw RipplePatch::levelDraw(int L) {
    if (!m_levelsStep.running()) {  // else the last published states: the step writes its own, never those
        joinLevels();
        m_levels->publish();
    }
    return m_levels->draw(L, m_frames);
}

int RipplePatch::fadeCells() const { return m_levels ? m_levels->sponge() : 0; }

RipplePatch::~RipplePatch() { joinLevels(); }

void RipplePatch::joinLevels() const { m_levelsStep.join(); }

void RipplePatch::retune(const RippleDef& def) {
    joinLevels();
    static_cast<RippleModels::Defs&>(m_def) = def;
    m_solver->retune(m_def);
    if (m_levels) m_levels->retune(m_def);
}

void RipplePatch::centerOn(glm::vec2 worldCenter) {
    const glm::ivec2 shift = m_grid.centreOn(worldCenter);
    if (shift != glm::ivec2(0)) m_solver->scroll(shift);
    joinLevels();
    if (m_levels) m_levels->centerOn(worldCenter);
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
    ++m_frames;
    if (!m_levels) return;
    joinLevels();
    if (!m_pipelined || m_levels->onGpu() || !m_levels->stepDue()) {  // a GPU twin steps where its GL context is
        m_levels->step(dt, m_obstacles);
        return;
    }
    // On a worker: what it reads (the levels, a copy of the obstacles) nothing else touches
    // until joinLevels.
    m_levelsStep.start([levels = m_levels.get(), dt, obstacles = m_obstacles] { levels->step(dt, obstacles); });
}

float RipplePatch::fineWeight(glm::vec2 world) const {
    return m_levels ? levelWeight(toGrid(world), cols(), m_levels->sponge()) : 1.0f;
}

float RipplePatch::heightAt(glm::vec2 world) const {
    const float fine = bilinear(height(), rows(), cols(), toGrid(world));
    if (!m_levels) return fine;
    joinLevels();
    return m_levels->composite(world, fine, fineWeight(world), [this](int L, glm::vec2 w) { return m_levels->heightAt(L, w); });
}

float RipplePatch::velocityAt(glm::vec2 world, float dt) const {
    const float fine = m_solver->velocityAt(toGrid(world), dt);
    if (!m_levels) return fine;
    joinLevels();
    return m_levels->composite(world, fine, fineWeight(world), [this](int L, glm::vec2 w) { return m_levels->velocityAt(L, w); });
}

glm::vec2 RipplePatch::horizontalVelocityAt(glm::vec2 world) const {
    const glm::vec2 fine = m_solver->horizontalVelocityAt(toGrid(world));
    if (!m_levels) return fine;
    joinLevels();
    return m_levels->composite(world, fine, fineWeight(world),
                               [this](int L, glm::vec2 w) { return m_levels->horizontalVelocityAt(L, w); });
}

void RipplePatch::hashState(StateHasher& h) const {
    joinLevels();
    m_solver->hashState(h);
    if (m_levels) m_levels->hashState(h);
}

bool RipplePatch::addCrater(glm::vec2 world, double volume) {
    const glm::vec2 g = toGrid(world);
    const long ix = std::lround(g.x), iz = std::lround(g.y);
    const bool fine = ix >= 1 && iz >= 1 && ix <= cols() - 2 && iz <= rows() - 2;  // the outer ring stays 0
    const double cell = m_def.cell_size;
    if (fine) m_solver->addHeight(int(ix), int(iz), volume / (cell * cell));
    joinLevels();
    const bool coarse = m_levels && m_levels->addCrater(world, volume, 1);
    return fine || coarse;
}

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
    if (!m_levels) return m_solver->addSphere(sphere, contact, motion);
    joinLevels();
    // Levels: the finest level that the composite reads at the centre plans the stamp, and
    // its source goes to every coarser level too (EWaveLevels::pushSource).
    const glm::vec2 at(centre.x, centre.z);
    if (fineWeight(at) <= 0.0f) return m_levels->stampSphere(sphere, contact, motion, at);
    LevelSource s;
    if (!m_solver->planLevelSource(sphere, contact, motion, s)) return false;
    m_solver->addLevelSource(s);
    m_levels->pushSource(at, std::max(s.radiusCells, 1.0f) * m_def.cell_size, s.accel, 1);
    return true;
}

} // namespace ob::interaction
