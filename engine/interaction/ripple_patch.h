// The ripple patch in the world: a ripple solver (RippleSolver, the Def's model) placed on a
// square of the water plane, moved in whole cells (the solver's data scrolls with it so waves
// stay put), sampled and stamped by world position, with the coarse levels of its model around
// it (ripples.levels > 1, interaction/ripple_levels.h). It knows no model: every model is a
// RippleSolver to it.
#pragma once
#include "core/scrolling_grid.h"
#include "core/worker_task.h"
#include "interaction/ripple_def.h"
#include "interaction/ripple_levels.h"
#include "interaction/ripple_solver.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>

namespace ob::interaction {

/// The Def's solver (RippleModels: its model's make) on a ScrollingGrid. Where the grid is,
/// and world ↔ grid, are the patch's; everything about the waves is the solver's.
class RipplePatch {
public:
    /// The Def's model's solver, centred on def.center. The Def is checked (validate).
    explicit RipplePatch(const RippleDef& def);
    /// A given solver of def.resolution cells a side (a test's, a new model's before it is
    /// registered), centred on def.center; def.model is not read. With def.levels > 1 the
    /// coarse levels are the solver's makeLevel; std::invalid_argument with its levelRefusal()
    /// where it has none.
    RipplePatch(const RippleDef& def, std::unique_ptr<RippleSolver> solver);
    ~RipplePatch();

    /// The solver: what splash, tools, hashing and dumps talk to.
    RippleSolver& solver() { return *m_solver; }
    const RippleSolver& solver() const { return *m_solver; }
    /// The solver as its concrete type, or null (tests that write a model's own state).
    template <class S> S* solverAs() { return dynamic_cast<S*>(m_solver.get()); }
    template <class S> const S* solverAs() const { return dynamic_cast<const S*>(m_solver.get()); }
    /// The coarse levels 1..K−1 around the solver's grid (ripples.levels = K > 1), or null (their
    /// step in flight waited for).
    const RippleLevels* levels() const {
        joinLevels();
        return m_levels.get();
    }
    RippleLevels* levels() {
        joinLevels();
        return m_levels.get();
    }
    /// [sim] pipelined: from the next step on, the coarse levels' step (on the frames one is due)
    /// runs on a worker thread, and whatever reads or writes them next waits for it, so the
    /// state is the same bits; levelHeight meanwhile gives the last finished heights.
    void setPipelined(bool on) { m_pipelined = on; }
    /// The levels of the composite, the solver's own grid (level 0) and the coarse ones: 1 + K − 1.
    int levelCount() const;
    /// Level L's placement (0: the patch's own grid).
    const ScrollingGrid& levelGrid(int L) const;
    /// Coarse level L (≥ 1) as the renderer draws it: its two states, uploaded when they change,
    /// and the cubic's weights at this frame (the shader evaluates it: RippleLevels::draw). While
    /// their step is in flight (pipelined), the last finished states.
    LevelDraw levelDraw(int L);
    /// The composite's fade band, cells of each level (RippleLevels::sponge; 0 without levels).
    int fadeCells() const;
    /// True once the solver steps on its GPU twin (interaction/gpu/attachGpu).
    bool onGpu() const { return m_solver->onGpu(); }

    /// Moves the patch so its centre is the cell nearest `worldCenter` (scrolls the solver).
    void centerOn(glm::vec2 worldCenter);
    /// Grid coordinates (column x, row z; cell centres at integers) of a world (x, z).
    glm::vec2 toGrid(glm::vec2 world) const { return m_grid.toGrid(world); }
    /// The height at world (x, z), bilinear between cell centres; 0 outside the patch (m). With
    /// levels: the composite, each level's bilinear height cross-faded (RippleLevels::composite).
    float heightAt(glm::vec2 world) const;
    /// The vertical velocity at world (x, z), m/s (the solver's, see RippleSolver::velocityAt;
    /// with levels the composite, as heightAt).
    float velocityAt(glm::vec2 world, float dt) const;
    /// The horizontal surface velocity at world (x, z), (x, z) components in m/s (the solver's, see
    /// RippleSolver::horizontalVelocityAt: 0 for kang2008; with levels the composite, as heightAt).
    glm::vec2 horizontalVelocityAt(glm::vec2 world) const;
    /// The wavenumber the layer's vertical velocity variance is centred on, Σ|K|·|v̂|²/Σ|v̂|² over
    /// the solver's own grid's modes after the last step, rad/m; 0 when still (and for kang2008).
    /// For an e^{kz} decay of the layer's velocity below the surface.
    float velocityWavenumber() const { return m_solver->velocityWavenumber(); }
    /// The composite's weight of the solver's own grid (level 0) at world (x, z): 1 without levels.
    float fineWeight(glm::vec2 world) const;
    /// World (x, z) of cell (0, 0)'s centre.
    glm::vec2 origin() const { return m_grid.origin(); }

    /// Table 2 and the solver's source for one sphere this step; world centre, m; velocity
    /// m/s; mass kg; surfaceY the water height there, m. True: it stamped.
    bool stampSphere(const BoundingSphere& sphere, SphereContact& contact, const glm::vec3& centre,
                     const glm::vec3& velocity, float mass, float surfaceY);
    /// A splash drop's crater of `volume` m³ (< 0: a hollow) at world (x, z): on the solver's
    /// grid as addHeight of volume / Δ² at the nearest cell (not the outer ring), and with levels
    /// on every coarse level that holds the point (RippleLevels::addCrater, the same volume).
    /// True: some level took it.
    bool addCrater(glm::vec2 world, double volume);
    /// The footprints of the bodies that cut the surface this step (world m; fixed bodies,
    /// hulls), replacing the last ones: step() rasterises them on the grid where it then
    /// stands and hands the cells to the solver (RippleSolver::setObstruction).
    void setObstacles(std::span<const ObstacleShape> shapes) { m_obstacles.assign(shapes.begin(), shapes.end()); }
    /// The cells the last step obstructed (interaction/obstruction.h), for tests and views.
    std::span<const ObstructionCell> obstruction() const { return m_obstruction; }
    /// One step of dt seconds (the obstacles rasterised first, when there are or were some).
    void step(float dt);

    /// The solver's state, then every coarse level's (the state hash).
    void hashState(StateHasher& h) const;

    const RippleDef& def() const { return m_def; }
    /// Takes `def`'s solver keys (every model's: ripples.damping, .decay_time, .viscosity)
    /// from the next step on; the rest of `def` is not read.
    void retune(const RippleDef& def);

    /// The solver's height level, rows·cols row-major (z·cols + x), m: what the renderer
    /// uploads and dumps write.
    std::span<const float> height() const { return m_solver->height(); }
    /// Rows (z) of the height level.
    int rows() const { return m_solver->rows(); }
    /// Columns (x) of the height level.
    int cols() const { return m_solver->cols(); }

private:
    // Waits for the coarse levels' step in flight, if any (from any thread: queries may run in parallel).
    void joinLevels() const;

    RippleDef m_def;
    ScrollingGrid m_grid;  // placement: origin cell, cell size, resolution
    std::unique_ptr<RippleSolver> m_solver;
    std::unique_ptr<RippleLevels> m_levels;       // levels 1..K−1, null when K = 1
    std::vector<ObstacleShape> m_obstacles;       // setObstacles', world m
    std::vector<ObstructionCell> m_obstruction;   // their cells at the last step
    bool m_pipelined = false;                     // setPipelined
    int64_t m_frames = 0;                         // steps so far (the levels' frame count)
    WorkerTask m_levelsStep;                      // the coarse levels' step in flight
};

} // namespace ob::interaction
