// The foam map's transport: semi-Lagrangian advection and exact decay (law in foam_transport.h).
#include "foam/foam_transport.h"

#include "core/parallel.h"
#include "core/simd.h"
#include "core/thread_choice.h"
#include "foam/foam_flow.h"
#include "foam/foam_sources.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

namespace ob::foam {

namespace {

// Maps from this side on have the sweep's threads measured (smaller ones split as they come).
constexpr int PARALLEL_MIN_RESOLUTION = 256;

// A step's coverage below COVERAGE_FLOOR ends as 0: nothing to see (an 8-bit texture's step is
// 4e-3), and the tails that resampling spreads would otherwise sink into subnormal floats,
// which cost the FPU ~100× a normal operation.
constexpr float COVERAGE_FLOOR = 1e-12f;
inline float floored(float v) { return v > COVERAGE_FLOOR ? v : 0.0f; }

// Coverage of a row-major n×n map at sample (i, j), 0 outside.
inline float cellOr0(const float* f, int n, int i, int j) {
    return (i < 0 || j < 0 || i >= n || j >= n) ? 0.0f : f[size_t(j) * size_t(n) + size_t(i)];
}

// e^(−dt/τ) as a float: the decay of one step.
inline float decayFactor(float decayS, float dt) { return float(std::exp(-double(dt) / double(decayS))); }

// One row of the uniform-flow step: dst[i] = w00·s0[i+ix] + w10·s0[i+ix+1] + w01·s1[i+ix] +
// w11·s1[i+ix+1] for i in [lo, hi), where every index is inside its row.
OB_VECTOR_KERNEL void uniformRowKernel(float* __restrict dst, const float* __restrict s0, const float* __restrict s1,
                                       int lo, int hi, int ix, float w00, float w10, float w01, float w11) {
    for (int i = lo; i < hi; ++i)
        dst[i] = floored(w00 * s0[i + ix] + w10 * s0[i + ix + 1] + w01 * s1[i + ix] + w11 * s1[i + ix + 1]);
}

// Linear interpolation of a row of n values (0 outside) at g (in samples).
inline float lerpRow(const float* row, int n, float g) {
    g = std::clamp(g, -1.0f, float(n));  // beyond: both samples are 0 anyway
    const float g0 = std::floor(g);
    const int x0 = int(g0);
    const float t = g - g0;
    return (1 - t) * cellOr0(row, n, x0, 0) + t * cellOr0(row, n, x0 + 1, 0);
}

// One sample of a pass along an axis: the water moves c samples along it this step; for |c| ≤ 1
// the departure point lies between the sample and its upstream neighbour (before: the one at
// −1 when c > 0, after: at +1 when c < 0): mid + |c|·(upstream − mid).
inline float passCell(float mid, float before, float after, float c) {
    const float upstream = c > 0.0f ? before : after;
    return mid + std::abs(c) * (upstream - mid);
}

// Per-sample flow, pass 1, the samples [lo, hi) of a row (neighbours inside it), c = ux·back.
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

// Pass 2, one row along z from the rows above (j − 1), at and below (j + 1) it, times the decay a
// and the streak cells' gathering (foam_flow.h), at most 1.
OB_VECTOR_KERNEL int zPassKernel(float* __restrict dst, const float* __restrict up, const float* __restrict mid,
                                 const float* __restrict down, const float* __restrict uz, const float* __restrict gather,
                                 int n, float back, float a) {
    int over = 0;
    for (int i = 0; i < n; ++i) {
        const float c = uz[i] * back;
        over |= int(c > 1.0f) | int(c < -1.0f);
        dst[i] = floored(std::min(1.0f, a * (gather[i] * passCell(mid[i], up[i], down[i], c))));
    }
    return over;
}

// The sweep's passes (every |c| ≤ 1), the velocity the lerp of two node rows expanded along x
// (e0, e1) at weight t: pass 1 over the samples [lo, hi) of a row...
OB_VECTOR_KERNEL void xSweepKernel(float* __restrict dst, const float* __restrict src, const float* __restrict e0,
                                   const float* __restrict e1, const float* __restrict wind, float t, int lo, int hi,
                                   float back) {
    for (int i = lo; i < hi; ++i) {
        const float u = e0[i] * (1 - t) + e1[i] * t + wind[i];
        dst[i] = passCell(src[i], src[i - 1], src[i + 1], u * back);
    }
}
// ...and pass 2 over a row, times the decay a (the velocity plus the wind's row).
OB_VECTOR_KERNEL void zSweepKernel(float* __restrict dst, const float* __restrict up, const float* __restrict mid,
                                   const float* __restrict down, const float* __restrict e0, const float* __restrict e1,
                                   const float* __restrict wind, const float* __restrict gather, float t, int n, float back,
                                   float a) {
    for (int i = 0; i < n; ++i) {
        const float u = e0[i] * (1 - t) + e1[i] * t + wind[i];
        dst[i] = floored(std::min(1.0f, a * (gather[i] * passCell(mid[i], up[i], down[i], u * back))));
    }
}

OB_VECTOR_KERNEL void scaleFoamKernel(float* __restrict dst, const float* __restrict src, size_t count, float a) {
    for (size_t i = 0; i < count; ++i) dst[i] = floored(a * src[i]);
}

} // namespace

// One thread or all for the sweep, measured on a map of zeros in still nodes (a sweep of zeros
// costs what any sweep costs and leaves zeros), kept per size.
void FoamTransport::chooseThreads(const ScrollingGrid& grid, int flowResolution, std::vector<float>& zeros) {
    if (grid.n < PARALLEL_MIN_RESOLUTION) return;
    FoamFlow still(grid, flowResolution);
    still.setNodes(std::vector<glm::vec2>(size_t(still.nodesPerSide()) * size_t(still.nodesPerSide()), glm::vec2(0.0f)));
    const std::string size = std::to_string(grid.n) + "x" + std::to_string(grid.n);
    m_sweepThreads = measuredThreads("foam sweep " + size, workerCount(), [&](int threads) {
        m_sweepThreads = threads;
        sweep(zeros, grid, still, nullptr, 1.0f, 1.0f / 60.0f);
    });
}

void FoamTransport::step(std::vector<float>& f, const ScrollingGrid& grid, const FoamFlow& flow, float decayS, float dt) {
    const float a = decayFactor(decayS, dt);
    const int n = grid.n;
    m_next.resize(f.size());
    FoamFlow::Mode mode = flow.mode();
    glm::vec2 uniform = mode == FoamFlow::Mode::Uniform ? flow.uniform() : glm::vec2(0.0f);
    if (mode == FoamFlow::Mode::Still || mode == FoamFlow::Mode::Uniform) {  // with the wind: uniform, or per sample
        if (flow.wind().streaks()) mode = FoamFlow::Mode::Field;
        else if (flow.windy()) uniform += flow.wind().drift, mode = FoamFlow::Mode::Uniform;
        if (mode == FoamFlow::Mode::Uniform && uniform == glm::vec2(0.0f)) mode = FoamFlow::Mode::Still;
    }
    switch (mode) {
    case FoamFlow::Mode::Still:  // decay only
        parallelFor(0, n, ROW_CHUNK, [&](int lo, int hi) {
            scaleFoamKernel(m_next.data() + size_t(lo) * size_t(n), f.data() + size_t(lo) * size_t(n), size_t(hi - lo) * size_t(n), a);
        });
        break;
    case FoamFlow::Mode::Uniform: uniformStep(f, grid, uniform, a, dt); break;
    case FoamFlow::Mode::Nodes:
        if (sweepFits(grid, flow, dt)) return sweep(f, grid, flow, nullptr, decayS, dt);
        [[fallthrough]];
    case FoamFlow::Mode::Field: splitStep(f, grid, flow, a, dt); break;
    }
    f.swap(m_next);
}

// Every sample reads the same 2×2 stencil offset, its weights folded with the decay a.
void FoamTransport::uniformStep(const std::vector<float>& f, const ScrollingGrid& grid, glm::vec2 u, float a, float dt) {
    const int n = grid.n;
    const float* src = f.data();
    float* dst = m_next.data();
    const glm::vec2 o = -u * dt / grid.cell;  // source offset, samples
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
}

// Per-sample velocity, split by axis: along x with u_x into m_split, then along z with u_z (and
// the decay a) into m_next; each pass reads only the previous one, so rows are independent
// within a pass. Rows where the flow crosses more than a sample redo the pass with a general
// linear interpolation (0 from outside).
void FoamTransport::splitStep(const std::vector<float>& f, const ScrollingGrid& grid, const FoamFlow& flow, float a, float dt) {
    const int n = grid.n;
    const float* src = f.data();
    float* dst = m_next.data();
    const float back = dt / grid.cell;  // (m/s) → samples over dt
    const FoamFlow::Mode mode = flow.mode();
    const bool windy = flow.windy();
    // Row j's velocity component: the per-sample arrays' row, or formed from the nodes or the
    // uniform velocity in rowBuf; plus the wind's.
    const auto velocityRow = [&](int j, int component, std::vector<float>& rowBuf, std::vector<float>& scratch) -> const float* {
        const float* field = mode == FoamFlow::Mode::Field ? (component == 0 ? flow.fieldX() : flow.fieldZ()).data() + size_t(j) * size_t(n)
                                                            : nullptr;
        if (field && !windy) return field;
        rowBuf.resize(size_t(n));
        scratch.resize(size_t(std::max(n, flow.nodesPerSide())));
        if (field) std::copy(field, field + n, rowBuf.begin());
        else if (mode == FoamFlow::Mode::Nodes) flow.nodeRow(j, component, rowBuf.data(), scratch.data());
        else std::fill(rowBuf.begin(), rowBuf.end(), mode == FoamFlow::Mode::Uniform ? flow.uniform()[component] : 0.0f);
        if (windy) {
            flow.windRow(j, component, scratch.data());
            for (int i = 0; i < n; ++i) rowBuf[size_t(i)] += scratch[size_t(i)];
        }
        return rowBuf.data();
    };
    m_split.resize(f.size());
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
        std::vector<float> rowBuf, scratch, gather;
        for (int j = rowLo; j < rowHi; ++j) {
            const size_t row = size_t(j) * size_t(n);
            const float* up = j > 0 ? split + row - size_t(n) : m_zeros.data();
            const float* down = j + 1 < n ? split + row + size_t(n) : m_zeros.data();
            const float* u = velocityRow(j, 1, rowBuf, scratch);
            gather.resize(size_t(n));
            flow.windGatherRow(j, dt, gather.data());
            float* d = dst + row;
            if (zPassKernel(d, up, split + row, down, u, gather.data(), n, back, a) == 0) continue;
            for (int i = 0; i < n; ++i) {
                const float g = std::clamp(float(j) - u[i] * back, -1.0f, float(n));
                const float g0 = std::floor(g);
                const int z0 = int(g0);
                const float t = g - g0;
                d[i] = floored(std::min(1.0f, a * (gather[size_t(i)] * ((1 - t) * cellOr0(split, n, i, z0) + t * cellOr0(split, n, i, z0 + 1)))));
            }
        }
    });
}

// The sweep needs every sample's flow within a sample a step (its departure point between the
// sample and a neighbour); a sample's velocity is a convex combination of nodes', so the nodes'
// bound holds for it (the margin covers the rounding of the combination).
bool FoamTransport::sweepFits(const ScrollingGrid& grid, const FoamFlow& flow, float dt) const {
    return flow.mode() == FoamFlow::Mode::Nodes && (flow.nodesMax() + flow.windMax()) * (dt / grid.cell) <= 0.999f;
}

// The node rows along x, [l][component][sample].
void FoamTransport::expandNodeRows(const ScrollingGrid& grid, const FoamFlow& flow, int threads) {
    const int m = flow.nodesPerSide();
    const size_t row = size_t(grid.n);
    m_nodeRows.resize(size_t(m) * 2 * row);
    parallelFor(0, m, threads > 1 ? 8 : m, [&](int lo, int hi) {
        std::vector<float> scratch(static_cast<size_t>(m));
        for (int l = lo; l < hi; ++l)
            for (int c = 0; c < 2; ++c) flow.expandNodeRow(l, c, &m_nodeRows[(size_t(l) * 2 + size_t(c)) * row], scratch.data());
    });
}

// A chunk of rows [lo, hi) keeps the x pass of rows j − 1, j, j + 1 and writes the z pass of row
// j over row j, whose coverage it no longer needs; the rows around a chunk are read from copies
// taken before (the neighbour chunks overwrite them), so every row's result is the same for any
// split. A row's velocity is bilinear between the nodes: their rows expanded along x first
// (m_nodeRows), then the lerp of the two around it along z.
void FoamTransport::sweep(std::vector<float>& f, const ScrollingGrid& grid, const FoamFlow& flow, const RowSources* s,
                          float decayS, float dt) {
    assert(sweepFits(grid, flow, dt));
    const float a = decayFactor(decayS, dt);
    const int n = grid.n;
    const float back = dt / grid.cell;  // (m/s) → samples over dt
    const size_t row = size_t(n);
    const int threads = std::min(workerCount(), m_sweepThreads);
    expandNodeRows(grid, flow, threads);
    const auto nodeRows = [&](int r, int component, const float*& e0, const float*& e1) {
        int l = 0;
        const float t = flow.nodeRowWeight(r, l);
        e0 = &m_nodeRows[(size_t(l) * 2 + size_t(component)) * row];
        e1 = e0 + 2 * row;  // node row l + 1
        return t;
    };

    // --- the chunks and copies of the rows around them
    const int chunks = std::clamp(threads, 1, std::max(1, n / ROW_CHUNK));
    const auto chunkStart = [&](int c) { return int(int64_t(n) * c / chunks); };
    m_halo.resize(size_t(chunks) * 2 * row);
    for (int c = 1; c < chunks; ++c)  // rows b − 1 and b around boundary b
        std::memcpy(&m_halo[size_t(c) * 2 * row], &f[size_t(chunkStart(c) - 1) * row], 2 * row * sizeof(float));

    parallelFor(0, chunks, 1, [&](int cLo, int cHi) {
        std::vector<float> ring(3 * row), sourced(row), windX(row, 0.0f), windZ(row, 0.0f), gather(row, 1.0f);
        const bool windy = flow.windy();
        std::optional<RowSources::Rows> rows;
        if (s) rows.emplace(*s);
        for (int c = cLo; c < cHi; ++c) {
            const int lo = chunkStart(c), hi = chunkStart(c + 1);
            // Row r's coverage before the step (the copies for the rows around the chunk).
            const auto coverage = [&](int r) -> const float* {
                if (r == lo - 1) return &m_halo[size_t(c) * 2 * row];
                if (r == hi && c + 1 < chunks) return &m_halo[size_t(c + 1) * 2 * row + row];
                return f.data() + size_t(r) * row;
            };
            // Row r's coverage with its sources, moved along x with u_x (0 outside the map).
            const auto xRow = [&](int r, float* out) {
                if (r < 0 || r >= n) return std::fill(out, out + n, 0.0f);
                const float* in = coverage(r);
                if (rows && rows->add(r, in, sourced.data())) in = sourced.data();
                const float *e0, *e1;
                const float t = nodeRows(r, 0, e0, e1);
                if (windy) flow.windRow(r, 0, windX.data());
                xSweepKernel(out, in, e0, e1, windX.data(), t, 1, n - 1, back);
                for (int i : {0, n - 1}) {  // a neighbour is outside: 0
                    const float u = e0[i] * (1 - t) + e1[i] * t + windX[size_t(i)];
                    out[i] = passCell(in[i], i > 0 ? in[i - 1] : 0.0f, i + 1 < n ? in[i + 1] : 0.0f, u * back);
                }
            };
            float *up = ring.data(), *mid = up + n, *down = mid + n;
            xRow(lo - 1, up);
            xRow(lo, mid);
            for (int j = lo; j < hi; ++j) {
                xRow(j + 1, down);
                const float *e0, *e1;
                const float t = nodeRows(j, 1, e0, e1);
                if (windy) flow.windRow(j, 1, windZ.data());
                if (flow.wind().streaks()) flow.windGatherRow(j, dt, gather.data());
                zSweepKernel(f.data() + size_t(j) * row, up, mid, down, e0, e1, windZ.data(), gather.data(), t, n, back, a);
                std::swap(up, mid), std::swap(mid, down);
            }
        }
    });
}

} // namespace ob::foam
