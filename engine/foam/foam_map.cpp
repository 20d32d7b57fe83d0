// Persistent foam map: semi-Lagrangian advection, exact decay, the whitecap, ripple and drop
// sources (laws in the header; a hull's foam in foam_wake.cpp, the velocity in foam_flow.cpp).
#include "foam/foam_map.h"

#include "core/hash.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "core/thread_choice.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"
#include "water/composite_water.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <numbers>

namespace ob::foam {

namespace {

// Rows per parallelFor chunk: 512² is 32 chunks of 16 rows, ~8 µs each.
constexpr int ROW_CHUNK = 16;
// Maps from this side on have the sweep's threads measured (smaller ones split as they come).
constexpr int PARALLEL_MIN_RESOLUTION = 256;

// A step's coverage below COVERAGE_FLOOR ends as 0: nothing to see (an 8-bit texture's step is
// 4e-3), and the tails that resampling spreads would otherwise sink into subnormal floats,
// which cost the FPU ~100× a normal operation.
constexpr float COVERAGE_FLOOR = 1e-12f;
inline float floored(float v) { return v > COVERAGE_FLOOR ? v : 0.0f; }

// Coverage of a row-major n×n map at cell (i, j), 0 outside.
inline float cellOr0(const float* f, int n, int i, int j) {
    return (i < 0 || j < 0 || i >= n || j >= n) ? 0.0f : f[size_t(j) * size_t(n) + size_t(i)];
}

// One row of the uniform-flow step: dst[i] = w00·s0[i+ix] + w10·s0[i+ix+1] + w01·s1[i+ix] +
// w11·s1[i+ix+1] for i in [lo, hi), where every index is inside its row.
OB_VECTOR_KERNEL void uniformRowKernel(float* __restrict dst, const float* __restrict s0, const float* __restrict s1,
                                       int lo, int hi, int ix, float w00, float w10, float w01, float w11) {
    for (int i = lo; i < hi; ++i)
        dst[i] = floored(w00 * s0[i + ix] + w10 * s0[i + ix + 1] + w01 * s1[i + ix] + w11 * s1[i + ix + 1]);
}

// Linear interpolation of a row of n values (0 outside) at g (in cells; centres at integers).
inline float lerpRow(const float* row, int n, float g) {
    g = std::clamp(g, -1.0f, float(n));  // beyond: both samples are 0 anyway
    const float g0 = std::floor(g);
    const int x0 = int(g0);
    const float t = g - g0;
    return (1 - t) * cellOr0(row, n, x0, 0) + t * cellOr0(row, n, x0 + 1, 0);
}

// One cell of a pass along an axis: the water moves c cells along it this step; for |c| ≤ 1
// the departure point lies between the cell and its upstream neighbour (before: the one at
// −1 when c > 0, after: at +1 when c < 0): mid + |c|·(upstream − mid).
inline float passCell(float mid, float before, float after, float c) {
    const float upstream = c > 0.0f ? before : after;
    return mid + std::abs(c) * (upstream - mid);
}

// Per-cell flow, pass 1, the cells [lo, hi) of a row (neighbours inside it), c = ux·back.
// Returns nonzero when some |c| > 1 (the row is then redone by lerpRow).
OB_VECTOR_KERNEL int xPassKernel(float* __restrict dst, const float* __restrict src, const float* __restrict ux, int lo,
                                 int hi, float back) {
    int over = 0;
    for (int i = lo; i < hi; ++i) {
        const float c = ux[i] * back;
        over |= int(c > 1.0f) | int(c < -1.0f);
        dst[i] = passCell(src[i], src[i - 1], src[i + 1], c);
    }
    return over;
}

// Pass 2, one row along z from the rows above (j − 1), at and below (j + 1) it, times the decay a.
OB_VECTOR_KERNEL int zPassKernel(float* __restrict dst, const float* __restrict up, const float* __restrict mid,
                                 const float* __restrict down, const float* __restrict uz, int n, float back, float a) {
    int over = 0;
    for (int i = 0; i < n; ++i) {
        const float c = uz[i] * back;
        over |= int(c > 1.0f) | int(c < -1.0f);
        dst[i] = floored(a * passCell(mid[i], up[i], down[i], c));
    }
    return over;
}

// The sweep's passes (FoamMap::sweep; every |c| ≤ 1), the velocity the lerp of two node rows
// expanded along x (e0, e1) at weight t: pass 1 over the cells [lo, hi) of a row...
OB_VECTOR_KERNEL void xSweepKernel(float* __restrict dst, const float* __restrict src, const float* __restrict e0,
                                   const float* __restrict e1, float t, int lo, int hi, float back) {
    for (int i = lo; i < hi; ++i) {
        const float u = e0[i] * (1 - t) + e1[i] * t;
        dst[i] = passCell(src[i], src[i - 1], src[i + 1], u * back);
    }
}
// ...and pass 2 over a row, times the decay a.
OB_VECTOR_KERNEL void zSweepKernel(float* __restrict dst, const float* __restrict up, const float* __restrict mid,
                                   const float* __restrict down, const float* __restrict e0, const float* __restrict e1,
                                   float t, int n, float back, float a) {
    for (int i = 0; i < n; ++i) {
        const float u = e0[i] * (1 - t) + e1[i] * t;
        dst[i] = floored(a * passCell(mid[i], up[i], down[i], u * back));
    }
}

OB_VECTOR_KERNEL void scaleKernel(float* __restrict dst, const float* __restrict src, size_t count, float a) {
    for (size_t i = 0; i < count; ++i) dst[i] = floored(a * src[i]);
}

} // namespace

FoamMap::FoamMap(const FoamDef& def, float extent, glm::vec2 centre)
    : m_def(def), m_n(def.resolution), m_cell(extent / float(def.resolution)),
      m_f(size_t(def.resolution) * size_t(def.resolution), 0.0f), m_next(m_f.size(), 0.0f) {
    m_originCell = glm::ivec2(int(std::lround(centre.x / m_cell)), int(std::lround(centre.y / m_cell))) - glm::ivec2(m_n / 2);
    if (m_n >= PARALLEL_MIN_RESOLUTION) chooseThreads();
}

// One thread or all for the sweep, measured on this map while it is still 0 and still (a sweep
// of zeros costs what any sweep costs and leaves zeros), kept per size.
void FoamMap::chooseThreads() {
    setVelocityNodes(std::vector<glm::vec2>(size_t(flowNodes()) * size_t(flowNodes()), glm::vec2(0.0f)));
    const std::string size = std::to_string(m_n) + "x" + std::to_string(m_n);
    m_sweepThreads = measuredThreads("foam sweep " + size, workerCount(), [&](int n) {
        m_sweepThreads = n;
        sweep(nullptr, 1.0f / 60.0f);
    });
    m_nodes.clear();
    m_flow = Flow::Still;
}

void FoamMap::setDef(const FoamDef& def) {
    const int n = m_n, stride = flowStride();
    m_def = def;
    m_def.resolution = n;
    if (flowStride() != stride && m_flow == Flow::Nodes) {  // the nodes no longer fit: set them again
        m_nodes.clear();
        m_flow = Flow::Still;
    }
}

glm::vec2 FoamMap::origin() const { return glm::vec2(m_originCell) * m_cell; }

glm::vec2 FoamMap::toGrid(glm::vec2 world) const { return world / m_cell - glm::vec2(m_originCell); }

void FoamMap::centerOn(glm::vec2 worldCentre) {
    const glm::ivec2 target =
        glm::ivec2(int(std::lround(worldCentre.x / m_cell)), int(std::lround(worldCentre.y / m_cell))) - glm::ivec2(m_n / 2);
    const glm::ivec2 shift = target - m_originCell;
    if (shift == glm::ivec2(0)) return;
    // New cell (i, j) is old cell (i + dx, j + dz); the per-cell velocity is the caller's to refill.
    for (int j = 0; j < m_n; ++j)
        for (int i = 0; i < m_n; ++i) m_next[size_t(j) * size_t(m_n) + size_t(i)] = cellOr0(m_f.data(), m_n, i + shift.x, j + shift.y);
    m_f.swap(m_next);
    m_originCell = target;
    // Nodes set by setVelocityNodes keep their place in the world: shifted by whole nodes, the
    // ones the map scrolled onto copied from the nearest kept one (set them again to refresh).
    const glm::ivec2 nodeShift = flowNodeOrigin() - m_nodesOrigin;
    if (m_flow == Flow::Nodes && nodeShift != glm::ivec2(0)) {
        const int m = flowNodes();
        std::vector<glm::vec2> moved(m_nodes.size());
        for (int l = 0; l < m; ++l)
            for (int k = 0; k < m; ++k)
                moved[size_t(l) * size_t(m) + size_t(k)] =
                    m_nodes[size_t(std::clamp(l + nodeShift.y, 0, m - 1)) * size_t(m) + size_t(std::clamp(k + nodeShift.x, 0, m - 1))];
        m_nodes.swap(moved);
        m_nodesOrigin = flowNodeOrigin();
    }
}

float FoamMap::sample(float x, float z) const {
    const glm::vec2 g = toGrid(glm::vec2(x, z));
    const float fx = std::floor(g.x), fz = std::floor(g.y);
    const int i = int(fx), j = int(fz);
    if (i < -1 || j < -1 || i >= m_n || j >= m_n) return 0.0f;
    const float tx = g.x - fx, tz = g.y - fz;
    const float* f = m_f.data();
    return (cellOr0(f, m_n, i, j) * (1 - tx) + cellOr0(f, m_n, i + 1, j) * tx) * (1 - tz) +
           (cellOr0(f, m_n, i, j + 1) * (1 - tx) + cellOr0(f, m_n, i + 1, j + 1) * tx) * tz;
}

double FoamMap::mean() const {
    double sum = 0.0;
    for (float v : m_f) sum += v;
    return sum / double(m_f.size());
}

// A row of n cells linear between node values v[k] and v[k + 1], the row's cell 0 at offset q0
// (< s) past node 0: cell i at offset p = q0 + i from it, in segment p / s at weight (p mod s)/s.
OB_VECTOR_KERNEL static void nodeSegmentsKernel(float* __restrict out, const float* __restrict v, int n, int s, int q0,
                                                float inv) {
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

// Row j's velocity component (0: x, 1: z) from the nodes: the two node rows around it lerped
// along z into scratch (flowNodes() floats), then along x between each pair of nodes.
void FoamMap::nodeRow(int j, int component, float* out, float* scratch) const {
    const int m = flowNodes(), s = flowStride();
    const float inv = 1.0f / float(s);  // exact: s is a power of two
    // The map's cell (0, 0) sits q = (qx, qz) cells past node (0, 0), 0 ≤ q < s (the nodes are
    // kept for the map where it stands: centerOn moves them, m_nodesOrigin = flowNodeOrigin()).
    const glm::ivec2 q = m_originCell - m_nodesOrigin * s;
    assert(q.x >= 0 && q.y >= 0 && q.x < s && q.y < s);
    const int p = j + q.y;
    const int l = p / s;
    const float tz = float(p % s) * inv;
    const glm::vec2* n0 = &m_nodes[size_t(l) * size_t(m)];
    const glm::vec2* n1 = n0 + m;  // l + 1 ≤ (N − 1 + q.y)/s + 1 ≤ m − 1: a node row exists
    for (int k = 0; k < m; ++k) scratch[k] = n0[k][component] * (1 - tz) + n1[k][component] * tz;
    nodeSegmentsKernel(out, scratch, m_n, s, q.x, inv);
}

void FoamMap::add(int i, int j, float amount) {
    float& f = m_f[size_t(j) * size_t(m_n) + size_t(i)];
    f = std::min(1.0f, f + amount);
}

// Where a coordinate g (in samples of a periodic map of n) falls: the two samples around it
// and the weight of the second.
struct Wrapped {
    int i0, i1;
    float t;
};
static Wrapped wrap(float g, int n) {
    const float f = std::floor(g);
    long long i = (long long)(f) % n;
    if (i < 0) i += n;
    return Wrapped{int(i), int(i) + 1 == n ? 0 : int(i) + 1, g - f};
}

// One foam row of a source: f[i] = min(1, f[i] + max(0, s[i] − threshold)·rate), i in [0, n).
OB_VECTOR_KERNEL static void addExcessKernel(float* __restrict f, const float* __restrict s, int n, float threshold,
                                             float rate) {
    for (int i = 0; i < n; ++i) {
        float excess = s[i] - threshold;
        excess = excess > 0.0f ? excess : 0.0f;
        const float v = f[i] + excess * rate;
        f[i] = v < 1.0f ? v : 1.0f;
    }
}

// One foam row of the whitecap source from the two tile rows around it, each already read at
// every column (u0, u1): J = u0·(1 − t) + u1·t, out = min(1, in + max(0, j0 − J)·rate).
inline float whitecapCell(float in, float u0, float u1, float t, float j0, float rate) {
    const float j = u0 * (1 - t) + u1 * t;
    float excess = j0 - j;
    excess = excess > 0.0f ? excess : 0.0f;
    const float v = in + excess * rate;
    return v < 1.0f ? v : 1.0f;
}
OB_VECTOR_KERNEL static void whitecapRowKernel(float* __restrict out, const float* __restrict in, const float* __restrict u0,
                                               const float* __restrict u1, float t, int n, float j0, float rate) {
    for (int i = 0; i < n; ++i) out[i] = whitecapCell(in[i], u0[i], u1[i], t, j0, rate);
}
OB_VECTOR_KERNEL static void whitecapRowInPlaceKernel(float* __restrict f, const float* __restrict u0,
                                                      const float* __restrict u1, float t, int n, float j0, float rate) {
    for (int i = 0; i < n; ++i) f[i] = whitecapCell(f[i], u0[i], u1[i], t, j0, rate);
}

// A tile row read at every foam column: out[i] = w[c0[i]]·(1 − t[i]) + w[c0[i] + 1]·t[i].
OB_VECTOR_KERNEL static void upsampleRowKernel(float* __restrict out, const float* __restrict w, const int* __restrict c0,
                                               const float* __restrict t, int n) {
    for (int i = 0; i < n; ++i) out[i] = w[c0[i]] * (1 - t[i]) + w[c0[i] + 1] * t[i];
}

// |∇h|² by central differences at the interior cells [1, cols − 1) of the ripple row `mid`
// (its neighbours one row up and down at ∓cols), per metre via inv2d = 1/(2Δ). Returns nonzero
// when some |∇h|² exceeds steep (the row then needs its square roots, slopeRoots).
OB_VECTOR_KERNEL static int slopeSquaredRow(float* __restrict out, const float* __restrict mid, int cols, float inv2d,
                                            float steep) {
    const float* up = mid - cols;
    const float* down = mid + cols;
    int any = 0;
    for (int x = 1; x < cols - 1; ++x) {
        const float sx = (mid[x + 1] - mid[x - 1]) * inv2d, sz = (down[x] - up[x]) * inv2d;
        const float g2 = sx * sx + sz * sz;
        any |= int(g2 > steep);
        out[x] = g2;
    }
    return any;
}

OB_VECTOR_KERNEL static void slopeRoots(float* __restrict v, int cols) {
    for (int x = 1; x < cols - 1; ++x) v[x] = std::sqrt(v[x]);
}

// The tables of sources (a) and (b) for one call: where each foam column and row falls in the
// Jacobian tile and the ripple patch. Rows are formed from them by RowCache::add.
struct FoamMap::Sources {
    // (a) whitecaps: foam column i lies between samples c0[i] and c0[i] + 1 of a window of the
    // tile's columns (window[k]: the tile column of its sample k, periodic), at weight ct[i].
    const float* jacobian = nullptr;  // null: no whitecaps
    int n = 0;
    float toTile = 0.0f;              // tile samples per metre
    std::vector<int> window, c0;
    std::vector<float> ct;
    // The least J of each tile row over the window (+∞ for rows the map does not reach): a foam
    // row between two tile rows whose least J is J_0 or more gains nothing (J is bilinear).
    std::vector<float> rowMin;
    float j0 = 0.0f, whitecapRate = 0.0f;
    // (b) steep ripples: the nearest ripple cell of foam column i and row j (rx, rz), for the
    // columns [iLo, iHi) and rows [jLo, jHi) that have an interior one (a central difference).
    const float* height = nullptr;    // null: no ripples
    int cols = 0;
    float inv2d = 0.0f;
    std::vector<int> rx, rz;
    int iLo = 0, iHi = 0, jLo = 0, jHi = 0;
    bool contiguous = false;          // rx[i] = rx[iLo] + i − iLo (the ripple and foam cells match)
    float slope0 = 0.0f, rippleRate = 0.0f;
    float originZ = 0.0f, cell = 0.0f;  // the map's cell (0, 0) world z, Δ (tile rows)
};

// A worker's rows of the sources: the tile rows read at every column (the last two, reused by
// the foam rows between them) and the ripple row's slopes.
struct FoamMap::RowCache {
    int tileRow[2] = {-1, -1};
    std::vector<float> upsampled[2], windowRow;
    int slopeRow = -1;   // the ripple row rippleSlope holds
    bool steep = false;  // some |∇h| in it above the threshold (else it adds nothing)
    std::vector<float> rippleSlope, gathered;

    // Tile row r read at every foam column (one of the two buffers, not `keep`).
    const float* tile(const Sources& s, int r, int keep, int n, int& slot) {
        for (int b = 0; b < 2; ++b)
            if (tileRow[b] == r) return slot = b, upsampled[b].data();
        slot = keep == 0 ? 1 : 0;
        upsampled[slot].resize(size_t(n));
        windowRow.resize(s.window.size());
        const float* row = s.jacobian + size_t(r) * size_t(s.n);
        for (size_t k = 0; k < s.window.size(); ++k) windowRow[k] = row[s.window[k]];
        upsampleRowKernel(upsampled[slot].data(), windowRow.data(), s.c0.data(), s.ct.data(), n);
        tileRow[slot] = r;
        return upsampled[slot].data();
    }

    // Whether ripple row z has a cell steeper than the threshold; its |∇h| in rippleSlope (and
    // gathered at the foam's columns) if so. Once per ripple row.
    bool steepRow(const Sources& s, int z, int n) {
        if (z == slopeRow) return steep;
        rippleSlope.resize(size_t(s.cols));
        slopeRow = z;
        steep = slopeSquaredRow(rippleSlope.data(), s.height + size_t(z) * size_t(s.cols), s.cols, s.inv2d,
                                s.slope0 * s.slope0) != 0;
        if (!steep) return false;
        slopeRoots(rippleSlope.data(), s.cols);
        if (!s.contiguous) {
            gathered.resize(size_t(n));
            for (int i = s.iLo; i < s.iHi; ++i) gathered[size_t(i)] = rippleSlope[size_t(s.rx[size_t(i)])];
        }
        return true;
    }

    // Foam row j with the sources' S·dt added (a clamp at 1 after each): out[i] from in[i], n
    // cells (in == out: in place). Returns false (out untouched) when no source reaches the row.
    bool add(const Sources& s, int j, const float* in, float* out, int n) {
        const bool ripples = s.height && j >= s.jLo && j < s.jHi && steepRow(s, s.rz[size_t(j)], n);
        if (!s.jacobian && !ripples) return false;
        const Wrapped r = s.jacobian ? wrap((s.originZ + float(j) * s.cell) * s.toTile, s.n) : Wrapped{0, 0, 0.0f};
        const bool whitecaps = s.jacobian && std::min(s.rowMin[size_t(r.i0)], s.rowMin[size_t(r.i1)]) < s.j0;
        if (!whitecaps && !ripples) return false;
        if (whitecaps) {
            int slot0 = -1, slot1;
            const float* u0 = tile(s, r.i0, -1, n, slot0);
            const float* u1 = tile(s, r.i1, slot0, n, slot1);
            if (in == out) whitecapRowInPlaceKernel(out, u0, u1, r.t, n, s.j0, s.whitecapRate);
            else whitecapRowKernel(out, in, u0, u1, r.t, n, s.j0, s.whitecapRate);
        } else if (in != out) {
            std::memcpy(out, in, size_t(n) * sizeof(float));
        }
        float* f = out;
        if (ripples) {
            const float* slope =
                s.contiguous ? rippleSlope.data() + s.rx[size_t(s.iLo)] : gathered.data() + s.iLo;  // at column iLo
            addExcessKernel(f + s.iLo, slope, s.iHi - s.iLo, s.slope0, s.rippleRate);
        }
        return true;
    }
};

FoamMap::Sources FoamMap::sources(const FoamInputs& in, float dt) const {
    Sources s;
    const glm::vec2 o = origin();
    s.originZ = o.y;
    s.cell = m_cell;
    const int n = in.jacobianN;
    if (m_def.whitecap_weight > 0.0f && n > 0 && !in.jacobian.empty()) {
        assert(in.jacobian.size() >= size_t(n) * size_t(n));
        s.jacobian = in.jacobian.data();
        s.n = n;
        s.toTile = float(n) / in.jacobianTile;
        s.j0 = m_def.whitecap_jacobian;
        s.whitecapRate = m_def.whitecap_weight * dt;
        // Bilinear in the periodic tile at each cell centre (rest-point coordinates). The
        // columns' samples once: the window starts at the sample at or before column 0.
        s.c0.resize(size_t(m_n));
        s.ct.resize(size_t(m_n));
        long long k0 = 0;
        for (int i = 0; i < m_n; ++i) {
            const float g = (o.x + float(i) * m_cell) * s.toTile;
            const float f = std::floor(g);
            if (i == 0) k0 = (long long)(f);
            s.c0[size_t(i)] = int((long long)(f) - k0);
            s.ct[size_t(i)] = g - f;
        }
        s.window.resize(size_t(s.c0.back()) + 2);
        for (size_t k = 0; k < s.window.size(); ++k) {
            long long c = (k0 + (long long)(k)) % n;
            s.window[k] = int(c < 0 ? c + n : c);
        }
        // The tile rows the foam rows fall between: from the one at or before row 0 to the one
        // after row N − 1 (all n when the map spans the tile).
        const float z0 = std::floor(o.y * s.toTile), z1 = std::floor((o.y + float(m_n - 1) * m_cell) * s.toTile) + 1.0f;
        const long long rowsReached = std::min((long long)(z1 - z0) + 1, (long long)(n));
        s.rowMin.assign(size_t(n), std::numeric_limits<float>::infinity());
        for (long long k = 0; k < rowsReached; ++k) {
            long long r = ((long long)(z0) + k) % n;
            if (r < 0) r += n;
            const float* row = in.jacobian.data() + size_t(r) * size_t(n);
            float least = std::numeric_limits<float>::infinity();
            for (int c : s.window) least = std::min(least, row[c]);
            s.rowMin[size_t(r)] = least;
        }
    }
    const interaction::RipplePatch* patch = in.ripples;
    if (m_def.ripple_weight > 0.0f && patch) {
        const int rows = patch->rows(), cols = patch->cols();
        // The nearest ripple cell of each foam column and row; only interior ripple cells have a
        // central difference, and they form one range of columns and one of rows.
        s.rx.resize(size_t(m_n));
        s.iLo = m_n, s.iHi = 0;
        for (int i = 0; i < m_n; ++i) {
            const long x = std::lround(patch->toGrid(glm::vec2(o.x + float(i) * m_cell, o.y)).x);
            s.rx[size_t(i)] = int(x);
            if (x >= 1 && x <= cols - 2) s.iLo = std::min(s.iLo, i), s.iHi = std::max(s.iHi, i + 1);
        }
        s.rz.resize(size_t(m_n));
        s.jLo = m_n, s.jHi = 0;
        for (int j = 0; j < m_n; ++j) {
            const long z = std::lround(patch->toGrid(glm::vec2(o.x, o.y + float(j) * m_cell)).y);
            s.rz[size_t(j)] = int(z);
            if (z >= 1 && z <= rows - 2) s.jLo = std::min(s.jLo, j), s.jHi = std::max(s.jHi, j + 1);
        }
        if (s.iLo < s.iHi && s.jLo < s.jHi) {
            s.height = patch->height().data();  // either model's
            s.cols = cols;
            s.inv2d = 1.0f / (2.0f * patch->def().cell_size);
            s.slope0 = m_def.ripple_slope;
            s.rippleRate = m_def.ripple_weight * dt;
            s.contiguous = true;
            for (int i = s.iLo; i < s.iHi; ++i) s.contiguous = s.contiguous && s.rx[size_t(i)] == s.rx[size_t(s.iLo)] + (i - s.iLo);
        }
    }
    return s;
}

void FoamMap::addSources(const Sources& s) {
    if (!s.jacobian && !s.height) return;
    const int lo = s.jacobian ? 0 : s.jLo, hi = s.jacobian ? m_n : s.jHi;
    parallelFor(lo, hi, ROW_CHUNK, [&](int rowLo, int rowHi) {
        RowCache cache;
        for (int j = rowLo; j < rowHi; ++j) {
            float* f = &m_f[size_t(j) * size_t(m_n)];
            cache.add(s, j, f, f, m_n);
        }
    });
}

void FoamMap::addWhitecaps(std::span<const float> jacobian, int n, float tile, float dt) {
    FoamInputs in;
    in.jacobian = jacobian;
    in.jacobianN = n;
    in.jacobianTile = tile;
    addSources(sources(in, dt));
}

void FoamMap::addRipples(const interaction::RipplePatch& patch, float dt) {
    FoamInputs in;
    in.ripples = &patch;
    addSources(sources(in, dt));
}

void FoamMap::addLandings(std::span<const splash::Landing> landings) {
    if (m_def.splash_weight <= 0.0f) return;
    const float perArea = m_def.splash_weight * std::numbers::pi_v<float> * DROP_FOAM_RADIUS_FACTOR * DROP_FOAM_RADIUS_FACTOR /
                          (m_cell * m_cell);
    // Spread over the four cells around the landing by its bilinear weights (the amount kept;
    // one cell would print each drop as a cell-sized square).
    for (const splash::Landing& l : landings) {
        const glm::vec2 g = toGrid(glm::vec2(l.position.x, l.position.z));
        const glm::vec2 base(std::floor(g.x), std::floor(g.y)), w = g - base;
        const float amount = perArea * l.radius * l.radius;
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) {
                const int i = int(base.x) + di, j = int(base.y) + dj;
                const float weight = (di ? w.x : 1.0f - w.x) * (dj ? w.y : 1.0f - w.y);
                if (i >= 0 && j >= 0 && i < m_n && j < m_n && weight > 0.0f) add(i, j, amount * weight);
            }
    }
}

void FoamMap::step(float dt) {
    const float a = float(std::exp(-double(dt) / double(m_def.decay_s)));
    const int n = m_n;
    const float* src = m_f.data();
    float* dst = m_next.data();

    // --- still water: decay only
    if (m_flow == Flow::Still) {
        parallelFor(0, n, ROW_CHUNK, [&](int lo, int hi) {
            scaleKernel(dst + size_t(lo) * size_t(n), src + size_t(lo) * size_t(n), size_t(hi - lo) * size_t(n), a);
        });
        m_f.swap(m_next);
        return;
    }

    // --- uniform flow: every cell reads the same 2×2 stencil offset, weights folded with the decay
    if (m_flow == Flow::Uniform) {
        const glm::vec2 o = -m_uniform * dt / m_cell;  // source offset, cells
        const float ofx = std::floor(o.x), ofz = std::floor(o.y);
        const int ix = int(ofx), iz = int(ofz);
        const float tx = o.x - ofx, tz = o.y - ofz;
        const float w00 = a * (1 - tx) * (1 - tz), w10 = a * tx * (1 - tz), w01 = a * (1 - tx) * tz, w11 = a * tx * tz;
        // Columns whose four sources are all inside a row: i + ix >= 0 and i + ix + 1 <= n − 1.
        const int lo = std::clamp(-ix, 0, n), hi = std::clamp(n - 1 - ix, lo, n);
        parallelFor(0, n, ROW_CHUNK, [&](int rowLo, int rowHi) {
            for (int j = rowLo; j < rowHi; ++j) {
                float* d = dst + size_t(j) * size_t(n);
                const int j0 = j + iz, j1 = j0 + 1;
                const bool in0 = j0 >= 0 && j0 < n, in1 = j1 >= 0 && j1 < n;
                auto edge = [&](int i) {
                    d[i] = floored(w00 * cellOr0(src, n, i + ix, j0) + w10 * cellOr0(src, n, i + ix + 1, j0) +
                                   w01 * cellOr0(src, n, i + ix, j1) + w11 * cellOr0(src, n, i + ix + 1, j1));
                };
                if (!in0 || !in1) {
                    for (int i = 0; i < n; ++i) edge(i);
                    continue;
                }
                for (int i = 0; i < lo; ++i) edge(i);
                uniformRowKernel(d, src + size_t(j0) * size_t(n), src + size_t(j1) * size_t(n), lo, hi, ix, w00, w10, w01, w11);
                for (int i = hi; i < n; ++i) edge(i);
            }
        });
        m_f.swap(m_next);
        return;
    }

    // --- per-cell velocity: from the nodes in one sweep where no node crosses a cell a step,
    // else the split passes
    if (m_flow == Flow::Nodes && sweepFits(dt)) {
        sweep(nullptr, dt);
        return;
    }
    splitStep(dt);
}

// Per-cell velocity, split by axis: along x with u_x into m_split, then along z with u_z (and
// the decay) into the result; each pass reads only the previous one, so rows are independent
// within a pass. Rows where the flow crosses more than a cell redo the pass with a general
// linear interpolation (0 from outside).
void FoamMap::splitStep(float dt) {
    const float a = float(std::exp(-double(dt) / double(m_def.decay_s)));
    const int n = m_n;
    const float* src = m_f.data();
    float* dst = m_next.data();
    const float back = dt / m_cell;  // (m/s) → cells over dt
    const bool nodes = m_flow == Flow::Nodes;
    // Row j's velocity component: the per-cell arrays' row, or formed from the nodes in rowBuf.
    const auto velocityRow = [&](int j, int component, std::vector<float>& rowBuf, std::vector<float>& scratch) -> const float* {
        if (!nodes) return (component == 0 ? m_ux.data() : m_uz.data()) + size_t(j) * size_t(n);
        rowBuf.resize(size_t(n));
        scratch.resize(size_t(flowNodes()));
        nodeRow(j, component, rowBuf.data(), scratch.data());
        return rowBuf.data();
    };
    m_split.resize(m_f.size());
    float* split = m_split.data();
    parallelFor(0, n, ROW_CHUNK, [&](int rowLo, int rowHi) {
        std::vector<float> rowBuf, scratch;
        for (int j = rowLo; j < rowHi; ++j) {
            const size_t row = size_t(j) * size_t(n);
            const float* s = src + row;
            const float* u = velocityRow(j, 0, rowBuf, scratch);
            float* d = split + row;
            const bool over = xPassKernel(d, s, u, 1, n - 1, back) != 0;
            for (int i : {0, n - 1}) d[i] = lerpRow(s, n, float(i) - u[i] * back);  // a neighbour is outside
            if (!over) continue;
            for (int i = 1; i < n - 1; ++i) d[i] = lerpRow(s, n, float(i) - u[i] * back);
        }
    });
    m_zeros.resize(size_t(n), 0.0f);
    parallelFor(0, n, ROW_CHUNK, [&](int rowLo, int rowHi) {
        std::vector<float> rowBuf, scratch;
        for (int j = rowLo; j < rowHi; ++j) {
            const size_t row = size_t(j) * size_t(n);
            const float* up = j > 0 ? split + row - size_t(n) : m_zeros.data();
            const float* down = j + 1 < n ? split + row + size_t(n) : m_zeros.data();
            const float* u = velocityRow(j, 1, rowBuf, scratch);
            float* d = dst + row;
            if (zPassKernel(d, up, split + row, down, u, n, back, a) == 0) continue;
            for (int i = 0; i < n; ++i) {
                const float g = std::clamp(float(j) - u[i] * back, -1.0f, float(n));
                const float g0 = std::floor(g);
                const int z0 = int(g0);
                const float t = g - g0;
                d[i] = floored(a * ((1 - t) * cellOr0(split, n, i, z0) + t * cellOr0(split, n, i, z0 + 1)));
            }
        }
    });
    m_f.swap(m_next);
}

// The sweep needs every cell's flow within a cell a step (its departure point between the cell
// and a neighbour); a cell's velocity is a convex combination of nodes', so the nodes' bound
// holds for it (the margin covers the rounding of the combination).
bool FoamMap::sweepFits(float dt) const { return m_nodesMax * (dt / m_cell) <= 0.999f; }

// The step from the nodes in one sweep over the rows, in place, with the sources (a), (b) of
// `s` added to each row before it moves (as addSources then step): a chunk of rows [lo, hi)
// keeps the x pass of rows j − 1, j, j + 1 and writes the z pass of row j over row j, whose
// coverage it no longer needs; the rows around a chunk are read from copies taken before (the
// neighbour chunks overwrite them), so every row's result is the same for any split. A row's
// velocity is bilinear between the nodes: their rows expanded along x first (m_nodeRows), then
// the lerp of the two around it along z.
void FoamMap::sweep(const Sources* s, float dt) {
    const float a = float(std::exp(-double(dt) / double(m_def.decay_s)));
    const int n = m_n, m = flowNodes(), stride = flowStride();
    const float inv = 1.0f / float(stride);  // exact: a power of two
    const glm::ivec2 q = m_originCell - m_nodesOrigin * stride;  // cell (0, 0) past node (0, 0)
    assert(q.x >= 0 && q.y >= 0 && q.x < stride && q.y < stride);
    const float back = dt / m_cell;  // (m/s) → cells over dt
    const size_t row = size_t(n);

    // --- the node rows along x: [l][component][cell]
    const int threads = std::min(workerCount(), m_sweepThreads);
    m_nodeRows.resize(size_t(m) * 2 * row);
    parallelFor(0, m, threads > 1 ? 8 : m, [&](int lo, int hi) {
        std::vector<float> scratch(static_cast<size_t>(m));
        for (int l = lo; l < hi; ++l)
            for (int c = 0; c < 2; ++c) {
                for (int k = 0; k < m; ++k) scratch[size_t(k)] = m_nodes[size_t(l) * size_t(m) + size_t(k)][c];
                nodeSegmentsKernel(&m_nodeRows[(size_t(l) * 2 + size_t(c)) * row], scratch.data(), n, stride, q.x, inv);
            }
    });
    const auto nodeRows = [&](int r, int component, const float*& e0, const float*& e1) {
        const int p = r + q.y, l = p / stride;
        e0 = &m_nodeRows[(size_t(l) * 2 + size_t(component)) * row];
        e1 = e0 + 2 * row;  // node row l + 1
        return float(p % stride) * inv;
    };

    // --- the chunks and copies of the rows around them
    const int chunks = std::clamp(threads, 1, std::max(1, n / ROW_CHUNK));
    const auto chunkStart = [&](int c) { return int(int64_t(n) * c / chunks); };
    m_halo.resize(size_t(chunks) * 2 * row);
    for (int c = 1; c < chunks; ++c) {  // rows b − 1 and b around boundary b
        const int b = chunkStart(c);
        std::memcpy(&m_halo[size_t(c) * 2 * row], &m_f[size_t(b - 1) * row], 2 * row * sizeof(float));
    }

    float* f = m_f.data();
    parallelFor(0, chunks, 1, [&](int cLo, int cHi) {
        std::vector<float> ring(3 * row), sourced(row);
        RowCache cache;
        for (int c = cLo; c < cHi; ++c) {
            const int lo = chunkStart(c), hi = chunkStart(c + 1);
            // Row r's coverage before the step (the copies for the rows around the chunk).
            const auto coverage = [&](int r) -> const float* {
                if (r == lo - 1) return &m_halo[size_t(c) * 2 * row];
                if (r == hi && c + 1 < chunks) return &m_halo[size_t(c + 1) * 2 * row + row];
                return f + size_t(r) * row;
            };
            // Row r's coverage with its sources, moved along x with u_x (0 outside the map).
            const auto xRow = [&](int r, float* out) {
                if (r < 0 || r >= n) {
                    std::fill(out, out + n, 0.0f);
                    return;
                }
                const float* in = coverage(r);
                if (s && cache.add(*s, r, in, sourced.data(), n)) in = sourced.data();
                const float *e0, *e1;
                const float t = nodeRows(r, 0, e0, e1);
                xSweepKernel(out, in, e0, e1, t, 1, n - 1, back);
                for (int i : {0, n - 1}) {  // a neighbour is outside: 0
                    const float u = e0[i] * (1 - t) + e1[i] * t;
                    out[i] = passCell(in[i], i > 0 ? in[i - 1] : 0.0f, i + 1 < n ? in[i + 1] : 0.0f, u * back);
                }
            };
            float* up = ring.data();
            float* mid = up + n;
            float* down = mid + n;
            xRow(lo - 1, up);
            xRow(lo, mid);
            for (int j = lo; j < hi; ++j) {
                xRow(j + 1, down);
                const float *e0, *e1;
                const float t = nodeRows(j, 1, e0, e1);
                zSweepKernel(f + size_t(j) * row, up, mid, down, e0, e1, t, n, back, a);
                float* old = up;
                up = mid, mid = down, down = old;
            }
        }
    });
}

void FoamMap::update(const FoamInputs& in, float dt) {
    // --- the velocity grid at the water's time
    if (in.water) refreshFlow(*in.water);
    // --- sources and step: one sweep when the flow is from the nodes and within a cell a step
    const Sources s = sources(in, dt);
    if (m_flow == Flow::Nodes && sweepFits(dt)) {
        sweep(&s, dt);
        return;
    }
    addSources(s);
    step(dt);
}

void FoamMap::hash(StateHasher& h) const {
    h.u64(uint64_t(uint32_t(m_originCell.x)) | (uint64_t(uint32_t(m_originCell.y)) << 32));
    h.f32(m_cell);
    h.f32s(m_f.data(), m_f.size());
}

} // namespace ob::foam
