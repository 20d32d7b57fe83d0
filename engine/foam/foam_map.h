// Persistent foam: a coverage map in world space over the ripple patch, advected with the
// surface's horizontal velocity, fed by six sources, decaying exponentially. docs/splash_foam.md.
//
// Laws (coverage f ∈ [0, 1] per cell; N×N cells of side Δ = extent/N; cell (i, j) has its
// centre at origin() + (i, j)·Δ, i along x, j along z; row-major, index j·N + i):
//   transport  ∂f/∂t + u·∇f = −f/τ + S,  τ = [foam] decay_s, u the surface's horizontal velocity
//   step(dt)   f ← e^(−dt/τ) · f(x − u(x)·dt): semi-Lagrangian, linear between cell centres,
//              0 from outside the map; the decay is exact for any dt (no sources: f(t) = f(0)·e^(−t/τ)).
//              A uniform u reads one bilinear stencil; a per-cell u is split by axis (along x with
//              u_x, then along z with u_z; for a uniform u the same bilinear step)
//   sources    each add S·dt (or a fixed amount) to a cell, clamped to 1; call them between steps:
//     (a) whitecaps  S = whitecap_weight · max(0, J_0 − J), J the ocean's Jacobian at the cell
//                    centre (bilinear in the periodic cascade tile, at rest points), J_0 = whitecap_jacobian
//     (b) ripples    S = ripple_weight · max(0, |∇h| − s_0), |∇h| the ripple slope by central
//                    differences at the ripple cell nearest the cell centre, s_0 = ripple_slope
//     (c) drops      a landed drop of radius r adds splash_weight · π·(10·r)² / Δ² to its cell
//     (d) wake       a hull sphere (centre c, radius R, horizontal speed U > 0) adds
//                    S = wake_weight · U / R to every cell within R of c that lies behind it
//                    ((p − c)·u ≤ 0): a point it passes at lateral offset y gains
//                    wake_weight·sqrt(1 − (y/R)²)·m(y) (before decay and the clamp), nothing ahead of it;
//                    m(y) = 1 − wake_streaks·(½ + ½·n(y)) (wakeStreaks) lays it in streaks along the track
//     (e) turbulent wake  a segment of a stern's track of age a adds S = wake_weight·e^(−a/a_s)/a_s ·
//                    (R/b)·sqrt(1 − (y/b)²)·m(y·R/b) to the cells beside it within b(a) = sqrt(R² + 2·K·a)
//                    (a_s = wake_turbulence_s, K = wake_diffusivity): it widens and thins with age, and
//                    adds at most wake_weight on the track (R/b ≤ 1)
//     (f) bow wave   above the bow-spray speed U_b a bow sphere (radius R, speed U) breaks its bow wave
//                    along two arms from its shoulders (c + ½R·û ± R·side), back at the Kelvin angle
//                    θ = asin(1/3) either side, 8·R·q long, q = min(1, U/U_b − 1): the cells within w/2
//                    of an arm (w = max(2Δ, 0.3 m)) gain S = bow_weight·q·U·sin θ / w, so a point an arm
//                    sweeps over gains bow_weight·q
// The map scrolls in whole cells (centerOn), like the ripple patch, so foam stays put in the world.
// The per-cell velocity is either the caller's (velocityX/Z) or bilinear between the nodes of a
// coarse grid fixed in the world (setVelocityNodes, or update() from the water; the surface's
// velocity varies over a wavelength, not a cell). update() is the whole step in one sweep over
// the map: sources (a), (b), then the step, rows of both formed as it goes; its velocity grid
// re-evaluates a K-th of its node rows a step (K = flow_refresh_steps) and extrapolates each
// node linearly in time from its last two values (error ≤ max|∂²u/∂t²|·(T + s)·s/2, T = K·dt
// between the values, s < T the age).
// Rows are split over the worker pool (the sweep's from 256² only where this machine measured
// it faster: core/thread_choice.h); each cell's value depends only on the previous map, so the
// bits do not depend on the worker count.
#pragma once
#include "foam/foam_def.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob {
class StateHasher;
}
namespace ob::interaction {
class RipplePatch;
}
namespace ob::splash {
struct Landing;
}
namespace ob::water {
class CompositeWater;
}

namespace ob::foam {

/// How far update() lets the velocity grid's rest points miss (|α + D(α) − x|, metres): a
/// node's velocity is then a particle's up to 1 cm away, off by |∂u/∂x| times it at most
/// (a Gerstner wave: k·a·ω/(1 − k·a), 1 mm/s for a = 1 m, λ = 64 m).
constexpr float FLOW_REST_TOLERANCE = 0.01f;

/// How a landed drop's whitened disc relates to its radius (disc radius = this × r).
constexpr float DROP_FOAM_RADIUS_FACTOR = 10.0f;

/// The streaks of a wake (law (d), (e)): its foam is laid times m(y) = 1 − depth·(½ + ½·n(y)),
/// y the lateral offset from the track (m), n ∈ [−1, 1] a fixed sum of three sines of y
/// (wavelengths 0.9, 1.5, 2.6 m), so the foam lies in lines along the track as the bubbles of
/// a ship's wake gather where its longitudinal vortices converge.
float wakeStreaks(float y, float depth);

/// What one whole foam update reads (FoamMap::update); each part may be absent.
struct FoamInputs {
    std::span<const float> jacobian;  ///< (a) an ocean cascade's Jacobian, n×n floats row-major [j][i] at X = (i, j)·tile/n; empty: no whitecaps
    int jacobianN = 0;                ///< n
    float jacobianTile = 0.0f;        ///< tile, m
    const interaction::RipplePatch* ripples = nullptr;  ///< (b) steep ripples of its Vh(t); null: none
    const water::CompositeWater* water = nullptr;       ///< the surface velocity at its time(); null: the velocity set last
};

/// The foam coverage map (see the laws above).
class FoamMap {
public:
    /// A map of def.resolution² cells over a square of side `extent` metres (the caller resolves
    /// def.extent_m) centred on the cell nearest `centre` (world x, z). Coverage starts at 0, the velocity at 0.
    FoamMap(const FoamDef& def, float extent, glm::vec2 centre = glm::vec2(0.0f));

    /// Moves the map so its centre is the cell nearest `worldCentre` (scrolls the data; new cells 0).
    void centerOn(glm::vec2 worldCentre);
    /// Grid coordinates of a world (x, z): cell centres at integers.
    glm::vec2 toGrid(glm::vec2 world) const;
    /// World (x, z) of cell (0, 0)'s centre.
    glm::vec2 origin() const;
    /// Δ, metres per cell.
    float cellSize() const { return m_cell; }
    /// N, cells per side.
    int resolution() const { return m_n; }

    /// Coverage at world (x, z), bilinear between cell centres, 0 outside the map: "is there foam here".
    float sample(float x, float z) const;
    /// Coverage of every cell, row-major (index j·N + i), [0, 1]; writable (tests, tools).
    std::span<float> coverage() { return m_f; }
    std::span<const float> coverage() const { return m_f; }
    /// Mean coverage over the map.
    double mean() const;

    /// The same horizontal velocity u (m/s, world x and z) everywhere.
    void setUniformVelocity(glm::vec2 u);
    /// Per-cell velocity, m/s (row-major like coverage()); calling these switches the map to it.
    std::span<float> velocityX();
    std::span<float> velocityZ();
    /// Cells between two nodes of the velocity grid, s: resolution / min(flow_resolution, resolution).
    int flowStride() const { return m_n / std::min(m_def.flow_resolution, m_n); }
    /// Nodes per side of the velocity grid, N / s + 2. The grid is fixed in the world: its nodes
    /// sit on the centres of the world cells whose indices are multiples of s, node (0, 0) on the
    /// last one at or before the map's cell (0, 0) (flowNodeOrigin()), so N / s + 2 cover the
    /// map wherever it scrolls and a node keeps its place when it does.
    int flowNodes() const { return m_n / flowStride() + 2; }
    /// World cell index of node (0, 0), over s: ⌊cell (0, 0)'s world index / s⌋.
    glm::ivec2 flowNodeOrigin() const;
    /// World (x, z) of every node, row-major (index l·flowNodes() + k).
    std::vector<glm::vec2> flowNodePositions() const;
    /// Sets the per-cell velocity bilinear between the nodes' (m/s, world x and z; row-major
    /// like flowNodePositions(), for the map where it stands now); the weights are exact binary
    /// fractions (power-of-two stride). step() forms each row's velocities as it goes
    /// (velocityX/Z() switch back to their arrays).
    void setVelocityNodes(std::span<const glm::vec2> nodes);
    /// The nodes' velocity the next step uses (m/s; set, or update()'s extrapolation; empty before either).
    std::span<const glm::vec2> velocityNodes() const { return m_nodes; }

    // --- sources (laws (a)–(f) above), each clamped to coverage 1
    /// (a) Jacobian of an ocean cascade: n×n floats row-major [j][i] at X = (i, j)·tile/n (m).
    void addWhitecaps(std::span<const float> jacobian, int n, float tile, float dt);
    /// (b) steep ripples of the patch's Vh(t).
    void addRipples(const interaction::RipplePatch& patch, float dt);
    /// (c) landed splash drops, each spread over the four cells around it (bilinear weights).
    void addLandings(std::span<const splash::Landing> landings);
    /// (d) one hull sphere: centre (m), velocity (m/s; its horizontal part counts), radius (m).
    void addWake(const glm::vec3& centre, const glm::vec3& velocity, float radius, float dt);
    /// (e) one segment of a stern's track, from its older end to its newer (world x, z, m), of
    /// age a (s, at its middle), behind a stern sphere of radius R (m).
    void addWakeTrail(glm::vec2 from, glm::vec2 to, float age, float radius, float dt);
    /// (f) a bow sphere's breaking bow wave: centre (m), velocity (m/s; its horizontal part
    /// counts), radius (m), strength q = min(1, U/U_b − 1) (nothing when ≤ 0).
    void addBowWave(const glm::vec3& centre, const glm::vec3& velocity, float radius, float strength, float dt);

    /// Advects by the velocity and decays over dt seconds.
    void step(float dt);
    /// One whole update over dt in one sweep over the map: sources (a) and (b) from `in` (as
    /// addWhitecaps, addRipples), the velocity grid from in.water (a K-th of its node rows
    /// evaluated, the others extrapolated linearly in time, K = flow_refresh_steps; every node
    /// on the first call, after the time went back or jumped by over 0.5 s, and where the map
    /// scrolled onto new ones, twice), then step(dt). Without a water, the same bits as
    /// addWhitecaps, addRipples, then step.
    void update(const FoamInputs& in, float dt);

    const FoamDef& def() const { return m_def; }
    /// Changes the weights and decay from the next call on (resolution stays).
    void setDef(const FoamDef& def);
    /// Feeds the coverage and the map's placement to h.
    void hash(StateHasher& h) const;

private:
    enum class Flow { Still, Uniform, Field, Nodes };
    struct Sources;   // the per-call tables of sources (a) and (b) (foam_map.cpp)
    struct RowCache;  // a worker's rows of them
    struct FlowNode {  // a node of update()'s velocity grid: u(t) ≈ u + (t − time)·rate
        glm::vec2 u{0.0f}, rate{0.0f};  // m/s, m/s²
        glm::vec2 rest{0.0f};           // the rest point of the particle above it then, world m
        double time = 0.0;              // s, of its last evaluation
        int evaluations = 0;            // since it came onto the grid (a slope from the second on)
    };
    void add(int i, int j, float amount);
    void nodeRow(int j, int component, float* out, float* scratch) const;
    Sources sources(const FoamInputs& in, float dt) const;
    void addSources(const Sources& s);
    void refreshFlow(const water::CompositeWater& water);
    bool sweepFits(float dt) const;
    void sweep(const Sources* s, float dt);
    void splitStep(float dt);
    void chooseThreads();

    FoamDef m_def;
    int m_n;
    float m_cell;
    glm::ivec2 m_originCell{0, 0};  // world cell index of cell (0, 0)
    std::vector<float> m_f, m_next; // coverage; the step writes m_next, then swaps
    Flow m_flow = Flow::Still;
    glm::vec2 m_uniform{0.0f};
    std::vector<float> m_ux, m_uz;  // Flow::Field, m/s
    std::vector<glm::vec2> m_nodes; // Flow::Nodes, m/s (flowNodes()² row-major)
    glm::ivec2 m_nodesOrigin{0, 0}; // Flow::Nodes: flowNodeOrigin() when they were set
    float m_nodesMax = 0.0f;        // Flow::Nodes: the largest |u_x|, |u_z| of a node, m/s
    std::vector<float> m_nodeRows;  // sweep: the node rows expanded along x, [l][component][cell]
    std::vector<float> m_halo;      // sweep: copies of the rows around its chunks' boundaries
    int m_sweepThreads = 1 << 30;   // sweep: 1, or every worker (measured: chooseThreads)
    std::vector<FlowNode> m_grid;   // update()'s velocity grid (flowNodes()² row-major)
    glm::ivec2 m_gridOrigin{0, 0};  // its flowNodeOrigin()
    int m_gridStride = 0;           // its flowStride(); 0: none yet
    double m_gridTime = 0.0;        // the water's time at the last update(), s
    uint64_t m_updates = 0;         // update() calls with a water: picks the node rows to evaluate
    std::vector<float> m_split;     // Flow::Field, Nodes: the coverage after the x pass (see step)
    std::vector<float> m_zeros;     // Flow::Field, Nodes: a row of zeros, the rows beyond the map's edges
};

} // namespace ob::foam
