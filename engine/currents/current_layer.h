// Surface current layer (docs/currents.md): a 2-D incompressible flow of the surface layer on its
// own scrolling grid, stepped unconditionally stably after Stam 1999, "Stable Fluids":
//   ∂u/∂t + (u·∇)u = −∇p/ρ + f,   ∇·u = 0,
// f the forcing (bodies' impulses, sources, wind, decay towards the background flow). A step:
// forcing, semi-Lagrangian self-advection (RK2 backtrace, bilinear), a uniform correction that
// gives the advection's momentum error back, then the pressure projection (FFT on the periodic
// patch; walls: preconditioned conjugate gradients for the remainder, no flow through a wall).
//
// Data layout: a staggered (MAC) grid. Cell (i, j)'s centre is at world origin + (i, j)·Δ (grid
// coordinates with cell centres at integers, as the ripple patch and rasteriseObstacles); u(i, j)
// is the x velocity on the face between cells (i, j) and (i + 1, j), at grid (i + ½, j), v(i, j)
// the z velocity on the face between (i, j) and (i, j + 1), at grid (i, j + ½). Both are stored
// with a ring of one ghost face around the n × n faces, holding the background flow (what enters
// the patch), row-major with stride n + 2: u(i, j) = uField()[(j + 1)·stride + i + 1].
#pragma once
#include "core/hash.h"
#include "core/scrolling_grid.h"
#include "core/worker_task.h"
#include "currents/currents_def.h"
#include "interaction/obstruction.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace ob::currents {

class CurrentProjection;

/// One named float array of the layer's state (a soak checks each is finite).
struct CurrentLevel {
    const char* name;               ///< "u", "v", "phi"
    std::span<const float> values;  ///< the array, ghost ring included
};

/// How the last step's wall solve went (none: iterations = 0).
struct WallSolve {
    int iterations = 0;     ///< conjugate-gradient iterations taken
    float residual = 0.0f;  ///< max |∇·u|·Δ over open cells after them, m/s
};

/// The current layer; see the file comment for the law and the layout.
class CurrentLayer {
public:
    /// A layer of def's grid centred on the world origin, at rest in the background flow;
    /// waterDensity ρ in kg/m³ (environment.water_density).
    CurrentLayer(const CurrentsDef& def, float waterDensity);
    ~CurrentLayer();
    CurrentLayer(const CurrentLayer&) = delete;
    CurrentLayer& operator=(const CurrentLayer&) = delete;

    /// Moves the grid in whole cells so its middle cell is nearest `world` (m); cells that enter
    /// hold the background flow.
    void centerOn(glm::vec2 world);
    /// The wind at 10 m, [x, z] m/s: the layer's drift tends to wind_drift·u10 in wind_time.
    void setWind(glm::vec2 u10);
    /// Fixed bodies, harbour walls and floating hulls as waterline footprints; rasterised at each
    /// step on the grid where it then stands (a cell whose centre is inside a footprint is a wall:
    /// no flow through its faces). Kept until the next call.
    void setWalls(std::span<const interaction::ObstacleShape> shapes);
    /// Adds `impulse` (N·s, horizontal [x, z]) of momentum at the next step, spread over a disc of
    /// `radius` m (at least one cell) around `world` with weights summing to 1 over the open faces
    /// it covers, so the layer's momentum changes by exactly `impulse` (none if it covers none).
    void addImpulse(glm::vec2 world, glm::vec2 impulse, float radius);
    /// Advances the layer by dt s; pipelined, on a worker: every other call but the grid's and
    /// the Def's waits for it first, so a reader sees the step done, whatever its thread.
    void step(float dt);
    /// Whether step() runs on a worker ([sim] pipelined).
    void setPipelined(bool on) { m_pipelined = on; }
    /// Steps run on a worker so far.
    uint64_t stepsOnWorker() const { return m_stepTask.started(); }
    /// Takes the LIVE keys (uniform, decay_time, wind_drift, arrows) of def from the next step.
    /// A new `uniform` moves the whole layer by the difference (the tide turning), departures kept.
    void retune(const CurrentsDef& def);
    /// Writes the face velocities, m/s: u and v n² each, row-major without the ghost ring
    /// (u[j·n + i] = u(i, j)); tests and tools that start from a given flow.
    void setFaces(std::span<const float> u, std::span<const float> v);

    /// The flow at a world point, [x, z] m/s: bilinear on the faces; outside the grid the
    /// background flow (uniform + the wind drift it tends to).
    glm::vec2 velocityAt(glm::vec2 world) const;
    /// The layer's own flow at `world` (velocityAt without the displacers' flow), m/s.
    glm::vec2 flowAt(glm::vec2 world) const;
    /// A hull moving through the layer pushes its water aside: the potential flow round a
    /// Rankine body, a 2-D source of `strength` q (m²/s of outflow) at `source` and the sink −q at
    /// `sink` (a hull of beam B moving at U along its keel: q = U·B, the flux its half-body
    /// parts; far away a dipole, 1/r²). Instantaneous and momentless, it is added to what
    /// velocityAt reads (bodies, foam), not stored. `core`: m, the radius inside which it is
    /// smoothed (|r|² + core²).
    struct Displacer {
        glm::vec2 source{0.0f}, sink{0.0f};  ///< world (x, z), m
        float strength = 0.0f;               ///< q, m²/s
        float core = 0.5f;                   ///< m
    };
    /// The displacers of this step (replacing the last ones).
    void setDisplacers(std::vector<Displacer> displacers) { m_displacers = std::move(displacers); }
    /// velocityAt for each point of `world` into `out` (same size).
    void velocityBatch(std::span<const glm::vec2> world, std::span<glm::vec2> out) const;
    /// The flow at cell (i, j)'s centre (the mean of its faces), m/s: what an arrow shows.
    glm::vec2 cellVelocity(int i, int j) const;
    /// The background flow now: uniform + the wind-driven drift, m/s.
    glm::vec2 background() const {
        join();
        return backgroundNow();
    }

    /// Total horizontal momentum of the layer, kg·m/s: ρ·depth·Δ²·Σu over the open faces.
    glm::vec2 momentum() const;
    /// max |∇·u|·Δ over the open cells, m/s (the discrete divergence the projection zeroes:
    /// face differences of the staggered grid, periodic at the patch's edges or, open, with its edge faces).
    float maxDivergence() const;
    /// The velocity's flux through the faces of the cells listed (indices j·n + i), m²/s: the sum
    /// over each listed cell's four faces of |u|·Δ (tests: the flow through a wall's cells).
    double fluxThrough(std::span<const uint32_t> cells) const;
    /// Whether cell (i, j) is a wall (after the last step's rasterisation).
    bool wall(int i, int j) const {
        join();
        return !m_solid.empty() && m_solid[size_t(j) * size_t(m_grid.n) + size_t(i)] != 0;
    }
    /// How the last step's wall solve went.
    WallSolve lastWallSolve() const {
        join();
        return m_wallSolve;
    }

    /// The grid: cells a side, cell size (m), world position of cell (0, 0)'s centre (m).
    int resolution() const { return m_grid.n; }
    float cellSize() const { return m_grid.cell; }
    glm::vec2 origin() const { return m_grid.origin(); }
    /// World point (m) → grid coordinates (cell centres at integers).
    glm::vec2 toGrid(glm::vec2 world) const { return m_grid.toGrid(world); }
    /// Row stride of the face arrays, n + 2 (a ghost face each side).
    int stride() const { return m_grid.n + 2; }
    /// The x and z face velocities, m/s (layout: file comment).
    std::span<const float> uField() const {
        join();
        return m_u;
    }
    std::span<const float> vField() const {
        join();
        return m_v;
    }
    /// The Def as the layer now uses it (LIVE keys as last retuned).
    const CurrentsDef& def() const { return m_def; }

    /// The float arrays of the state (a soak checks them).
    std::vector<CurrentLevel> levels() const;
    /// Whether every value of the state is finite.
    bool finite() const;
    /// Hashes the state (faces, pressure warm start, drift, grid position).
    void hashState(StateHasher& h) const;

    /// Switches the global momentum correction after the advection (on by default; tests switch
    /// it off to show the drift it removes).
    void setConserveMomentum(bool on) {
        join();
        m_conserve = on, m_sum = faceSum();
    }

private:
    struct Impulse {
        glm::vec2 world, impulse;
        float radius;
    };
    void join() const { m_stepTask.join(); }
    void stepNow(float dt);
    glm::vec2 backgroundNow() const { return m_def.uniform + m_drift; }
    size_t at(int i, int j) const { return size_t(j + 1) * size_t(m_grid.n + 2) + size_t(i + 1); }
    void rasteriseWalls();
    void applyForcing(float dt);
    void depositImpulse(const Impulse& imp);
    void fillGhosts();
    void zeroWallFaces();
    glm::dvec2 faceSum() const;
    void addUniform(glm::dvec2 du);
    void chooseThreads();

    CurrentsDef m_def;
    std::vector<Displacer> m_displacers;
    float m_rho;
    ScrollingGrid m_grid;
    std::vector<float> m_u, m_v;            // faces, (n + 2)² each
    std::vector<float> m_u0, m_v0;          // the advection's source copy
    std::vector<uint8_t> m_solid;           // n² cells, 1 = wall; empty while no wall ever
    std::vector<uint8_t> m_openU, m_openV;  // n² faces: 1 = both cells open (empty with no wall)
    std::vector<interaction::ObstacleShape> m_shapes;
    std::vector<interaction::ObstructionCell> m_cells;  // rasterisation scratch
    // What the wall mask was made from (rasteriseWalls keeps it while they stay).
    bool m_rastered = false;
    glm::ivec2 m_rasterOrigin{0};
    std::vector<interaction::ObstacleShape> m_rasterShapes;
    std::vector<Impulse> m_impulses;
    glm::vec2 m_wind{0.0f};
    glm::vec2 m_drift{0.0f};               // the wind-driven part of the background, m/s
    glm::vec2 m_appliedUniform{0.0f};      // the uniform the field holds (a retune shifts it at the next step)
    bool m_conserve = true;
    glm::dvec2 m_sum{0.0};                 // Σ over the open faces as the forcing left it (kept, not summed: see step())
    glm::dvec2 m_openCount{0.0};           // open u faces, open v faces
    bool m_walls = false;                  // some wall cell this step
    int m_threads = 1;                     // workers the advection and the projection's loops split over (measured)
    WallSolve m_wallSolve;
    std::unique_ptr<CurrentProjection> m_projection;
    bool m_pipelined = false;              // setPipelined
    WorkerTask m_stepTask;                 // the step in flight (last: destroyed first, joining it)
};

} // namespace ob::currents
