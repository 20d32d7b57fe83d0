// Persistent foam map: semi-Lagrangian advection, exact decay, the four sources (laws in the header).
#include "foam/foam_map.h"

#include "core/hash.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"

#include <algorithm>
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

// Zero cells round the padded copy the per-cell flow reads.
constexpr int PAD = 2;

// One row j of the per-cell flow step: dst[i] = a · bilinear(padded, (i, j) − u·back), the
// traced point clamped to [−1.5, n + 0.5] (inside the zero ring). int(g + PAD) − PAD is
// floor(g) there, as g + PAD > 0.
OB_VECTOR_KERNEL void fieldRowKernel(float* __restrict dst, const float* __restrict padded, const float* __restrict ux,
                                     const float* __restrict uz, int n, int j, int stride, float back, float a) {
    const float lo = -1.5f, hi = float(n) + 0.5f;
    for (int i = 0; i < n; ++i) {
        float gx = float(i) - ux[i] * back, gz = float(j) - uz[i] * back;
        gx = gx < lo ? lo : gx;
        gx = gx > hi ? hi : gx;
        gz = gz < lo ? lo : gz;
        gz = gz > hi ? hi : gz;
        const int x0 = int(gx + float(PAD)) - PAD, z0 = int(gz + float(PAD)) - PAD;
        const float tx = gx - float(x0), tz = gz - float(z0);
        const int c = (z0 + PAD) * stride + (x0 + PAD);
        const float v00 = padded[c], v10 = padded[c + 1], v01 = padded[c + stride], v11 = padded[c + stride + 1];
        dst[i] = a * ((v00 * (1 - tx) + v10 * tx) * (1 - tz) + (v01 * (1 - tx) + v11 * tx) * tz);
    }
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

void FoamMap::addWhitecaps(std::span<const float> jacobian, int n, float tile, float dt) {
    if (m_def.whitecap_weight <= 0.0f || n <= 0) return;
    const float toTile = float(n) / tile;  // tile samples per metre
    const glm::vec2 o = origin();
    // Bilinear in the periodic tile at each cell centre (rest-point coordinates): the columns'
    // samples and weights once, then row by row. The source is max(0, J₀ − J) = max(0, (−J) − (−J₀)).
    std::vector<Wrapped> columns(static_cast<size_t>(m_n));
    for (int i = 0; i < m_n; ++i) columns[size_t(i)] = wrap((o.x + float(i) * m_cell) * toTile, n);
    std::vector<float> negJ(static_cast<size_t>(m_n));
    for (int j = 0; j < m_n; ++j) {
        const Wrapped r = wrap((o.y + float(j) * m_cell) * toTile, n);
        const float* r0 = &jacobian[size_t(r.i0) * size_t(n)];
        const float* r1 = &jacobian[size_t(r.i1) * size_t(n)];
        for (int i = 0; i < m_n; ++i) {
            const Wrapped& c = columns[size_t(i)];
            negJ[size_t(i)] = -((r0[c.i0] * (1 - c.t) + r0[c.i1] * c.t) * (1 - r.t) + (r1[c.i0] * (1 - c.t) + r1[c.i1] * c.t) * r.t);
        }
        addExcessKernel(&m_f[size_t(j) * size_t(m_n)], negJ.data(), m_n, -m_def.whitecap_jacobian, m_def.whitecap_weight * dt);
    }
}

void FoamMap::addRipples(const interaction::RipplePatch& patch, float dt) {
    if (m_def.ripple_weight <= 0.0f) return;
    const int rows = patch.rows(), cols = patch.cols();
    const std::span<const float> h = patch.height();  // either model's

    const float inv2d = 1.0f / (2.0f * patch.def().cell_size);
    const glm::vec2 o = origin();
    // The nearest ripple cell of each foam column and row; only interior ripple cells have a
    // central difference, and they form one range of columns and one of rows.
    std::vector<int> rx(static_cast<size_t>(m_n));
    int iLo = m_n, iHi = 0;
    for (int i = 0; i < m_n; ++i) {
        const long x = std::lround(patch.toGrid(glm::vec2(o.x + float(i) * m_cell, o.y)).x);
        rx[size_t(i)] = int(x);
        if (x >= 1 && x <= cols - 2) iLo = std::min(iLo, i), iHi = std::max(iHi, i + 1);
    }
    if (iLo >= iHi) return;
    std::vector<float> slope(static_cast<size_t>(m_n));
    for (int j = 0; j < m_n; ++j) {
        const long z = std::lround(patch.toGrid(glm::vec2(o.x, o.y + float(j) * m_cell)).y);
        if (z < 1 || z > rows - 2) continue;
        const float* up = &h[size_t(z - 1) * size_t(cols)];
        const float* mid = up + cols;
        const float* down = mid + cols;
        for (int i = iLo; i < iHi; ++i) {
            const int x = rx[size_t(i)];
            const float sx = (mid[x + 1] - mid[x - 1]) * inv2d, sz = (down[x] - up[x]) * inv2d;
            slope[size_t(i)] = std::sqrt(sx * sx + sz * sz);
        }
        addExcessKernel(&m_f[size_t(j) * size_t(m_n) + size_t(iLo)], &slope[size_t(iLo)], iHi - iLo, m_def.ripple_slope,
                        m_def.ripple_weight * dt);
    }
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

    // --- per-cell velocity: trace each cell centre back by u·dt, bilinear there. The source is
    // copied into a map with a ring of PAD zero cells and the traced point clamped into that
    // ring, so the kernel reads no branch: beyond the ring the value would be 0 as well.
    const int stride = n + 2 * PAD;
    m_padded.resize(size_t(stride) * size_t(stride));  // the ring is 0 from here on, rows are overwritten
    parallelFor(0, n, ROW_CHUNK, [&](int rowLo, int rowHi) {
        for (int j = rowLo; j < rowHi; ++j)
            std::copy(src + size_t(j) * size_t(n), src + size_t(j + 1) * size_t(n),
                      m_padded.data() + size_t(j + PAD) * size_t(stride) + PAD);
    });
    const float back = dt / m_cell;  // (m/s) → cells over dt
    const float* ux = m_ux.data();
    const float* uz = m_uz.data();
    const float* padded = m_padded.data();
    parallelFor(0, n, ROW_CHUNK, [&](int rowLo, int rowHi) {
        for (int j = rowLo; j < rowHi; ++j) {
            const size_t row = size_t(j) * size_t(n);
            fieldRowKernel(dst + row, padded, ux + row, uz + row, n, j, stride, back, a);
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
