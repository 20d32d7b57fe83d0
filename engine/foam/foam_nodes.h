// The foam's velocity on a coarse grid of nodes fixed in the world (FoamFlow's Mode::Nodes),
// bilinear between them: set by the caller, or refreshed from the water a K-th of its rows a
// step, each node between carried by linear extrapolation in time from its last two values
// (error ≤ max|∂²u/∂t²|·(T + s)·s/2, T = K·dt between the values, s < T the age).
#pragma once
#include "core/scrolling_grid.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec2.hpp>

namespace ob::water {
class CompositeWater;
}

namespace ob::foam {

/// How far refresh() lets the velocity grid's rest points miss (|α + D(α) − x|, metres): a
/// node's velocity is then a particle's up to 1 cm away, off by |∂u/∂x| times it at most
/// (a Gerstner wave: k·a·ω/(1 − k·a), 1 mm/s for a = 1 m, λ = 64 m).
constexpr float FLOW_REST_TOLERANCE = 0.01f;

/// The node grid over a foam map's placement; nodes every n / min(flowResolution, n) samples.
class FoamNodes {
public:
    FoamNodes(const ScrollingGrid& grid, int flowResolution) : m_grid(grid), m_resolution(flowResolution) {}

    /// Samples between two nodes, s: n / min(flow_resolution, n) (a power of two).
    int stride() const { return m_grid.n / std::min(m_resolution, m_grid.n); }
    /// Nodes per side, n / s + 2 (FoamFlow::nodesPerSide).
    int perSide() const { return m_grid.n / stride() + 2; }
    /// World sample index of node (0, 0), over s: ⌊sample (0, 0)'s world index / s⌋.
    glm::ivec2 origin() const;
    /// World (x, z) of every node, row-major (index l·perSide() + k).
    std::vector<glm::vec2> positions() const;
    /// Sets the nodes' velocity (m/s, row-major like positions(), for the map where it stands now).
    void set(std::span<const glm::vec2> nodes);
    /// The nodes' velocity the next step uses (set, or refresh()'s extrapolation; empty before either).
    std::span<const glm::vec2> values() const { return m_nodes; }
    /// The largest |u_x|, |u_z| of a node, m/s.
    float max() const { return m_max; }
    /// The nodes from the water at its time() (FoamFlow::refresh).
    void refresh(const water::CompositeWater& water, int refreshSteps);
    /// The map moved to `grid`; `shift`: the nodes keep their place in the world, shifted by whole
    /// nodes, the ones it scrolled onto copied from the nearest kept one.
    void follow(const ScrollingGrid& grid, bool shift);
    /// A new flow_resolution; true when the stride changed (the nodes no longer fit).
    bool setResolution(int flowResolution);
    /// Drops the nodes.
    void clear() { m_nodes.clear(); }

    /// Map row j's component (0: x, 1: z), FoamFlow::nodeRow.
    void row(int j, int component, float* out, float* scratch) const;
    /// Node row l's component along x at every sample of a map row, FoamFlow::expandNodeRow.
    void expandRow(int l, int component, float* out, float* scratch) const;
    /// The node row l at or before map row j and the weight of row l + 1 (exact binary fraction).
    float rowWeight(int j, int& l) const;

private:
    struct FlowNode {  // a node of refresh()'s grid: u(t) ≈ u + (t − time)·rate
        glm::vec2 u{0.0f}, rate{0.0f};  // m/s, m/s²
        glm::vec2 rest{0.0f};           // the rest point of the particle above it then, world m
        double time = 0.0;              // s, of its last evaluation
        int evaluations = 0;            // since it came onto the grid (a slope from the second on)
    };
    void alignHistory(double t);
    void extrapolate(double t);
    glm::ivec2 offset() const;  // the map's sample (0, 0) past node (0, 0), samples, in [0, s)

    ScrollingGrid m_grid;              // the map's placement
    int m_resolution;                  // flow_resolution
    std::vector<glm::vec2> m_nodes;    // m/s (perSide()² row-major)
    glm::ivec2 m_origin{0, 0};         // origin() when they were set
    float m_max = 0.0f;                // the largest |u_x|, |u_z| of a node, m/s
    std::vector<FlowNode> m_history;   // refresh()'s grid (perSide()² row-major)
    glm::ivec2 m_historyOrigin{0, 0};  // its origin()
    int m_historyStride = 0;           // its stride(); 0: none yet
    double m_historyTime = 0.0;        // the water's time at the last refresh(), s
    uint64_t m_refreshes = 0;          // refresh() calls: pick the node rows to evaluate
};

} // namespace ob::foam
