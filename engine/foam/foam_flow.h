// The velocity the foam map moves with (docs/splash_foam.md §2): still, uniform, per sample, or
// bilinear between the nodes of a coarse grid fixed in the world (the surface's velocity varies
// over a wavelength, not a cell), set by the caller or refreshed from the water.
//
// refresh() re-evaluates a K-th of the node rows a step (K = flow_refresh_steps) and carries
// each node between by linear extrapolation in time from its last two values (error ≤
// max|∂²u/∂t²|·(T + s)·s/2, T = K·dt between the values, s < T the age).
#pragma once
#include "core/scrolling_grid.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/geometric.hpp>

namespace ob::water {
class CompositeWater;
}

namespace ob::foam {

/// How far refresh() lets the velocity grid's rest points miss (|α + D(α) − x|, metres): a
/// node's velocity is then a particle's up to 1 cm away, off by |∂u/∂x| times it at most
/// (a Gerstner wave: k·a·ω/(1 − k·a), 1 mm/s for a = 1 m, λ = 64 m).
constexpr float FLOW_REST_TOLERANCE = 0.01f;

/// The streak cells: STREAK_MODES (12) rolls of random spacing, slant and drift (foamStreakModes), so
/// that their lines wander, merge and part rather than lie as a grating. Wavenumbers spread evenly
/// over [k/R, k], k = 2π/L, R = STREAK_SPACING_RANGE (one per stratum, jittered: spacings L to
/// R·L); axes slanted off the wind by up to ±STREAK_SLANT rad (so each line meanders along the wind over tens of metres,
/// where rolls of different slant beat); each roll's lines move across the wind at its own speed,
/// so the pattern renews over STREAK_LIFE_S (the windrows' lifetime of minutes), and all of it
/// drifts with the surface (WindFlow::drift).
constexpr int STREAK_MODES = 12;
constexpr double STREAK_SPACING_RANGE = 4.0;
/// The draws' seed: of the first 400 seeds, the one whose rolls' autocorrelation across the wind
/// (Σ (V_m·|K_m|)²·cos(K_m·ĉ·r), normalised) has the lowest secondary peak out to 60 m (0.28;
/// median 0.48).
constexpr uint64_t STREAK_SEED = 322;
constexpr double STREAK_SLANT = 0.06;
constexpr double STREAK_LIFE_S = 120.0;

/// One roll of streak cells: u = V·(cos θ·ŵ − sin θ·ĉ), θ = K·(p − drift·t) + ω·t + β.
struct StreakMode {
    glm::dvec2 k{0.0};   ///< K, rad/m, world x and z: mostly across the wind (|K| = 2π/spacing)
    double speed = 0.0;  ///< V_m, m/s
    double omega = 0.0;  ///< ω, rad/s (on top of the drift's −K·drift)
    double phase = 0.0;  ///< β, rad
};

/// The wind's part of the foam's velocity (docs/splash_foam.md §2.2), added to the water's in
/// every mode:
///   u_w(p) = drift + Σ_m V_m·(cos θ_m·ŵ − sin θ_m·ĉ),   θ_m = K_m·(p − drift·t) + ω_m·t + β_m,   ĉ = (−ŵ_z, ŵ_x),
/// drift the surface's mean drift (wind drift and Stokes drift, m/s). Each other term is a roll of
/// streak (Langmuir) cells whose axes lie nearly along the wind, 2π/|K_m| apart: the surface
/// converges toward its lines θ_m = 2π·j (across the wind at up to V_m) and diverges between them;
/// along the wind it runs V_m faster on the lines and V_m slower between. Their mean over the
/// cells is 0: foam drifts at `drift` on average. V_m = V·sqrt(2/M)·(L_m/L)^½: the rolls' mean
/// square speed that of two rolls of V, the wider ones faster. The rolls are foamStreakModes().
struct WindFlow {
    glm::vec2 drift{0.0f};            ///< m/s, world x and z
    glm::vec2 direction{1.0f, 0.0f};  ///< ŵ, unit, the way the wind blows
    float streakSpeed = 0.0f;         ///< V, m/s; 0: no streak cells
    float streakSpacing = 0.0f;       ///< L, m, the finest rolls' spacing; ≤ 0: no streak cells
    bool streaks() const { return streakSpeed > 0.0f && streakSpacing > 0.0f; }
    bool operator==(const WindFlow&) const = default;
};

/// The STREAK_MODES rolls for a wind (fixed pseudo-random draws: the same every run).
std::vector<StreakMode> foamStreakModes(const WindFlow& wind);

/// The horizontal surface velocity (m/s, world x and z) over a foam map's samples.

class FoamFlow {
public:
    enum class Mode { Still, Uniform, Field, Nodes };

    /// Still water over `grid` (the map's placement); nodes every n / min(flowResolution, n) samples.
    FoamFlow(const ScrollingGrid& grid, int flowResolution);

    Mode mode() const { return m_mode; }

    /// The same velocity u everywhere (m/s; 0: still).
    void setUniform(glm::vec2 u);
    glm::vec2 uniform() const { return m_uniform; }

    /// Per-sample velocity, m/s, row-major like the coverage; calling these switches to it. The
    /// caller refills it after a scroll (it is not moved).
    std::span<float> velocityX();
    std::span<float> velocityZ();
    std::span<const float> fieldX() const { return m_ux; }
    std::span<const float> fieldZ() const { return m_uz; }

    /// Samples between two nodes, s: n / min(flow_resolution, n) (a power of two).
    int stride() const { return m_grid.n / std::min(m_resolution, m_grid.n); }
    /// Nodes per side, n / s + 2. The grid is fixed in the world: its nodes sit on the world
    /// samples whose indices are multiples of s, node (0, 0) on the last one at or before the
    /// map's sample (0, 0) (nodeOrigin()), so n / s + 2 cover the map wherever it scrolls and a
    /// node keeps its place when it does.
    int nodesPerSide() const { return m_grid.n / stride() + 2; }
    /// World sample index of node (0, 0), over s: ⌊sample (0, 0)'s world index / s⌋.
    glm::ivec2 nodeOrigin() const;
    /// World (x, z) of every node, row-major (index l·nodesPerSide() + k).
    std::vector<glm::vec2> nodePositions() const;
    /// Sets the velocity bilinear between the nodes' (m/s, row-major like nodePositions(), for
    /// the map where it stands now); the weights are exact binary fractions (power-of-two stride).
    void setNodes(std::span<const glm::vec2> nodes);
    /// The nodes' velocity the next step uses (set, or refresh()'s extrapolation; empty before either).
    std::span<const glm::vec2> nodes() const { return m_nodes; }
    /// The largest |u_x|, |u_z| of a node, m/s (Mode::Nodes).
    float nodesMax() const { return m_nodesMax; }

    /// The nodes from the water at its time(): a K-th of the node rows evaluated (by world row
    /// index, K = refreshSteps), the others extrapolated linearly in time; every node on the first
    /// call, after the time went back or jumped by over 0.5 s, and where the map scrolled onto
    /// new ones, twice.
    void refresh(const water::CompositeWater& water, int refreshSteps);

    /// The map moved to `grid`: nodes set by setNodes keep their place in the world, shifted by
    /// whole nodes, the ones it scrolled onto copied from the nearest kept one.
    void follow(const ScrollingGrid& grid);
    /// A new flow_resolution (from the next step on); nodes that no longer fit are dropped (still).
    void setResolution(int flowResolution);

    /// The wind's part (WindFlow), added to the velocity of every mode; none at first.
    void setWind(const WindFlow& wind);
    /// The time t of the streak cells' phases (s; they drift and renew with it); 0 at first.
    void setWindTime(double t);
    /// The rolls of the streak cells (empty without them).
    std::span<const StreakMode> streakModes() const { return m_modes; }
    const WindFlow& wind() const { return m_wind; }
    /// Whether the wind adds anything; whether what it adds varies over the map (streak cells).
    bool windy() const { return m_wind.streaks() || m_wind.drift != glm::vec2(0.0f); }
    /// The largest |x|, |z| component the wind adds anywhere, m/s.
    float windMax() const;
    /// Map row j's wind component (0: x, 1: z) at each of its n samples (out).
    void windRow(int j, int component, float* out) const;
    /// Map row j's gathering over a step dt by the streak cells, at each of its n samples (out):
    /// 1 − dt·∇·u_w = 1 + dt·Σ_m V_m·((K_m·ĉ)·cos θ_m + (K_m·ŵ)·sin θ_m). Floating foam is not lost where the surface converges (it
    /// sinks, and the foam piles up) nor made where it diverges: the transport multiplies the
    /// advected coverage by it (the continuity equation ∂f/∂t + ∇·(u_w·f) = 0 for the wind's
    /// part; the waves' orbital part stays advective, its convergence undone within a period).
    /// All 1 without streak cells.
    void windGatherRow(int j, float dt, float* out) const;

    // --- the per-sample velocity from the nodes (Mode::Nodes), row by row
    /// Map row j's component (0: x, 1: z): the node rows around it lerped along z (into scratch,
    /// nodesPerSide() floats), then along x between each pair of nodes (n floats into out).
    void nodeRow(int j, int component, float* out, float* scratch) const;
    /// Node row l's component along x at every sample of a map row (n floats into out; scratch
    /// nodesPerSide() floats).
    void expandNodeRow(int l, int component, float* out, float* scratch) const;
    /// The node row l at or before map row j and the weight of row l + 1 (exact binary fraction).
    float nodeRowWeight(int j, int& l) const;

private:
    struct FlowNode {  // a node of refresh()'s grid: u(t) ≈ u + (t − time)·rate
        glm::vec2 u{0.0f}, rate{0.0f};  // m/s, m/s²
        glm::vec2 rest{0.0f};           // the rest point of the particle above it then, world m
        double time = 0.0;              // s, of its last evaluation
        int evaluations = 0;            // since it came onto the grid (a slope from the second on)
    };
    void alignHistory(double t);
    void extrapolateNodes(double t);
    glm::ivec2 nodeOffset() const;  // the map's sample (0, 0) past node (0, 0), samples, in [0, s)

    ScrollingGrid m_grid;              // the map's placement
    int m_resolution;                  // flow_resolution
    Mode m_mode = Mode::Still;
    glm::vec2 m_uniform{0.0f};
    std::vector<float> m_ux, m_uz;     // Mode::Field, m/s
    std::vector<glm::vec2> m_nodes;    // Mode::Nodes, m/s (nodesPerSide()² row-major)
    glm::ivec2 m_nodesOrigin{0, 0};    // Mode::Nodes: nodeOrigin() when they were set
    float m_nodesMax = 0.0f;           // Mode::Nodes: the largest |u_x|, |u_z| of a node, m/s
    std::vector<FlowNode> m_history;   // refresh()'s grid (nodesPerSide()² row-major)
    glm::ivec2 m_historyOrigin{0, 0};  // its nodeOrigin()
    int m_historyStride = 0;           // its stride(); 0: none yet
    double m_historyTime = 0.0;        // the water's time at the last refresh(), s
    uint64_t m_refreshes = 0;          // refresh() calls: pick the node rows to evaluate
    WindFlow m_wind;                   // setWind
    double m_windTime = 0.0;           // setWindTime
    std::vector<StreakMode> m_modes;   // the streak cells' rolls (setWind)
    std::vector<float> m_windCos, m_windSin;  // cos, sin of the x part of θ_m at each map column, [m][i] (refilled on a scroll)
    std::vector<float> m_rowCos, m_rowSin;    // cos, sin of the z part of θ_m at each map row, [m][j] (refilled on a scroll)
    std::vector<float> m_timeCos, m_timeSin;  // cos, sin of θ_m's part from the time, [m] (setWindTime)
    void fillWindTime();
    // cos, sin of θ_m's part from row j and the time.
    void rowPhase(size_t m, int j, float& c, float& s) const {
        const size_t k = m * size_t(m_grid.n) + size_t(j);
        c = m_rowCos[k] * m_timeCos[m] - m_rowSin[k] * m_timeSin[m];
        s = m_rowSin[k] * m_timeCos[m] + m_rowCos[k] * m_timeSin[m];
    }
    void fillWindColumns();                      // every entry of the tables below
    void fillWindTable(int axis, int lo, int hi);  // entries [lo, hi) of the column (0) or row (1) tables
    void scrollWindTables(glm::ivec2 shift);       // after the map moved by shift samples
};

} // namespace ob::foam
