// Persistent foam map: semi-Lagrangian advection, exact decay, the four sources (laws in the header).
#include "foam/foam_map.h"

#include "core/hash.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace ob::foam {

namespace {

// Rows per parallelFor chunk: 512² is 32 chunks of 16 rows, ~8 µs each.
constexpr int ROW_CHUNK = 16;

// Coverage of a row-major n×n map at cell (i, j), 0 outside.
inline float cellOr0(const float* f, int n, int i, int j) {
    return (i < 0 || j < 0 || i >= n || j >= n) ? 0.0f : f[size_t(j) * size_t(n) + size_t(i)];
}

// One row of the uniform-flow step: dst[i] = w00·s0[i+ix] + w10·s0[i+ix+1] + w01·s1[i+ix] +
// w11·s1[i+ix+1] for i in [lo, hi), where every index is inside its row.
OB_VECTOR_KERNEL void uniformRowKernel(float* __restrict dst, const float* __restrict s0, const float* __restrict s1,
                                       int lo, int hi, int ix, float w00, float w10, float w01, float w11) {
    for (int i = lo; i < hi; ++i)
        dst[i] = w00 * s0[i + ix] + w10 * s0[i + ix + 1] + w01 * s1[i + ix] + w11 * s1[i + ix + 1];
}

// Linear interpolation of a row of n values (0 outside) at g (in cells; centres at integers).
inline float lerpRow(const float* row, int n, float g) {
    g = std::clamp(g, -1.0f, float(n));  // beyond: both samples are 0 anyway
    const float g0 = std::floor(g);
    const int x0 = int(g0);
    const float t = g - g0;
    return (1 - t) * cellOr0(row, n, x0, 0) + t * cellOr0(row, n, x0 + 1, 0);
}

// Per-cell flow, pass 1, the cells [lo, hi) of a row (neighbours inside it): the water moves
// c = ux·back cells along x this step; for |c| ≤ 1 the departure point x − c lies between the
// cell and its upstream neighbour: dst = src + max(c, 0)·(left − src) + max(−c, 0)·(right − src).
// Returns nonzero when some |c| > 1 (the row is then redone by lerpRow).
OB_VECTOR_KERNEL int xPassKernel(float* __restrict dst, const float* __restrict src, const float* __restrict ux, int lo,
                                 int hi, float back) {
    int over = 0;
    for (int i = lo; i < hi; ++i) {
        const float c = ux[i] * back;
        const float cp = c > 0.0f ? c : 0.0f, cm = c < 0.0f ? -c : 0.0f;
        over |= int(c > 1.0f) | int(c < -1.0f);
        dst[i] = src[i] + cp * (src[i - 1] - src[i]) + cm * (src[i + 1] - src[i]);
    }
    return over;
}

// Pass 2, one row along z from the rows above (j − 1), at and below (j + 1) it, times the decay a.
OB_VECTOR_KERNEL int zPassKernel(float* __restrict dst, const float* __restrict up, const float* __restrict mid,
                                 const float* __restrict down, const float* __restrict uz, int n, float back, float a) {
    int over = 0;
    for (int i = 0; i < n; ++i) {
        const float c = uz[i] * back;
        const float cp = c > 0.0f ? c : 0.0f, cm = c < 0.0f ? -c : 0.0f;
        over |= int(c > 1.0f) | int(c < -1.0f);
        dst[i] = a * (mid[i] + cp * (up[i] - mid[i]) + cm * (down[i] - mid[i]));
    }
    return over;
}

OB_VECTOR_KERNEL void scaleKernel(float* __restrict dst, const float* __restrict src, size_t count, float a) {
    for (size_t i = 0; i < count; ++i) dst[i] = a * src[i];
}

} // namespace

FoamMap::FoamMap(const FoamDef& def, float extent, glm::vec2 centre)
    : m_def(def), m_n(def.resolution), m_cell(extent / float(def.resolution)),
      m_f(size_t(def.resolution) * size_t(def.resolution), 0.0f), m_next(m_f.size(), 0.0f) {
    m_originCell = glm::ivec2(int(std::lround(centre.x / m_cell)), int(std::lround(centre.y / m_cell))) - glm::ivec2(m_n / 2);
}

void FoamMap::setDef(const FoamDef& def) {
    const int n = m_n;
    m_def = def;
    m_def.resolution = n;
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

std::vector<glm::vec2> FoamMap::flowNodePositions() const {
    const int m = flowNodes(), s = flowStride();
    const glm::vec2 o = origin();
    std::vector<glm::vec2> out(size_t(m) * size_t(m));
    for (int l = 0; l < m; ++l)
        for (int k = 0; k < m; ++k) out[size_t(l) * size_t(m) + size_t(k)] = o + glm::vec2(float(k * s), float(l * s)) * m_cell;
    return out;
}

// Cells [k·s, (k + 1)·s) of a row, k < segments, linear between node values v[k] and v[k + 1].
OB_VECTOR_KERNEL static void nodeSegmentsKernel(float* __restrict out, const float* __restrict v, int segments, int s,
                                                float inv) {
    for (int k = 0; k < segments; ++k) {
        const float v0 = v[k], v1 = v[k + 1];
        float* d = out + size_t(k) * size_t(s);
        for (int q = 0; q < s; ++q) {
            const float tx = float(q) * inv;
            d[q] = v0 * (1 - tx) + v1 * tx;
        }
    }
}

void FoamMap::setVelocityNodes(std::span<const glm::vec2> nodes) {
    assert(nodes.size() == size_t(flowNodes()) * size_t(flowNodes()));
    m_nodes.assign(nodes.begin(), nodes.end());
    m_flow = Flow::Nodes;
}

// Row j's velocity component (0: x, 1: z) from the nodes: the two node rows around it lerped
// along z into scratch (flowNodes() floats), then along x between each pair of nodes.
void FoamMap::nodeRow(int j, int component, float* out, float* scratch) const {
    const int m = flowNodes(), s = flowStride();
    const float inv = 1.0f / float(s);  // exact: s is a power of two
    const int l = j / s;
    const float tz = float(j % s) * inv;
    const glm::vec2* n0 = &m_nodes[size_t(l) * size_t(m)];
    const glm::vec2* n1 = n0 + m;  // l + 1 ≤ N/s: a node row exists
    for (int k = 0; k < m; ++k) scratch[k] = n0[k][component] * (1 - tz) + n1[k][component] * tz;
    nodeSegmentsKernel(out, scratch, m - 1, s, inv);
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

// One foam row of the whitecap source: the tile row (lerped along z) read bilinearly along x
// at each column's two samples, J = row[i0]·(1 − t) + row[i1]·t, then the excess as addExcessKernel.
OB_VECTOR_KERNEL static void whitecapRowKernel(float* __restrict f, const float* __restrict row, const int* __restrict i0,
                                               const int* __restrict i1, const float* __restrict t, int n, float j0,
                                               float rate) {
    for (int i = 0; i < n; ++i) {
        const float j = row[i0[i]] * (1 - t[i]) + row[i1[i]] * t[i];
        float excess = j0 - j;
        excess = excess > 0.0f ? excess : 0.0f;
        const float v = f[i] + excess * rate;
        f[i] = v < 1.0f ? v : 1.0f;
    }
}

void FoamMap::addWhitecaps(std::span<const float> jacobian, int n, float tile, float dt) {
    if (m_def.whitecap_weight <= 0.0f || n <= 0) return;
    const float toTile = float(n) / tile;  // tile samples per metre
    const glm::vec2 o = origin();
    // Bilinear in the periodic tile at each cell centre (rest-point coordinates): the columns'
    // samples and weights once (structure of arrays), then per row the two tile rows lerped
    // along z and read at them.
    std::vector<int> c0(static_cast<size_t>(m_n)), c1(static_cast<size_t>(m_n));
    std::vector<float> ct(static_cast<size_t>(m_n));
    for (int i = 0; i < m_n; ++i) {
        const Wrapped c = wrap((o.x + float(i) * m_cell) * toTile, n);
        c0[size_t(i)] = c.i0, c1[size_t(i)] = c.i1, ct[size_t(i)] = c.t;
    }
    parallelFor(0, m_n, ROW_CHUNK, [&](int rowLo, int rowHi) {
        std::vector<float> row(static_cast<size_t>(n));
        for (int j = rowLo; j < rowHi; ++j) {
            const Wrapped r = wrap((o.y + float(j) * m_cell) * toTile, n);
            const float* r0 = &jacobian[size_t(r.i0) * size_t(n)];
            const float* r1 = &jacobian[size_t(r.i1) * size_t(n)];
            for (int x = 0; x < n; ++x) row[size_t(x)] = r0[x] * (1 - r.t) + r1[x] * r.t;
            whitecapRowKernel(&m_f[size_t(j) * size_t(m_n)], row.data(), c0.data(), c1.data(), ct.data(), m_n,
                              m_def.whitecap_jacobian, m_def.whitecap_weight * dt);
        }
    });
}

// |∇h| by central differences at the interior cells [1, cols − 1) of the ripple row `mid`
// (its neighbours one row up and down at ∓cols), per metre via inv2d = 1/(2Δ).
OB_VECTOR_KERNEL static void slopeRippleRow(float* __restrict out, const float* __restrict mid, int cols, float inv2d) {
    const float* up = mid - cols;
    const float* down = mid + cols;
    for (int x = 1; x < cols - 1; ++x) {
        const float sx = (mid[x + 1] - mid[x - 1]) * inv2d, sz = (down[x] - up[x]) * inv2d;
        out[x] = std::sqrt(sx * sx + sz * sz);
    }
}

void FoamMap::addRipples(const interaction::RipplePatch& patch, float dt) {
    if (m_def.ripple_weight <= 0.0f) return;
    const int rows = patch.rows(), cols = patch.cols();
    const std::span<const float> h = patch.height();  // either model's

    const float inv2d = 1.0f / (2.0f * patch.def().cell_size);
    const glm::vec2 o = origin();
    // The nearest ripple cell of each foam column and row; only interior ripple cells have a
    // central difference, and they form one range of columns and one of rows (the rows split
    // over the pool).
    std::vector<int> rx(static_cast<size_t>(m_n));
    int iLo = m_n, iHi = 0;
    for (int i = 0; i < m_n; ++i) {
        const long x = std::lround(patch.toGrid(glm::vec2(o.x + float(i) * m_cell, o.y)).x);
        rx[size_t(i)] = int(x);
        if (x >= 1 && x <= cols - 2) iLo = std::min(iLo, i), iHi = std::max(iHi, i + 1);
    }
    if (iLo >= iHi) return;
    std::vector<int> rz(static_cast<size_t>(m_n));
    int jLo = m_n, jHi = 0;
    for (int j = 0; j < m_n; ++j) {
        const long z = std::lround(patch.toGrid(glm::vec2(o.x, o.y + float(j) * m_cell)).y);
        rz[size_t(j)] = int(z);
        if (z >= 1 && z <= rows - 2) jLo = std::min(jLo, j), jHi = std::max(jHi, j + 1);
    }
    if (jLo >= jHi) return;
    parallelFor(jLo, jHi, ROW_CHUNK, [&](int rowLo, int rowHi) {
        std::vector<float> slope(static_cast<size_t>(m_n)), rippleSlope(static_cast<size_t>(cols));
        int slopeRow = -1;  // the ripple row rippleSlope holds
        for (int j = rowLo; j < rowHi; ++j) {
            const int z = rz[size_t(j)];
            if (z != slopeRow) {  // |∇h| along the whole ripple row, once per ripple row
                slopeRippleRow(rippleSlope.data(), &h[size_t(z) * size_t(cols)], cols, inv2d);
                slopeRow = z;
            }
            for (int i = iLo; i < iHi; ++i) slope[size_t(i)] = rippleSlope[size_t(rx[size_t(i)])];
            addExcessKernel(&m_f[size_t(j) * size_t(m_n) + size_t(iLo)], &slope[size_t(iLo)], iHi - iLo,
                            m_def.ripple_slope, m_def.ripple_weight * dt);
        }
    });
}

void FoamMap::addLandings(std::span<const splash::Landing> landings) {
    if (m_def.splash_weight <= 0.0f) return;
    const float perArea = m_def.splash_weight * std::numbers::pi_v<float> * DROP_FOAM_RADIUS_FACTOR * DROP_FOAM_RADIUS_FACTOR /
                          (m_cell * m_cell);
    for (const splash::Landing& l : landings) {
        const glm::vec2 g = toGrid(glm::vec2(l.position.x, l.position.z));
        const long i = std::lround(g.x), j = std::lround(g.y);
        if (i < 0 || j < 0 || i >= m_n || j >= m_n) continue;
        add(int(i), int(j), perArea * l.radius * l.radius);
    }
}

void FoamMap::addWake(const glm::vec3& centre, const glm::vec3& velocity, float radius, float dt) {
    const glm::vec2 u(velocity.x, velocity.z);
    const float speed = std::sqrt(u.x * u.x + u.y * u.y);
    if (m_def.wake_weight <= 0.0f || speed <= 0.0f || radius <= 0.0f) return;
    const float amount = m_def.wake_weight * speed / radius * dt;
    const glm::vec2 c = toGrid(glm::vec2(centre.x, centre.z));
    const float rCells = radius / m_cell;
    const int i0 = std::max(0, int(std::floor(c.x - rCells))), i1 = std::min(m_n - 1, int(std::ceil(c.x + rCells)));
    const int j0 = std::max(0, int(std::floor(c.y - rCells))), j1 = std::min(m_n - 1, int(std::ceil(c.y + rCells)));
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const glm::vec2 d(float(i) - c.x, float(j) - c.y);  // cells
            if (d.x * d.x + d.y * d.y > rCells * rCells) continue;
            if (d.x * u.x + d.y * u.y > 0.0f) continue;  // ahead of the sphere's centre
            add(i, j, amount);
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
                    d[i] = w00 * cellOr0(src, n, i + ix, j0) + w10 * cellOr0(src, n, i + ix + 1, j0) +
                           w01 * cellOr0(src, n, i + ix, j1) + w11 * cellOr0(src, n, i + ix + 1, j1);
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

    // --- per-cell velocity, split by axis: along x with u_x into m_split, then along z with u_z
    // (and the decay) into the result; each pass reads only the previous one, so rows are
    // independent within a pass. Rows where the flow crosses more than a cell redo the pass
    // with a general linear interpolation (0 from outside).
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
                d[i] = a * ((1 - t) * cellOr0(split, n, i, z0) + t * cellOr0(split, n, i, z0 + 1));
            }
        }
    });
    m_f.swap(m_next);
}

void FoamMap::hash(StateHasher& h) const {
    h.u64(uint64_t(uint32_t(m_originCell.x)) | (uint64_t(uint32_t(m_originCell.y)) << 32));
    h.f32(m_cell);
    h.f32s(m_f.data(), m_f.size());
}

} // namespace ob::foam
