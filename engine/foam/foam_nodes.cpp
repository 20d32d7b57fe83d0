// The foam's velocity on a grid of nodes fixed in the world, refreshed from the water a K-th of
// its rows a step (laws in foam_nodes.h).
#include "foam/foam_nodes.h"

#include "core/simd.h"
#include "water/composite_water.h"

#include <cassert>
#include <cmath>

namespace ob::foam {

namespace {

// ⌊a / b⌋ for b > 0.
inline int floorDivide(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// A row of n samples linear between node values v[k] and v[k + 1], the row's sample 0 at offset
// q0 (< s) past node 0: sample i at offset p = q0 + i from it, in segment p / s at weight (p mod s)/s.
OB_VECTOR_KERNEL void nodeSegmentsKernel(float* __restrict out, const float* __restrict v, int n, int s, int q0, float inv) {
    int i = 0, k = 0;
    if (q0 > 0) {  // the partial first segment
        for (int q = q0; q < s && i < n; ++q, ++i) out[i] = v[0] * (1 - float(q) * inv) + v[1] * (float(q) * inv);
        k = 1;
    }
    for (; i + s <= n; ++k, i += s) {  // whole segments
        const float v0 = v[k], v1 = v[k + 1];
        float* d = out + i;
        for (int q = 0; q < s; ++q) {
            const float tx = float(q) * inv;
            d[q] = v0 * (1 - tx) + v1 * tx;
        }
    }
    for (int q = 0; i < n; ++q, ++i) out[i] = v[k] * (1 - float(q) * inv) + v[k + 1] * (float(q) * inv);  // the partial last
}

} // namespace

glm::ivec2 FoamNodes::origin() const {
    const int s = stride();
    return glm::ivec2(floorDivide(m_grid.originCell.x, s), floorDivide(m_grid.originCell.y, s));
}

std::vector<glm::vec2> FoamNodes::positions() const {
    const int m = perSide(), s = stride();
    const glm::ivec2 first = origin() * s;  // world sample of node (0, 0)
    std::vector<glm::vec2> out(size_t(m) * size_t(m));
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k)
            out[size_t(l) * size_t(m) + size_t(k)] = glm::vec2(first + glm::ivec2(k * s, l * s)) * m_grid.cell;
    return out;
}

void FoamNodes::set(std::span<const glm::vec2> nodes) {
    assert(nodes.size() == size_t(perSide()) * size_t(perSide()));
    m_nodes.assign(nodes.begin(), nodes.end());
    m_origin = origin();
    m_max = 0.0f;
    for (const glm::vec2& u : m_nodes) m_max = std::max({m_max, std::abs(u.x), std::abs(u.y)});
}

void FoamNodes::follow(const ScrollingGrid& grid, bool shift) {
    m_grid = grid;
    // Not scrollCells: the nodes the map scrolled onto take the nearest kept one's value (a
    // velocity, not 0), until they are set again.
    const glm::ivec2 nodeShift = origin() - m_origin;
    if (!shift || nodeShift == glm::ivec2(0)) return;
    const int m = perSide();
    std::vector<glm::vec2> moved(m_nodes.size());
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k)
            moved[size_t(l) * size_t(m) + size_t(k)] =
                m_nodes[size_t(std::clamp(l + nodeShift.y, 0, m - 1)) * size_t(m) + size_t(std::clamp(k + nodeShift.x, 0, m - 1))];
    m_nodes.swap(moved);
    m_origin = origin();
}

bool FoamNodes::setResolution(int flowResolution) {
    const int old = stride();
    m_resolution = flowResolution;
    return stride() != old;
}

// The history re-aligned to the map: anew when it is new, its stride changed or the time went
// back or jumped; else scrolled with the map, the nodes it scrolled onto starting afresh.
void FoamNodes::alignHistory(double t) {
    const int m = perSide(), s = stride();
    const glm::ivec2 here = origin();
    if (m_historyStride != s || m_history.size() != size_t(m) * size_t(m) || t < m_historyTime || t - m_historyTime > 0.5) {
        m_history.assign(size_t(m) * size_t(m), FlowNode{});
        m_historyStride = s;
        m_historyOrigin = here;
    }
    scrollCells(m_history.data(), m, m, here - m_historyOrigin, FlowNode{});
    m_historyOrigin = here;
    m_historyTime = t;
}

// A K-th of the node rows evaluated, by world row index: row L when L ≡ (refresh count) mod K,
// and every node with fewer than two evaluations (a new node has its slope one step after it
// came). A node keeps its last value and the slope from the one before.
void FoamNodes::refresh(const water::CompositeWater& water, int refreshSteps) {
    const double t = water.time();
    alignHistory(t);
    const int m = perSide(), s = stride();
    const glm::ivec2 here = origin();
    const int K = std::max(1, refreshSteps);
    const int phase = int(m_refreshes++ % uint64_t(K));
    std::vector<glm::vec2> points, rest;
    std::vector<uint32_t> which;
    points.reserve(size_t(m) * size_t(m) / size_t(K) + 2 * size_t(m));
    which.reserve(points.capacity());
    const glm::ivec2 first = here * s;  // world sample of node (0, 0)
    for (int l = 0; l < m; ++l) {
        const int L = here.y + l;
        const bool due = ((L % K) + K) % K == phase;
        for (int k = 0; k < m; ++k) {
            const size_t c = size_t(l) * size_t(m) + size_t(k);
            if (!due && m_history[c].evaluations >= 2) continue;
            const glm::vec2 x = glm::vec2(first + glm::ivec2(k * s, l * s)) * m_grid.cell;
            points.push_back(x);
            which.push_back(uint32_t(c));
            // The particle above x was at rest point α then; as the water moves on, the one
            // above x comes from α − J⁻¹·u·Δt ≈ α − ū·Δt (ū: u over the interval).
            const FlowNode& node = m_history[c];
            const float age = float(t - node.time);
            rest.push_back(node.evaluations > 0 ? node.rest - (node.u + 0.5f * age * node.rate) * age : x);
        }
    }
    std::vector<glm::vec2> u(points.size());
    if (!points.empty()) water.horizontalVelocityBatch(points, u, rest, FLOW_REST_TOLERANCE);
    for (size_t p = 0; p < which.size(); ++p) {
        FlowNode& node = m_history[which[p]];
        if (node.evaluations > 0 && t > node.time) node.rate = (u[p] - node.u) / float(t - node.time);
        node.u = u[p];
        node.rest = rest[p];
        node.time = t;
        node.evaluations = std::min(node.evaluations + 1, 2);
    }
    extrapolate(t);
}

// The step's velocity: each node's linear extrapolation to the water's time t.
void FoamNodes::extrapolate(double t) {
    m_nodes.resize(m_history.size());
    m_max = 0.0f;
    for (size_t c = 0; c < m_history.size(); ++c) {
        const FlowNode& node = m_history[c];
        const glm::vec2 v = node.u + float(t - node.time) * node.rate;
        m_nodes[c] = v;
        m_max = std::max({m_max, std::abs(v.x), std::abs(v.y)});
    }
    m_origin = origin();
}

glm::ivec2 FoamNodes::offset() const {
    // The nodes are kept for the map where it stands (follow moves them, m_origin = origin()).
    const glm::ivec2 q = m_grid.originCell - m_origin * stride();
    assert(q.x >= 0 && q.y >= 0 && q.x < stride() && q.y < stride());
    return q;
}

void FoamNodes::row(int j, int component, float* out, float* scratch) const {
    const int m = perSide(), s = stride();
    const float inv = 1.0f / float(s);  // exact: s is a power of two
    const glm::ivec2 q = offset();
    const int p = j + q.y;
    const int l = p / s;
    const float tz = float(p % s) * inv;
    const glm::vec2* n0 = &m_nodes[size_t(l) * size_t(m)];
    const glm::vec2* n1 = n0 + m;  // l + 1 ≤ (n − 1 + q.y)/s + 1 ≤ m − 1: a node row exists
    for (int k = 0; k < m; ++k) scratch[k] = n0[k][component] * (1 - tz) + n1[k][component] * tz;
    nodeSegmentsKernel(out, scratch, m_grid.n, s, q.x, inv);
}

void FoamNodes::expandRow(int l, int component, float* out, float* scratch) const {
    const int m = perSide(), s = stride();
    for (int k = 0; k < m; ++k) scratch[k] = m_nodes[size_t(l) * size_t(m) + size_t(k)][component];
    nodeSegmentsKernel(out, scratch, m_grid.n, s, offset().x, 1.0f / float(s));
}

float FoamNodes::rowWeight(int j, int& l) const {
    const int s = stride();
    const int p = j + offset().y;
    l = p / s;
    return float(p % s) * (1.0f / float(s));
}

} // namespace ob::foam
