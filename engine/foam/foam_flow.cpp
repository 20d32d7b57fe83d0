// The velocity the foam map moves with: still, uniform, per sample, or a grid of nodes fixed in
// the world and refreshed from the water a K-th of its rows a step (laws in foam_flow.h).
#include "foam/foam_flow.h"

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

FoamFlow::FoamFlow(const ScrollingGrid& grid, int flowResolution) : m_grid(grid), m_resolution(flowResolution) {}

void FoamFlow::setUniform(glm::vec2 u) {
    m_mode = (u == glm::vec2(0.0f)) ? Mode::Still : Mode::Uniform;
    m_uniform = u;
}

std::span<float> FoamFlow::velocityX() {
    const size_t cells = size_t(m_grid.n) * size_t(m_grid.n);
    if (m_ux.empty()) m_ux.assign(cells, 0.0f), m_uz.assign(cells, 0.0f);
    m_mode = Mode::Field;
    return m_ux;
}

std::span<float> FoamFlow::velocityZ() {
    velocityX();
    return m_uz;
}

glm::ivec2 FoamFlow::nodeOrigin() const {
    const int s = stride();
    return glm::ivec2(floorDivide(m_grid.originCell.x, s), floorDivide(m_grid.originCell.y, s));
}

std::vector<glm::vec2> FoamFlow::nodePositions() const {
    const int m = nodesPerSide(), s = stride();
    const glm::ivec2 first = nodeOrigin() * s;  // world sample of node (0, 0)
    std::vector<glm::vec2> out(size_t(m) * size_t(m));
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k)
            out[size_t(l) * size_t(m) + size_t(k)] = glm::vec2(first + glm::ivec2(k * s, l * s)) * m_grid.cell;
    return out;
}

void FoamFlow::setNodes(std::span<const glm::vec2> nodes) {
    assert(nodes.size() == size_t(nodesPerSide()) * size_t(nodesPerSide()));
    m_nodes.assign(nodes.begin(), nodes.end());
    m_nodesOrigin = nodeOrigin();
    m_nodesMax = 0.0f;
    for (const glm::vec2& u : m_nodes) m_nodesMax = std::max({m_nodesMax, std::abs(u.x), std::abs(u.y)});
    m_mode = Mode::Nodes;
}

void FoamFlow::follow(const ScrollingGrid& grid) {
    const glm::ivec2 scroll = grid.originCell - m_grid.originCell;
    const bool resized = grid.n != m_grid.n || grid.cell != m_grid.cell;
    m_grid = grid;
    if (!m_modes.empty() && resized) fillWindColumns();
    else if (!m_modes.empty() && scroll != glm::ivec2(0)) scrollWindTables(scroll);
    // Not scrollCells: the nodes the map scrolled onto take the nearest kept one's value (a
    // velocity, not 0), until they are set again.
    const glm::ivec2 nodeShift = nodeOrigin() - m_nodesOrigin;
    if (m_mode != Mode::Nodes || nodeShift == glm::ivec2(0)) return;
    const int m = nodesPerSide();
    std::vector<glm::vec2> moved(m_nodes.size());
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k)
            moved[size_t(l) * size_t(m) + size_t(k)] =
                m_nodes[size_t(std::clamp(l + nodeShift.y, 0, m - 1)) * size_t(m) + size_t(std::clamp(k + nodeShift.x, 0, m - 1))];
    m_nodes.swap(moved);
    m_nodesOrigin = nodeOrigin();
}

void FoamFlow::setResolution(int flowResolution) {
    const int old = stride();
    m_resolution = flowResolution;
    if (stride() != old && m_mode == Mode::Nodes) {  // the nodes no longer fit: set them again
        m_nodes.clear();
        m_mode = Mode::Still;
    }
}

// The history re-aligned to the map: anew when it is new, its stride changed or the time went
// back or jumped; else scrolled with the map, the nodes it scrolled onto starting afresh.
void FoamFlow::alignHistory(double t) {
    const int m = nodesPerSide(), s = stride();
    const glm::ivec2 origin = nodeOrigin();
    if (m_historyStride != s || m_history.size() != size_t(m) * size_t(m) || t < m_historyTime || t - m_historyTime > 0.5) {
        m_history.assign(size_t(m) * size_t(m), FlowNode{});
        m_historyStride = s;
        m_historyOrigin = origin;
    }
    scrollCells(m_history.data(), m, m, origin - m_historyOrigin, FlowNode{});
    m_historyOrigin = origin;
    m_historyTime = t;
}

// A K-th of the node rows evaluated, by world row index: row L when L ≡ (refresh count) mod K,
// and every node with fewer than two evaluations (a new node has its slope one step after it
// came). A node keeps its last value and the slope from the one before.
void FoamFlow::refresh(const water::CompositeWater& water, int refreshSteps) {
    const double t = water.time();
    alignHistory(t);
    const int m = nodesPerSide(), s = stride();
    const glm::ivec2 origin = nodeOrigin();
    const int K = std::max(1, refreshSteps);
    const int phase = int(m_refreshes++ % uint64_t(K));
    std::vector<glm::vec2> points, rest;
    std::vector<uint32_t> which;
    points.reserve(size_t(m) * size_t(m) / size_t(K) + 2 * size_t(m));
    which.reserve(points.capacity());
    const glm::ivec2 first = origin * s;  // world sample of node (0, 0)
    for (int l = 0; l < m; ++l) {
        const int L = origin.y + l;
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
    extrapolateNodes(t);
}

// The step's velocity: each node's linear extrapolation to the water's time t.
void FoamFlow::extrapolateNodes(double t) {
    m_nodes.resize(m_history.size());
    m_nodesMax = 0.0f;
    for (size_t c = 0; c < m_history.size(); ++c) {
        const FlowNode& node = m_history[c];
        const glm::vec2 v = node.u + float(t - node.time) * node.rate;
        m_nodes[c] = v;
        m_nodesMax = std::max({m_nodesMax, std::abs(v.x), std::abs(v.y)});
    }
    m_nodesOrigin = nodeOrigin();
    m_mode = Mode::Nodes;
}

glm::ivec2 FoamFlow::nodeOffset() const {
    // The nodes are kept for the map where it stands (follow moves them, m_nodesOrigin = nodeOrigin()).
    const glm::ivec2 q = m_grid.originCell - m_nodesOrigin * stride();
    assert(q.x >= 0 && q.y >= 0 && q.x < stride() && q.y < stride());
    return q;
}

void FoamFlow::nodeRow(int j, int component, float* out, float* scratch) const {
    const int m = nodesPerSide(), s = stride();
    const float inv = 1.0f / float(s);  // exact: s is a power of two
    const glm::ivec2 q = nodeOffset();
    const int p = j + q.y;
    const int l = p / s;
    const float tz = float(p % s) * inv;
    const glm::vec2* n0 = &m_nodes[size_t(l) * size_t(m)];
    const glm::vec2* n1 = n0 + m;  // l + 1 ≤ (n − 1 + q.y)/s + 1 ≤ m − 1: a node row exists
    for (int k = 0; k < m; ++k) scratch[k] = n0[k][component] * (1 - tz) + n1[k][component] * tz;
    nodeSegmentsKernel(out, scratch, m_grid.n, s, q.x, inv);
}

void FoamFlow::expandNodeRow(int l, int component, float* out, float* scratch) const {
    const int m = nodesPerSide(), s = stride();
    for (int k = 0; k < m; ++k) scratch[k] = m_nodes[size_t(l) * size_t(m) + size_t(k)][component];
    nodeSegmentsKernel(out, scratch, m_grid.n, s, nodeOffset().x, 1.0f / float(s));
}

// θ_m = K_m·p + (ω_m − K_m·drift)·t + β_m, split in the column's part K_x·x, the row's K_z·z
// (both tabulated when the map scrolls) and the time's (each step): the phases in double, reduced
// mod 2π, from world sample indices (a map far from the origin loses nothing).
namespace {
constexpr double TWO_PI_D = 2.0 * 3.141592653589793;
// splitmix64 of a fixed seed and a draw's index → [0, 1).
double streakDraw(uint64_t index) {
    uint64_t z = STREAK_SEED + index * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}
// out[i] = init + Σ_m (a[m]·ca[m][i] + b[m]·sa[m][i]) over `modes` rolls, the tables [m][n]: in
// blocks of columns whose sums stay in registers over all the rolls (one store a sample).
constexpr int STREAK_BLOCK = 32;
OB_VECTOR_KERNEL void streakSumKernel(float* __restrict out, const float* __restrict ca, const float* __restrict sa,
                                      const float* __restrict a, const float* __restrict b, int modes, int n, float init) {
    int i0 = 0;
    for (; i0 + STREAK_BLOCK <= n; i0 += STREAK_BLOCK) {
        float acc[STREAK_BLOCK];
        for (int k = 0; k < STREAK_BLOCK; ++k) acc[k] = init;
        for (int m = 0; m < modes; ++m) {
            const float am = a[m], bm = b[m];
            const float* c = ca + size_t(m) * size_t(n) + i0;
            const float* s = sa + size_t(m) * size_t(n) + i0;
            for (int k = 0; k < STREAK_BLOCK; ++k) acc[k] += am * c[k] + bm * s[k];
        }
        for (int k = 0; k < STREAK_BLOCK; ++k) out[i0 + k] = acc[k];
    }
    for (int i = i0; i < n; ++i) {
        float acc = init;
        for (int m = 0; m < modes; ++m) acc += a[m] * ca[size_t(m) * size_t(n) + i] + b[m] * sa[size_t(m) * size_t(n) + i];
        out[i] = acc;
    }
}

} // namespace

std::vector<StreakMode> foamStreakModes(const WindFlow& wind) {
    std::vector<StreakMode> modes;
    if (!wind.streaks()) return modes;
    const glm::dvec2 w = glm::normalize(glm::dvec2(wind.direction)), c(-w.y, w.x);
    for (int m = 0; m < STREAK_MODES; ++m) {
        const uint64_t d = uint64_t(m) * 4;
        const double u = (m + streakDraw(d)) / STREAK_MODES;
        const double spacing = double(wind.streakSpacing) / (1.0 - (1.0 - 1.0 / STREAK_SPACING_RANGE) * u);
        const double slant = STREAK_SLANT * (2.0 * streakDraw(d + 1) - 1.0), k = TWO_PI_D / spacing;
        StreakMode mode;
        mode.k = k * (std::cos(slant) * c + std::sin(slant) * w);
        mode.speed = double(wind.streakSpeed) * std::sqrt(2.0 / STREAK_MODES * spacing / double(wind.streakSpacing));
        // Lines moving across at ±spacing per lifetime, so the pattern renews over it.
        mode.omega = TWO_PI_D / STREAK_LIFE_S * (2.0 * streakDraw(d + 2) - 1.0);
        mode.phase = TWO_PI_D * streakDraw(d + 3);
        modes.push_back(mode);
    }
    return modes;
}

void FoamFlow::setWind(const WindFlow& wind) {
    if (wind == m_wind) return;
    m_wind = wind;
    m_modes = foamStreakModes(wind);
    fillWindColumns();
    fillWindTime();
}

void FoamFlow::setWindTime(double t) {
    m_windTime = t;
    fillWindTime();
}

void FoamFlow::fillWindTime() {
    m_timeCos.resize(m_modes.size());
    m_timeSin.resize(m_modes.size());
    for (size_t m = 0; m < m_modes.size(); ++m) {
        const StreakMode& mode = m_modes[m];
        const double a = std::fmod((mode.omega - glm::dot(mode.k, glm::dvec2(m_wind.drift))) * m_windTime, TWO_PI_D) + mode.phase;
        m_timeCos[m] = float(std::cos(a));
        m_timeSin[m] = float(std::sin(a));
    }
}

void FoamFlow::fillWindColumns() {
    const size_t n = size_t(m_grid.n), count = m_modes.size();
    m_windCos.resize(count * n), m_windSin.resize(count * n);
    m_rowCos.resize(count * n), m_rowSin.resize(count * n);
    fillWindTable(0, 0, m_grid.n);
    fillWindTable(1, 0, m_grid.n);
}

// Entries [lo, hi) of the column (axis 0: cos, sin of K_x·x) or row (axis 1: K_z·z) tables.
void FoamFlow::fillWindTable(int axis, int lo, int hi) {
    const size_t n = size_t(m_grid.n);
    float* c = axis == 0 ? m_windCos.data() : m_rowCos.data();
    float* s = axis == 0 ? m_windSin.data() : m_rowSin.data();
    const int64_t origin = axis == 0 ? m_grid.originCell.x : m_grid.originCell.y;
    for (size_t m = 0; m < m_modes.size(); ++m) {
        const double k = m_modes[m].k[axis] * double(m_grid.cell);
        for (int i = lo; i < hi; ++i) {
            const double a = std::fmod(k * double(origin + i), TWO_PI_D);
            c[m * n + size_t(i)] = float(std::cos(a));
            s[m * n + size_t(i)] = float(std::sin(a));
        }
    }
}

// The map moved by `shift` samples: the tables' entries it keeps move with it (the same bits as
// filling them anew), only the ones it scrolled onto are computed.
void FoamFlow::scrollWindTables(glm::ivec2 shift) {
    const int n = m_grid.n;
    for (int axis = 0; axis < 2; ++axis) {
        const int d = shift[axis];
        if (d == 0) continue;
        if (std::abs(d) >= n) {
            fillWindTable(axis, 0, n);
            continue;
        }
        std::vector<float>* const tables[2] = {axis == 0 ? &m_windCos : &m_rowCos, axis == 0 ? &m_windSin : &m_rowSin};
        for (std::vector<float>* t : tables)
            for (size_t m = 0; m < m_modes.size(); ++m) {
                float* row = t->data() + m * size_t(n);
                if (d > 0) std::copy(row + d, row + n, row);  // new i = old i + d
                else std::copy_backward(row, row + n + d, row + n);
            }
        if (d > 0) fillWindTable(axis, n - d, n);
        else fillWindTable(axis, 0, -d);
    }
}

float FoamFlow::windMax() const {
    const glm::vec2 w = m_wind.direction, c(-w.y, w.x);
    double v = 0.0;
    for (const StreakMode& mode : m_modes) v += mode.speed;
    return std::max(std::abs(m_wind.drift.x) + float(v) * (std::abs(w.x) + std::abs(c.x)),
                    std::abs(m_wind.drift.y) + float(v) * (std::abs(w.y) + std::abs(c.y)));
}

// u_w = drift + Σ_m V_m·(cos θ_m·ŵ − sin θ_m·ĉ), θ_m = a_i + b_j: with cos θ = ca·cb − sa·sb and
// sin θ = sa·cb + ca·sb, each roll adds A·ca_i + B·sa_i, A = V·(ŵ·cb − ĉ·sb), B = −V·(ŵ·sb + ĉ·cb).
void FoamFlow::windRow(int j, int component, float* out) const {
    const int n = m_grid.n, count = int(m_modes.size());
    const float d = m_wind.drift[component];
    if (count == 0) return std::fill(out, out + n, d);
    const glm::vec2 w = m_wind.direction, c(-w.y, w.x);
    float A[STREAK_MODES], B[STREAK_MODES];
    for (int m = 0; m < count; ++m) {
        float cb, sb;
        rowPhase(size_t(m), j, cb, sb);
        const float v = float(m_modes[size_t(m)].speed);
        A[m] = v * (w[component] * cb - c[component] * sb), B[m] = -v * (w[component] * sb + c[component] * cb);
    }
    streakSumKernel(out, m_windCos.data(), m_windSin.data(), A, B, count, n, d);
}

// ∇·u_w = −Σ_m V_m·((K_m·ĉ)·cos θ_m + (K_m·ŵ)·sin θ_m); with P = dt·V·K·ĉ, Q = dt·V·K·ŵ,
// −dt·∇·u_w adds ca·(P·cb + Q·sb) + sa·(Q·cb − P·sb) a roll.
void FoamFlow::windGatherRow(int j, float dt, float* out) const {
    const int n = m_grid.n, count = int(m_modes.size());
    if (count == 0) return std::fill(out, out + n, 1.0f);
    const glm::dvec2 w(m_wind.direction), c(-w.y, w.x);
    float X[STREAK_MODES], Y[STREAK_MODES];
    for (int m = 0; m < count; ++m) {
        const StreakMode& mode = m_modes[size_t(m)];
        const double g = double(dt) * mode.speed;
        const double P = g * glm::dot(mode.k, c), Q = g * glm::dot(mode.k, w);
        float cb, sb;
        rowPhase(size_t(m), j, cb, sb);
        X[m] = float(P) * cb + float(Q) * sb, Y[m] = float(Q) * cb - float(P) * sb;
    }
    streakSumKernel(out, m_windCos.data(), m_windSin.data(), X, Y, count, n, 1.0f);
}

float FoamFlow::nodeRowWeight(int j, int& l) const {
    const int s = stride();
    const int p = j + nodeOffset().y;
    l = p / s;
    return float(p % s) * (1.0f / float(s));
}

} // namespace ob::foam
