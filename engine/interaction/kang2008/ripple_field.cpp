// Ripple field: linear convolution, [Kang2008] eq. 1–2; fixed ring or absorbing sponge (docs/references.md#ripple-layer).
// Vh(t+1) is written over Vh(t−1) in place (eq. 2 reads Vh(t−1) only at the cell it writes),
// so two levels suffice; they then swap roles.
#include "interaction/kang2008/ripple_field.h"

#include "core/scrolling_grid.h"
#include "interaction/sponge.h"

#include "core/parallel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <numbers>

namespace ob::interaction {

namespace {

// Rows per parallel chunk are chosen so that a chunk holds at least this many cells: below
// it, waking a worker costs more than the rows it would take (measured on 2 cores: 256²
// was slower split than inline, 512² about 1.5× faster split).
constexpr int MIN_CELLS_PER_CHUNK = 32768;

// Columns per block of the row loop. A fixed trip count lets GCC's -O2 ("very cheap")
// vectoriser take the block with no epilogue or alias checks; the scalar tail runs the same
// operations in the same order, so a cell gets the same bits wherever it falls.
constexpr int BLOCK = 16;

// Friction at the outer edge of the sponge (see spongeFactor). The explicit friction term
// is stable only below 1/2 (Jury test on λ² − DF(G−γ)λ + DF(1−γ) with G >= −1).
constexpr float SPONGE_MAX_FRICTION = 0.4f;

// Eq. 1–2 for n cells starting at column x0. u, m, d point at column x0−1 of rows z−1, z,
// z+1 of Vh(t); o and c at column x0 of the output row and of the column sponge factors.
// o holds Vh(t−1) on entry and Vh(t+1) on exit (each index read, then written).
// SPONGE adds friction on the vertical velocity, γ·(Vh(t) − Vh(t−1)) with
// γ = SPONGE_MAX_FRICTION·(1 − rowFactor·c[i]); where both factors are 1, γ·(…) is ±0 and
// the cell gets eq. 2's bits. Without SPONGE the loop is eq. 2 as written.
template <bool SPONGE, int N>
inline void stepCells(const float* __restrict u, const float* __restrict m, const float* __restrict d,
                      float* __restrict o, const float* __restrict c, float df, float rowFactor, int n) {
    const int count = N > 0 ? N : n;
    for (int i = 0; i < count; ++i) {
        const float sum = (u[i] + u[i + 1] + u[i + 2]) + (m[i] + m[i + 2]) + (d[i] + d[i + 1] + d[i + 2]);
        const float buff = 0.25f * sum;  // eq. 1: C(i,j) = 1/4 for the 8 neighbours, C(0,0) = 0
        if constexpr (SPONGE) {
            const float gamma = SPONGE_MAX_FRICTION * (1.0f - rowFactor * c[i]);
            o[i] = ((buff - o[i]) - gamma * (m[i + 1] - o[i])) * df;
        } else {
            o[i] = (buff - o[i]) * df;  // eq. 2
        }
    }
}

// Eq. 1–2 for the interior columns 1..M−2 of row z; the ring columns 0 and M−1 get 0.
template <bool SPONGE>
inline void stepRow(const float* up, const float* mid, const float* down, float* out,
                    const float* colFactor, float df, float rowFactor, int cols) {
    int x = 1;
    for (; x + BLOCK <= cols - 1; x += BLOCK)
        stepCells<SPONGE, BLOCK>(up + x - 1, mid + x - 1, down + x - 1, out + x, colFactor + x, df, rowFactor, BLOCK);
    if (x < cols - 1)
        stepCells<SPONGE, 0>(up + x - 1, mid + x - 1, down + x - 1, out + x, colFactor + x, df, rowFactor, cols - 1 - x);
    out[0] = 0.0f;
    out[cols - 1] = 0.0f;
}

} // namespace

RippleField::RippleField(int rows, int cols, RippleBoundary boundary, int spongeWidth)
    : m_rows(rows), m_cols(cols), m_cells(size_t(rows) * size_t(cols)), m_boundary(boundary) {
    assert(rows >= 1 && cols >= 1);
    m_storage.assign(2 * m_cells, 0.0f);
    m_cur = m_storage.data();
    m_prev = m_storage.data() + m_cells;
    m_rowSponge.assign(size_t(rows), 1.0f);
    m_colSponge.assign(size_t(cols), 1.0f);
    setBoundary(boundary, spongeWidth);
}

// Sponge. Multiplying eq. 2's DF down near the edge does not absorb: a factor s < 1 on the
// whole update gives long waves a cut-off frequency, so they reflect off the band (measured:
// wider bands reflected more). The band instead adds friction on the vertical velocity,
//   Vh(t+1) = ((Buff − Vh(t−1)) − γ·(Vh(t) − Vh(t−1)))·DF,
// with γ = SPONGE_MAX_FRICTION·(1 − s_row·s_col) and, at distance d cells from the outer
// ring (d = 0 is the ring itself), s(d) = sin²(π/2 · d/w) inside a band of width w, 1
// beyond it. γ rises from 0 with zero slope at d = w, so the band starts with no step in
// the medium (a step reflects), and reaches SPONGE_MAX_FRICTION at the ring. Measured with
// a Gaussian bump in a 129² patch (energy coming back to the centre), w = 16 returns about
// 4 % of what a fixed edge reflects, w = 24 about 1.5 %, w = 32 about 0.7 %.
float RippleField::spongeFactor(int d, int w) { return spongeProfile(d, w); }

void RippleField::setBoundary(RippleBoundary boundary, int spongeWidth) {
    m_boundary = boundary;
    m_spongeWidth = 0;
    if (boundary == RippleBoundary::Absorbing)
        m_spongeWidth = std::clamp(spongeWidth, 0, std::min(m_rows, m_cols) / 2);
    rebuildSponge();
}

void RippleField::rebuildSponge() {
    for (int z = 0; z < m_rows; ++z)
        m_rowSponge[size_t(z)] = spongeFactor(std::min(z, m_rows - 1 - z), m_spongeWidth);
    for (int x = 0; x < m_cols; ++x)
        m_colSponge[size_t(x)] = spongeFactor(std::min(x, m_cols - 1 - x), m_spongeWidth);
}

RippleField& RippleField::operator=(const RippleField& o) {
    if (this == &o) return *this;
    m_rows = o.m_rows;
    m_cols = o.m_cols;
    m_cells = o.m_cells;
    m_boundary = o.m_boundary;
    m_spongeWidth = o.m_spongeWidth;
    m_storage = o.m_storage;
    m_cur = m_storage.data() + (o.m_cur - o.m_storage.data());
    m_prev = m_storage.data() + (o.m_prev - o.m_storage.data());
    m_rowSponge = o.m_rowSponge;
    m_colSponge = o.m_colSponge;
    return *this;
}

void RippleField::step(float damping) {
    const int rows = m_rows, cols = m_cols;
    float* const out = m_prev;
    if (rows < 3 || cols < 3) {
        // Every cell is on the outer ring.
        std::fill(out, out + m_cells, 0.0f);
    } else {
        const float* const cur = m_cur;
        const float* const colFactor = m_colSponge.data();
        const float* const rowFactor = m_rowSponge.data();
        const bool sponge = m_spongeWidth > 0;
        // --- interior rows, independent of each other: any split gives the same bits
        auto rowsBody = [=](int z0, int z1) {
            for (int z = z0; z < z1; ++z) {
                const float* mid = cur + size_t(z) * size_t(cols);
                float* o = out + size_t(z) * size_t(cols);
                if (sponge)
                    stepRow<true>(mid - cols, mid, mid + cols, o, colFactor, damping, rowFactor[z], cols);
                else
                    stepRow<false>(mid - cols, mid, mid + cols, o, colFactor, damping, 1.0f, cols);
            }
        };
        const int minChunk = std::max(1, MIN_CELLS_PER_CHUNK / cols);
        parallelFor(1, rows - 1, minChunk, rowsBody);
        // --- outer ring rows held at 0
        std::fill(out, out + cols, 0.0f);
        std::fill(out + size_t(rows - 1) * size_t(cols), out + m_cells, 0.0f);
    }
    // --- rotate levels: Vh(t−1) <- Vh(t), Vh(t) <- Vh(t+1)
    std::swap(m_cur, m_prev);
}

void RippleField::scroll(int dx, int dz) {
    if (dx == 0 && dz == 0) return;
    const int rows = m_rows, cols = m_cols;
    for (float* level : {m_cur, m_prev}) {
        scrollCells(level, rows, cols, glm::ivec2(dx, dz), 0.0f);
        // Outer ring back to 0.
        std::fill(level, level + cols, 0.0f);
        std::fill(level + size_t(rows - 1) * size_t(cols), level + m_cells, 0.0f);
        for (int z = 0; z < rows; ++z) {
            level[size_t(z) * size_t(cols)] = 0.0f;
            level[size_t(z) * size_t(cols) + size_t(cols - 1)] = 0.0f;
        }
    }
}

void RippleField::clear() { std::fill(m_storage.begin(), m_storage.end(), 0.0f); }

} // namespace ob::interaction
