// The velocity the foam map moves with (docs/splash_foam.md §2), by its mode: still, uniform,
// per sample, or bilinear between the nodes of a coarse grid fixed in the world (the surface's
// velocity varies over a wavelength, not a cell; foam_nodes.h), set by the caller or refreshed
// from the water; the wind's part (foam_wind.h) is added in every mode.
#pragma once
#include "core/scrolling_grid.h"
#include "foam/foam_nodes.h"
#include "foam/foam_wind.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace ob::foam {

/// The horizontal surface velocity (m/s, world x and z) over a foam map's samples.

/// The horizontal surface velocity over a foam map's samples: the mode's part, one object per
/// mode with state (the per-sample field here, FoamNodes), and the wind's (FoamWind).
class FoamFlow {
public:
    enum class Mode { Still, Uniform, Field, Nodes };

    /// Still water over `grid` (the map's placement); nodes every n / min(flowResolution, n) samples.
    FoamFlow(const ScrollingGrid& grid, int flowResolution) : m_grid(grid), m_nodes(grid, flowResolution), m_wind(grid) {}

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

    // --- Mode::Nodes (FoamNodes)
    /// Samples between two nodes, s: n / min(flow_resolution, n) (a power of two).
    int stride() const { return m_nodes.stride(); }
    /// Nodes per side, n / s + 2. The grid is fixed in the world: its nodes sit on the world
    /// samples whose indices are multiples of s, node (0, 0) on the last one at or before the
    /// map's sample (0, 0) (nodeOrigin()), so n / s + 2 cover the map wherever it scrolls and a
    /// node keeps its place when it does.
    int nodesPerSide() const { return m_nodes.perSide(); }
    /// World sample index of node (0, 0), over s: ⌊sample (0, 0)'s world index / s⌋.
    glm::ivec2 nodeOrigin() const { return m_nodes.origin(); }
    /// World (x, z) of every node, row-major (index l·nodesPerSide() + k).
    std::vector<glm::vec2> nodePositions() const { return m_nodes.positions(); }
    /// Sets the velocity bilinear between the nodes' (m/s, row-major like nodePositions(), for
    /// the map where it stands now); the weights are exact binary fractions (power-of-two stride).
    void setNodes(std::span<const glm::vec2> nodes);
    /// The nodes' velocity the next step uses (set, or refresh()'s extrapolation; empty before either).
    std::span<const glm::vec2> nodes() const { return m_nodes.values(); }
    /// The largest |u_x|, |u_z| of a node, m/s (Mode::Nodes).
    float nodesMax() const { return m_nodes.max(); }
    /// The nodes from the water at its time(): a K-th of the node rows evaluated (by world row
    /// index, K = refreshSteps), the others extrapolated linearly in time; every node on the first
    /// call, after the time went back or jumped by over 0.5 s, and where the map scrolled onto
    /// new ones, twice.
    void refresh(const water::CompositeWater& water, int refreshSteps);
    /// Map row j's component (0: x, 1: z): the node rows around it lerped along z (into scratch,
    /// nodesPerSide() floats), then along x between each pair of nodes (n floats into out).
    void nodeRow(int j, int component, float* out, float* scratch) const { m_nodes.row(j, component, out, scratch); }
    /// Node row l's component along x at every sample of a map row (n floats into out; scratch
    /// nodesPerSide() floats).
    void expandNodeRow(int l, int component, float* out, float* scratch) const { m_nodes.expandRow(l, component, out, scratch); }
    /// The node row l at or before map row j and the weight of row l + 1 (exact binary fraction).
    float nodeRowWeight(int j, int& l) const { return m_nodes.rowWeight(j, l); }

    /// The map moved to `grid`: nodes set by setNodes keep their place in the world, shifted by
    /// whole nodes, the ones it scrolled onto copied from the nearest kept one.
    void follow(const ScrollingGrid& grid);
    /// A new flow_resolution (from the next step on); nodes that no longer fit are dropped (still).
    void setResolution(int flowResolution);

    // --- the wind (FoamWind), added to the velocity of every mode; none at first
    void setWind(const WindFlow& wind) { m_wind.set(wind); }
    /// The time t of the streak cells' phases (s; they drift and renew with it); 0 at first.
    void setWindTime(double t) { m_wind.setTime(t); }
    /// The rolls of the streak cells (empty without them).
    std::span<const StreakMode> streakModes() const { return m_wind.modes(); }
    const WindFlow& wind() const { return m_wind.flow(); }
    /// Whether the wind adds anything; whether what it adds varies over the map (streak cells).
    bool windy() const { return m_wind.windy(); }
    /// The largest |x|, |z| component the wind adds anywhere, m/s.
    float windMax() const { return m_wind.max(); }
    /// Map row j's wind component (0: x, 1: z) at each of its n samples (out).
    void windRow(int j, int component, float* out) const { m_wind.row(j, component, out); }
    /// Map row j's gathering over a step dt by the streak cells, at each of its n samples (out):
    /// 1 − dt·∇·u_w = 1 + dt·Σ_m V_m·((K_m·ĉ)·cos θ_m + (K_m·ŵ)·sin θ_m). Floating foam is not lost where the surface converges (it
    /// sinks, and the foam piles up) nor made where it diverges: the transport multiplies the
    /// advected coverage by it (the continuity equation ∂f/∂t + ∇·(u_w·f) = 0 for the wind's
    /// part; the waves' orbital part stays advective, its convergence undone within a period).
    /// All 1 without streak cells.
    void windGatherRow(int j, float dt, float* out) const { m_wind.gatherRow(j, dt, out); }

private:
    ScrollingGrid m_grid;           // the map's placement
    Mode m_mode = Mode::Still;
    glm::vec2 m_uniform{0.0f};      // Mode::Uniform, m/s
    std::vector<float> m_ux, m_uz;  // Mode::Field, m/s
    FoamNodes m_nodes;              // Mode::Nodes
    FoamWind m_wind;                // every mode
};

} // namespace ob::foam
