// The velocity the foam map moves with: still, uniform, per cell, or a grid of nodes fixed in
// the world and refreshed from the water a K-th of its rows a step (laws in foam_map.h).
#include "foam/foam_map.h"

#include "water/composite_water.h"

#include <algorithm>
#include <cmath>

namespace ob::foam {

namespace {

// ⌊a / b⌋ for b > 0.
inline int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

} // namespace

void FoamMap::setUniformVelocity(glm::vec2 u) {
    m_flow = (u == glm::vec2(0.0f)) ? Flow::Still : Flow::Uniform;
    m_uniform = u;
}

std::span<float> FoamMap::velocityX() {
    if (m_ux.empty()) m_ux.assign(m_f.size(), 0.0f), m_uz.assign(m_f.size(), 0.0f);
    m_flow = Flow::Field;
    return m_ux;
}

std::span<float> FoamMap::velocityZ() {
    velocityX();
    return m_uz;
}

glm::ivec2 FoamMap::flowNodeOrigin() const {
    const int s = flowStride();
    return glm::ivec2(floorDiv(m_originCell.x, s), floorDiv(m_originCell.y, s));
}

std::vector<glm::vec2> FoamMap::flowNodePositions() const {
    const int m = flowNodes(), s = flowStride();
    const glm::ivec2 first = flowNodeOrigin() * s;  // world cell of node (0, 0)
    std::vector<glm::vec2> out(size_t(m) * size_t(m));
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k)
            out[size_t(l) * size_t(m) + size_t(k)] = glm::vec2(first + glm::ivec2(k * s, l * s)) * m_cell;
    return out;
}

void FoamMap::setVelocityNodes(std::span<const glm::vec2> nodes) {
    assert(nodes.size() == size_t(flowNodes()) * size_t(flowNodes()));
    m_nodes.assign(nodes.begin(), nodes.end());
    m_nodesOrigin = flowNodeOrigin();
    m_nodesMax = 0.0f;
    for (const glm::vec2& u : m_nodes) m_nodesMax = std::max({m_nodesMax, std::abs(u.x), std::abs(u.y)});
    m_flow = Flow::Nodes;
}

// The grid re-aligned to the map (nodes scrolled onto start afresh), then a K-th of its node
// rows evaluated, by world row index: row L when L ≡ (update count) mod K, and every node with
// fewer than two evaluations (a new node has its slope one step after it came). A node keeps
// its last value and the slope from the one before, and the step's velocity is their linear
// extrapolation to the water's time.
void FoamMap::refreshFlow(const water::CompositeWater& water) {
    const int m = flowNodes(), s = flowStride();
    const glm::ivec2 origin = flowNodeOrigin();
    const double t = water.time();
    if (m_gridStride != s || m_grid.size() != size_t(m) * size_t(m) || t < m_gridTime || t - m_gridTime > 0.5) {
        m_grid.assign(size_t(m) * size_t(m), FlowNode{});  // new, or the time went back or jumped
        m_gridStride = s;
        m_gridOrigin = origin;
    }
    if (origin != m_gridOrigin) {  // the map scrolled onto other nodes: keep the ones it still covers
        const glm::ivec2 shift = origin - m_gridOrigin;
        std::vector<FlowNode> moved(m_grid.size());
        for (int l = 0; l < m; ++l)
            for (int k = 0; k < m; ++k) {
                const int ok = k + shift.x, ol = l + shift.y;
                if (ok >= 0 && ol >= 0 && ok < m && ol < m) moved[size_t(l) * size_t(m) + size_t(k)] = m_grid[size_t(ol) * size_t(m) + size_t(ok)];
            }
        m_grid.swap(moved);
        m_gridOrigin = origin;
    }
    m_gridTime = t;
    const int K = std::max(1, m_def.flow_refresh_steps);
    const int phase = int(m_updates++ % uint64_t(K));
    std::vector<glm::vec2> points, rest;
    std::vector<uint32_t> which;
    points.reserve(size_t(m) * size_t(m) / size_t(K) + 2 * size_t(m));
    which.reserve(points.capacity());
    const glm::ivec2 first = origin * s;  // world cell of node (0, 0)
    for (int l = 0; l < m; ++l) {
        const int L = origin.y + l;
        const bool due = ((L % K) + K) % K == phase;
        for (int k = 0; k < m; ++k) {
            const size_t c = size_t(l) * size_t(m) + size_t(k);
            if (!due && m_grid[c].evaluations >= 2) continue;
            const glm::vec2 x = glm::vec2(first + glm::ivec2(k * s, l * s)) * m_cell;
            points.push_back(x);
            which.push_back(uint32_t(c));
            // The particle above x was at rest point α then; as the water moves on, the one
            // above x comes from α − J⁻¹·u·Δt ≈ α − ū·Δt (ū: u over the interval).
            const FlowNode& node = m_grid[c];
            const float age = float(t - node.time);
            rest.push_back(node.evaluations > 0 ? node.rest - (node.u + 0.5f * age * node.rate) * age : x);
        }
    }
    std::vector<glm::vec2> u(points.size());
    if (!points.empty()) water.horizontalVelocityBatch(points, u, rest, FLOW_REST_TOLERANCE);
    for (size_t p = 0; p < which.size(); ++p) {
        FlowNode& node = m_grid[which[p]];
        if (node.evaluations > 0 && t > node.time) node.rate = (u[p] - node.u) / float(t - node.time);
        node.u = u[p];
        node.rest = rest[p];
        node.time = t;
        node.evaluations = std::min(node.evaluations + 1, 2);
    }
    m_nodes.resize(m_grid.size());
    m_nodesMax = 0.0f;
    for (size_t c = 0; c < m_grid.size(); ++c) {
        const FlowNode& node = m_grid[c];
        const glm::vec2 v = node.u + float(t - node.time) * node.rate;
        m_nodes[c] = v;
        m_nodesMax = std::max({m_nodesMax, std::abs(v.x), std::abs(v.y)});
    }
    m_nodesOrigin = origin;
    m_flow = Flow::Nodes;
}

} // namespace ob::foam
