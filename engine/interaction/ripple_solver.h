// The ripple solver interface: what the patch (and through it splash, tools, hashing, dumps)
// asks of any ripple model. Each model implements it in its own folder (kang2008/, ewave/)
// and registers it in ripple_solvers.h.
#pragma once
#include "core/hash.h"
#include "interaction/obstruction.h"
#include "interaction/sphere_stamp.h"

#include <cmath>
#include <glm/vec2.hpp>
#include <memory>
#include <span>
#include <vector>

namespace ob::interaction {

struct RippleDef;

/// One named float level of a solver's state (a soak checks each is finite).
struct RippleLevel {
    const char* name;               ///< "Vh(t)", "h", … as messages name it
    std::span<const float> values;  ///< rows·cols, row-major (z·cols + x)
};

/// A pressure source as the level stack (interaction/ripple_levels.h) carries it from one level
/// to the next: centre and radius in the grid's cells, accel m/s² at the centre over one step.
struct LevelSource {
    float gx = 0.0f, gz = 0.0f;  ///< exact centre, cells (column x, row z)
    float radiusCells = 0.0f;    ///< R, cells
    float accel = 0.0f;          ///< m/s² at the centre, + lifts the water
};

/// A solver's state at the end of one of its steps as a coarse level of the stack keeps it: the
/// two ends of the cubic in time that the stack reads between its steps. rows·cols row-major.
struct LevelState {
    std::vector<float> h;      ///< height, m
    std::vector<float> v;      ///< its rate ∂h/∂t less its mean, m/s (the mean is no motion)
    std::vector<float> xi[2];  ///< horizontal displacement per axis x, z, m; empty: the model has no horizontal velocity
    std::vector<float> u[2];   ///< its rate, the horizontal surface velocity, m/s; empty with xi
};

/// A ripple solver on a rows × cols grid of square cells (row = z, column = x, row-major),
/// in grid coordinates: cell centres at integers. Where the grid is in the world is the
/// patch's business (RipplePatch), not the solver's.
class RippleSolver {
public:
    virtual ~RippleSolver() = default;

    /// Rows (z) of the grid.
    virtual int rows() const = 0;
    /// Columns (x) of the grid.
    virtual int cols() const = 0;
    /// Table 2 for one bounding sphere this step (planStamp: contact, SD, AF, SR = radius in
    /// metres / the cell size); when the sphere stamps, its stamp becomes this model's source,
    /// applied by the next step() at the latest. `motion` in grid coordinates. True: stamped.
    virtual bool addSphere(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion) = 0;
    /// Adds dh metres to the height of cell (x, z), in range (a splash drop's crater).
    virtual void addHeight(int x, int z, double dh) = 0;
    /// One step of dt seconds (> 0), this step's sources applied, then the obstruction.
    virtual void step(float dt) = 0;
    /// The cells bodies occupy on the surface (interaction/obstruction.h: fixed bodies, hulls),
    /// for the steps from the next on until set again: after each step every level of the state
    /// is scaled there by the cell's keep factor towards its level (0, or a hull's hollow) and
    /// what that moved is spread evenly over the grid (the mean level kept). Empty (the default): no obstruction, the step as before.
    virtual void setObstruction(std::span<const ObstructionCell> cells) = 0;
    /// Whether floating hulls (displacing footprints: their water held at their hollow, no
    /// source inside) obstruct this model; false: the patch hands it fixed bodies only
    /// (kang2008: the paper's ship is its six spheres).
    virtual bool obstructsHulls() const { return true; }
    /// Moves the data by `shift` cells, new (i, j) = old (i + shift.x, j + shift.y), cells
    /// from outside 0 (scrollCells), so the waves stay put in the world while the grid moves.
    virtual void scroll(glm::ivec2 shift) = 0;
    /// The whole state 0.
    virtual void clear() = 0;
    /// The current height level, rows·cols row-major, m: what sampling, rendering and dumps read.
    virtual std::span<const float> height() const = 0;
    /// The vertical velocity at grid position `g` (bilinear between cell centres; 0 off the
    /// interior), m/s; dt is the step in s (a two-level model differences its levels over it).
    virtual float velocityAt(glm::vec2 g, float dt) const = 0;
    /// The horizontal surface velocity at grid position `g` (bilinear between cell centres; 0 off
    /// the interior, as velocityAt), world (x, z), m/s. The default is none: a model without a
    /// velocity law (kang2008's height field) contributes its vertical velocity only.
    virtual glm::vec2 horizontalVelocityAt(glm::vec2 /*g*/) const { return {0.0f, 0.0f}; }
    /// The wavenumber the vertical velocity's variance is centred on over the grid's modes after
    /// the last step, rad/m (a caller's e^{kz} decay below the surface); 0 when still or unknown
    /// (the default).
    virtual float velocityWavenumber() const { return 0.0f; }
    /// The float levels of the state, the height first (a soak checks them).
    virtual std::vector<RippleLevel> levels() const = 0;
    /// Feeds the whole state that the next step reads, bit for bit, to `h` (the state hash).
    virtual void hashState(StateHasher& h) const = 0;
    /// Takes the Def's keys that may change live (ripples.damping, .decay_time, .viscosity):
    /// from the next step on.
    virtual void retune(const RippleDef& def) = 0;
    /// True once its step runs on a GPU twin (the model's moveToGpu).
    virtual bool onGpu() const = 0;
    /// Where it runs, for the log: "cpu", "cpu (FFTW)", "gpu (compute shaders)", ….
    virtual const char* backendName() const = 0;

    // --- nesting: coarse levels of this model around the patch's grid (ripples.levels > 1; the
    // stack, interaction/ripple_levels.h, asks a model only this). A model that cannot be nested
    // keeps the defaults: levelRefusal() says why, and the Def's check refuses levels > 1.

    /// Why this model cannot be a coarse level, or null when it can (the default: it cannot).
    virtual const char* levelRefusal() const { return "this ripple model has no coarse levels (RippleSolver::makeLevel)"; }
    /// A solver of this model and settings on the same grid size with cells `cellSize` metres,
    /// still water: a coarse level (its keepLevelState full from its first step). Null where
    /// levelRefusal() is not.
    virtual std::unique_ptr<RippleSolver> makeLevel(float /*cellSize*/) const { return nullptr; }
    /// The width of the absorbing band, cells, as the solver clamps it: the composite's fade band.
    virtual int spongeCells() const { return 1; }
    /// addSphere's decision and source without queuing it: true and `out` set when it stamps.
    virtual bool planLevelSource(const BoundingSphere& /*sphere*/, SphereContact& /*contact*/, const SphereMotion& /*motion*/,
                                 LevelSource& /*out*/) const {
        return false;
    }
    /// Queues a source (planLevelSource's, or one carried from a finer level) for the next step.
    virtual void addLevelSource(const LevelSource& /*source*/) {}
    /// The state the last step left, into `out` (each vector rows·cols, or xi, u empty).
    virtual void keepLevelState(LevelState& /*out*/) const {}
};

/// Bilinear sample of a row-major rows × cols level (float or double) at grid position g,
/// 0 where the 2×2 neighbourhood leaves the grid: the one sampler of patch and solvers.
template <class T>
float bilinear(std::span<const T> level, int rows, int cols, glm::vec2 g) {
    const float fx = std::floor(g.x), fz = std::floor(g.y);
    const int x0 = int(fx), z0 = int(fz);
    if (x0 < 0 || z0 < 0 || x0 + 1 >= cols || z0 + 1 >= rows) return 0.0f;
    const float tx = g.x - fx, tz = g.y - fz;
    const T* r0 = &level[size_t(z0) * size_t(cols) + size_t(x0)];
    const T* r1 = r0 + cols;
    return float((r0[0] * T(1 - tx) + r0[1] * T(tx)) * T(1 - tz) + (r1[0] * T(1 - tx) + r1[1] * T(tx)) * T(tz));
}

} // namespace ob::interaction
