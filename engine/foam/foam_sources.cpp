// The foam sources read from the sea and the drops (laws (a)–(c) in foam_sources.h): whitecaps
// from the ocean's Jacobian, steep ripples, landed splash drops.
#include "foam/foam_sources.h"

#include "core/parallel.h"
#include "core/simd.h"
#include "foam/foam_whitecaps.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"

#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

namespace ob::foam {

namespace {

// Where a coordinate g (in samples of a periodic map of n) falls: the two samples around it
// and the weight of the second.
struct Wrapped {
    int i0, i1;
    float t;
};
Wrapped wrap(float g, int n) {
    const float f = std::floor(g);
    long long i = (long long)(f) % n;
    if (i < 0) i += n;
    return Wrapped{int(i), int(i) + 1 == n ? 0 : int(i) + 1, g - f};
}

// One foam row of a source: f[i] = min(1, f[i] + max(0, s[i] − threshold)·rate), i in [0, n).
OB_VECTOR_KERNEL void addExcessKernel(float* __restrict f, const float* __restrict s, int n, float threshold, float rate) {
    for (int i = 0; i < n; ++i) {
        float excess = s[i] - threshold;
        excess = excess > 0.0f ? excess : 0.0f;
        const float v = f[i] + excess * rate;
        f[i] = v < 1.0f ? v : 1.0f;
    }
}

// One foam row of the whitecap source from the two tile rows around it, each already read at
// every column (u0, u1): J = u0·(1 − t) + u1·t, out = min(1, in + max(0, j0 − J)·rate·(1 − in)):
// the breaking covers the share still open, so coverage nears 1 smoothly (no plateau).
inline float whitecapCell(float in, float u0, float u1, float t, float j0, float rate) {
    const float j = u0 * (1 - t) + u1 * t;
    float excess = j0 - j;
    excess = excess > 0.0f ? excess : 0.0f;
    const float v = in + excess * rate * (1.0f - in);
    return v < 1.0f ? v : 1.0f;
}
OB_VECTOR_KERNEL void whitecapRowKernel(float* __restrict out, const float* __restrict in, const float* __restrict u0,
                                        const float* __restrict u1, float t, int n, float j0, float rate) {
    for (int i = 0; i < n; ++i) out[i] = whitecapCell(in[i], u0[i], u1[i], t, j0, rate);
}
OB_VECTOR_KERNEL void whitecapRowInPlaceKernel(float* __restrict f, const float* __restrict u0, const float* __restrict u1,
                                               float t, int n, float j0, float rate) {
    for (int i = 0; i < n; ++i) f[i] = whitecapCell(f[i], u0[i], u1[i], t, j0, rate);
}

// A tile row read at every foam column: out[i] = w[c0[i]]·(1 − t[i]) + w[c0[i] + 1]·t[i].
OB_VECTOR_KERNEL void upsampleRowKernel(float* __restrict out, const float* __restrict w, const int* __restrict c0,
                                        const float* __restrict t, int n) {
    for (int i = 0; i < n; ++i) out[i] = w[c0[i]] * (1 - t[i]) + w[c0[i] + 1] * t[i];
}

// |∇h|² by central differences at the interior cells [1, cols − 1) of the ripple row `mid`
// (its neighbours one row up and down at ∓cols), per metre via inv2d = 1/(2Δ). Returns nonzero
// when some |∇h|² exceeds steep (the row then needs its square roots, slopeRoots).
OB_VECTOR_KERNEL int slopeSquaredRow(float* __restrict out, const float* __restrict mid, int cols, float inv2d, float steep) {
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

OB_VECTOR_KERNEL void slopeRoots(float* __restrict v, int cols) {
    for (int x = 1; x < cols - 1; ++x) v[x] = std::sqrt(v[x]);
}

} // namespace

RowSources::RowSources(const FoamDef& def, const ScrollingGrid& grid, const FoamInputs& in, float dt)
    : m_mapN(grid.n), m_cell(grid.cell), m_origin(grid.origin()) {
    if (def.whitecap_weight > 0.0f && in.jacobianN > 0 && !in.jacobian.empty()) tabulateWhitecaps(def, in, dt);
    if (def.ripple_weight > 0.0f && in.ripples)
        tabulateRipples(def, *in.ripples, in.rippleHeight.empty() ? in.ripples->height() : in.rippleHeight, dt);
}

// Bilinear in the periodic tile at each sample (rest-point coordinates): the columns' samples
// once, the window starting at the tile sample at or before column 0.
void RowSources::tabulateWhitecaps(const FoamDef& def, const FoamInputs& in, float dt) {
    const int n = in.jacobianN, mapN = m_mapN;
    const glm::vec2 o = m_origin;
    assert(in.jacobian.size() >= size_t(n) * size_t(n));
    m_jacobian = in.jacobian.data();
    m_n = n;
    m_toTile = float(n) / in.jacobianTile;
    if (def.whitecap_from_wind) {
        const WhitecapLaw law =
            deriveWhitecapLaw(jacobianStats(in.jacobian, n, in.jacobianTile), in.windSpeed, in.gravity, def.decay_s);
        m_law = law;
        m_law.rate *= 0.5f * def.whitecap_weight;
    } else {
        m_law.j0 = def.whitecap_jacobian;
        m_law.rate = def.whitecap_weight;
    }
    m_j0 = m_law.j0;
    m_whitecapRate = m_law.rate * dt;
    m_c0.resize(size_t(mapN));
    m_ct.resize(size_t(mapN));
    long long k0 = 0;
    for (int i = 0; i < mapN; ++i) {
        const float g = (o.x + float(i) * m_cell) * m_toTile;
        const float f = std::floor(g);
        if (i == 0) k0 = (long long)(f);
        m_c0[size_t(i)] = int((long long)(f) - k0);
        m_ct[size_t(i)] = g - f;
    }
    m_window.resize(size_t(m_c0.back()) + 2);
    for (size_t k = 0; k < m_window.size(); ++k) {
        long long c = (k0 + (long long)(k)) % n;
        m_window[k] = int(c < 0 ? c + n : c);
    }
    // The tile rows the foam rows fall between: from the one at or before row 0 to the one
    // after row N − 1 (all n when the map spans the tile).
    const float z0 = std::floor(o.y * m_toTile), z1 = std::floor((o.y + float(mapN - 1) * m_cell) * m_toTile) + 1.0f;
    const long long rowsReached = std::min((long long)(z1 - z0) + 1, (long long)(n));
    m_rowMin.assign(size_t(n), std::numeric_limits<float>::infinity());
    for (long long k = 0; k < rowsReached; ++k) {
        long long r = ((long long)(z0) + k) % n;
        if (r < 0) r += n;
        const float* row = in.jacobian.data() + size_t(r) * size_t(n);
        float least = std::numeric_limits<float>::infinity();
        for (int c : m_window) least = std::min(least, row[c]);
        m_rowMin[size_t(r)] = least;
    }
}

// The nearest ripple cell of each foam column and row; only interior ripple cells have a
// central difference, and they form one range of columns and one of rows.
void RowSources::tabulateRipples(const FoamDef& def, const interaction::RipplePatch& patch, std::span<const float> height, float dt) {
    const int rows = patch.rows(), cols = patch.cols(), mapN = m_mapN;
    const glm::vec2 o = m_origin;
    m_rx.resize(size_t(mapN));
    m_iLo = mapN, m_iHi = 0;
    for (int i = 0; i < mapN; ++i) {
        const long x = std::lround(patch.toGrid(glm::vec2(o.x + float(i) * m_cell, o.y)).x);
        m_rx[size_t(i)] = int(x);
        if (x >= 1 && x <= cols - 2) m_iLo = std::min(m_iLo, i), m_iHi = std::max(m_iHi, i + 1);
    }
    m_rz.resize(size_t(mapN));
    m_jLo = mapN, m_jHi = 0;
    for (int j = 0; j < mapN; ++j) {
        const long z = std::lround(patch.toGrid(glm::vec2(o.x, o.y + float(j) * m_cell)).y);
        m_rz[size_t(j)] = int(z);
        if (z >= 1 && z <= rows - 2) m_jLo = std::min(m_jLo, j), m_jHi = std::max(m_jHi, j + 1);
    }
    if (m_iLo >= m_iHi || m_jLo >= m_jHi) return;
    assert(height.size() == size_t(rows) * size_t(cols));
    m_height = height.data();  // either model's
    m_cols = cols;
    m_inv2d = 1.0f / (2.0f * patch.def().cell_size);
    m_slope0 = def.ripple_slope;
    m_rippleRate = def.ripple_weight * dt;
    m_contiguous = true;
    for (int i = m_iLo; i < m_iHi; ++i) m_contiguous = m_contiguous && m_rx[size_t(i)] == m_rx[size_t(m_iLo)] + (i - m_iLo);
}

// Tile row r read at every foam column (one of the two buffers, not `keep`).
const float* RowSources::Rows::tile(int r, int keep, int& slot) {
    for (int b = 0; b < 2; ++b)
        if (m_tileRow[b] == r) return slot = b, m_upsampled[b].data();
    slot = keep == 0 ? 1 : 0;
    const int n = m_s.m_mapN;
    m_upsampled[slot].resize(size_t(n));
    m_windowRow.resize(m_s.m_window.size());
    const float* row = m_s.m_jacobian + size_t(r) * size_t(m_s.m_n);
    for (size_t k = 0; k < m_s.m_window.size(); ++k) m_windowRow[k] = row[m_s.m_window[k]];
    upsampleRowKernel(m_upsampled[slot].data(), m_windowRow.data(), m_s.m_c0.data(), m_s.m_ct.data(), n);
    m_tileRow[slot] = r;
    return m_upsampled[slot].data();
}

// Whether ripple row z has a cell steeper than the threshold; its |∇h| in m_rippleSlope (and
// gathered at the foam's columns) if so. Once per ripple row.
bool RowSources::Rows::steepRow(int z) {
    if (z == m_slopeRow) return m_steep;
    const RowSources& s = m_s;
    m_rippleSlope.resize(size_t(s.m_cols));
    m_slopeRow = z;
    m_steep = slopeSquaredRow(m_rippleSlope.data(), s.m_height + size_t(z) * size_t(s.m_cols), s.m_cols, s.m_inv2d,
                              s.m_slope0 * s.m_slope0) != 0;
    if (!m_steep) return false;
    slopeRoots(m_rippleSlope.data(), s.m_cols);
    if (!s.m_contiguous) {
        m_gathered.resize(size_t(s.m_mapN));
        for (int i = s.m_iLo; i < s.m_iHi; ++i) m_gathered[size_t(i)] = m_rippleSlope[size_t(s.m_rx[size_t(i)])];
    }
    return true;
}

bool RowSources::Rows::add(int j, const float* in, float* out) {
    const RowSources& s = m_s;
    const int n = s.m_mapN;
    const bool ripples = s.m_height && j >= s.m_jLo && j < s.m_jHi && steepRow(s.m_rz[size_t(j)]);
    if (!s.m_jacobian && !ripples) return false;
    const Wrapped r = s.m_jacobian ? wrap((s.m_origin.y + float(j) * s.m_cell) * s.m_toTile, s.m_n) : Wrapped{0, 0, 0.0f};
    const bool whitecaps = s.m_jacobian && std::min(s.m_rowMin[size_t(r.i0)], s.m_rowMin[size_t(r.i1)]) < s.m_j0;
    if (!whitecaps && !ripples) return false;
    if (whitecaps) {
        int slot0 = -1, slot1;
        const float* u0 = tile(r.i0, -1, slot0);
        const float* u1 = tile(r.i1, slot0, slot1);
        if (in == out) whitecapRowInPlaceKernel(out, u0, u1, r.t, n, s.m_j0, s.m_whitecapRate);
        else whitecapRowKernel(out, in, u0, u1, r.t, n, s.m_j0, s.m_whitecapRate);
    } else if (in != out) {
        std::memcpy(out, in, size_t(n) * sizeof(float));
    }
    if (ripples) {
        const float* slope = s.m_contiguous ? m_rippleSlope.data() + s.m_rx[size_t(s.m_iLo)]
                                            : m_gathered.data() + s.m_iLo;  // at column iLo
        addExcessKernel(out + s.m_iLo, slope, s.m_iHi - s.m_iLo, s.m_slope0, s.m_rippleRate);
    }
    return true;
}

void RowSources::addTo(std::span<float> f) const {
    if (!m_jacobian && !m_height) return;
    const int n = m_mapN;
    const int lo = m_jacobian ? 0 : m_jLo, hi = m_jacobian ? n : m_jHi;
    parallelFor(lo, hi, ROW_CHUNK, [&](int rowLo, int rowHi) {
        Rows rows(*this);
        for (int j = rowLo; j < rowHi; ++j) {
            float* row = &f[size_t(j) * size_t(n)];
            rows.add(j, row, row);
        }
    });
}

void addLandings(const FoamDef& def, const CoverageCells& cells, std::span<const splash::Landing> landings) {
    if (def.splash_weight <= 0.0f) return;
    const float cell = cells.grid.cell;
    const int n = cells.grid.n;
    const float perArea = def.splash_weight * std::numbers::pi_v<float> * DROP_FOAM_RADIUS_FACTOR * DROP_FOAM_RADIUS_FACTOR /
                          (cell * cell);
    // Spread over the four samples around the landing by its bilinear weights (the amount kept;
    // one sample would print each drop as a cell-sized square).
    for (const splash::Landing& l : landings) {
        const glm::vec2 g = cells.grid.toGrid(glm::vec2(l.position.x, l.position.z));
        const glm::vec2 base(std::floor(g.x), std::floor(g.y)), w = g - base;
        const float amount = perArea * l.radius * l.radius;
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) {
                const int i = int(base.x) + di, j = int(base.y) + dj;
                const float weight = (di ? w.x : 1.0f - w.x) * (dj ? w.y : 1.0f - w.y);
                if (i >= 0 && j >= 0 && i < n && j < n && weight > 0.0f) cells.add(i, j, amount * weight);
            }
    }
}

} // namespace ob::foam
