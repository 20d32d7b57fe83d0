// Batched bounding-sphere stamps ([Kang2008] eq. 5, 7 and Table 2; docs/references.md#ripple-layer): the list is
// applied backwards, each cell written once by the last stamp that covers it.
#include "interaction/kang2008/stamp_batch.h"

#include "core/parallel.h"
#include "core/simd.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>

namespace ob::interaction {

namespace {

// Side of the read index's tiles, cells. A read looks at the tiles within the largest
// queued reach of its cell: 3–4 per axis for SR 20.
constexpr int TILE = 16;

// A read first walks back over this many newest stamps. In a crowd (100,000 spheres of SR 20
// over 128² cells, each covering 8 % of the field, 2 % of a corner cell's surroundings) one of
// them covers the cell after a dozen, or a few hundred at the corners, and the index is never
// built; a sparse field falls through to the index.
constexpr size_t RECENT_SCAN = 1024;

// The list is applied backwards when its newest stamps cover the interior many times over in
// long spans: the walk pays per row span, forward writing per cell. Backward when overlap ×
// mean span length (cells) reaches BACKWARD_SPAN_PASSES, and overlap is at least 2. Measured
// on 128² cells (2-core EPYC): 110 stamps of SR 20 (8.6 times over, 32-cell spans) take 0.030
// ms backward, 0.050 forward; 1,000 of SR 7 (9 times over, 11-cell spans) 0.117 backward,
// 0.088 forward; 37,000 of SR 20 (2,900 times over) 45 ms forward, 0.1 backward.
constexpr double BACKWARD_SPAN_PASSES = 200.0;
constexpr size_t OVERLAP_SCAN = 16;  // overlap counted up to this many passes
// Cells no stamp reaches are looked for with at most this many distinct footprints.
constexpr int MAX_REACH_FOOTPRINTS = 16;
// Runs shorter than this are written inline; longer ones through the vector kernel.
constexpr int SHORT_RUN = 12;

// A band of rows is worth a worker when it holds at least this many cells of work: below it,
// waking a worker costs more than it saves (more so on a busy machine, where the worker may
// wait for a core: 1,000 stamps of SR 5 took 0.10 ms split, 0.04 ms inline, at load 6).
constexpr size_t MIN_CELLS_PER_BAND = 131072;

// Eq. 5 then eq. 7 on n consecutive cells: the loop of stampFootprint, same operations in
// the same order, so each cell gets the same bits.
OB_VECTOR_KERNEL void writeRun(float* __restrict cur, float* __restrict prev, const float* __restrict ph, int n,
                               float base, float heightScale, float af) {
    for (int i = 0; i < n; ++i) {
        const float v = base + ph[i] * heightScale;  // eq. 5
        cur[i] = v;
        prev[i] = v - v * af;                        // eq. 7
    }
}

// writeRun, with short runs inline (a call through the kernel's dispatcher costs more).
inline void writeCells(float* __restrict cur, float* __restrict prev, const float* __restrict ph, int n, float base,
                       float heightScale, float af) {
    if (n >= SHORT_RUN) {
        writeRun(cur, prev, ph, n, base, heightScale, af);
        return;
    }
    for (int i = 0; i < n; ++i) {
        const float v = base + ph[i] * heightScale;
        cur[i] = v;
        prev[i] = v - v * af;
    }
}

// Bits [lo, hi) of a word, 0 <= lo < hi <= 64.
inline uint64_t bitRange(int lo, int hi) {
    const uint64_t upTo = hi == 64 ? ~uint64_t(0) : (uint64_t(1) << hi) - 1;
    return upTo & ~((uint64_t(1) << lo) - 1);
}

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

} // namespace

StampBatch::StampBatch(int rows, int cols)
    : m_rows(rows), m_cols(cols), m_words((cols + 63) / 64), m_tilesX((cols + TILE - 1) / TILE),
      m_tilesZ((rows + TILE - 1) / TILE) {
    assert(rows >= 1 && cols >= 1);
    m_tiles.resize(size_t(m_tilesX) * size_t(m_tilesZ));
    m_covered.assign(size_t(rows) * size_t(m_words), 0);
    m_rowLeft.assign(size_t(rows), 0);
}

int StampBatch::tileOf(int cell, int tiles) const { return std::clamp(floorDiv(cell, TILE), 0, tiles - 1); }

StampBatch::Stamp StampBatch::makeStamp(const FootprintProfile& fp, int cx, int cz, float base, float heightScale,
                                        float af) const {
    // Rows dz = −reach .. reach; the dz = 0 row is the widest, ±reach. The interior is rows
    // [1, rows − 2] × columns [1, cols − 2]; outside its bounding box a stamp writes nothing.
    // (Callers clamp centres to ±1e9: no overflow.)
    int reach = int(fp.rows.size() / 2);
    if (fp.rows.empty() || cz + reach < 1 || cz - reach > m_rows - 2 || cx + reach < 1 || cx - reach > m_cols - 2)
        reach = -1;
    return {&fp, cx, cz, reach, base, heightScale, af};
}

void StampBatch::push(const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af) {
    const Stamp s = makeStamp(fp, cx, cz, base, heightScale, af);
    if (s.reach >= 0) m_stamps.push_back(s);
}

size_t StampBatch::grow(size_t count) {
    const size_t first = m_stamps.size();
    m_stamps.resize(first + count);
    return first;
}

void StampBatch::set(size_t k, const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af) {
    assert(k < m_stamps.size() && k >= m_indexed);
    m_stamps[k] = makeStamp(fp, cx, cz, base, heightScale, af);
}

// Whether stamp s writes interior cell (x, z), and the Vh(t) it writes there.
bool StampBatch::covers(const Stamp& s, int x, int z, float& value) const {
    const int dz = z - s.cz;
    if (dz < -s.reach || dz > s.reach) return false;  // also every empty stamp (reach −1)
    const FootprintRow& r = s.fp->rows[size_t(dz + s.reach)];
    const int i = x - (s.cx + r.dx0);
    if (i < 0 || i >= r.count) return false;
    value = s.base + s.fp->ph[size_t(r.offset + i)] * s.heightScale;  // eq. 5, as stampFootprint writes it
    return true;
}

void StampBatch::indexUpTo(size_t n) const {
    for (; m_indexed < n; ++m_indexed) {
        const Stamp& s = m_stamps[m_indexed];
        if (s.reach < 0) continue;
        m_maxReach = std::max(m_maxReach, s.reach);
        m_tiles[size_t(tileOf(s.cz, m_tilesZ)) * size_t(m_tilesX) + size_t(tileOf(s.cx, m_tilesX))].push_back(
            uint32_t(m_indexed));
    }
}

float StampBatch::currentAt(const RippleField& field, int x, int z, size_t k) const {
    assert(field.rows() == m_rows && field.cols() == m_cols && x >= 0 && x < m_cols && z >= 0 && z < m_rows);
    assert(k <= m_stamps.size());
    // Stamps never write the outer ring.
    if (k == 0 || x < 1 || z < 1 || x > m_cols - 2 || z > m_rows - 2) return field.currentAt(x, z);
    // --- the newest stamps first: in a crowd one of them usually covers the cell
    float value;
    const size_t near = k > RECENT_SCAN ? k - RECENT_SCAN : 0;
    for (size_t j = k; j-- > near;)
        if (covers(m_stamps[j], x, z, value)) return value;
    if (near == 0) return field.currentAt(x, z);

    // --- then every older stamp, through the index. A stamp covering (x, z) has its centre
    // within m_maxReach of it, so in one of these tiles (a centre off the field is filed under
    // the nearest edge tile, which the clamped range still includes).
    indexUpTo(std::max(m_indexed, near));
    const int tx0 = tileOf(x - m_maxReach, m_tilesX), tx1 = tileOf(x + m_maxReach, m_tilesX);
    const int tz0 = tileOf(z - m_maxReach, m_tilesZ), tz1 = tileOf(z + m_maxReach, m_tilesZ);
    // Walk the tiles' lists together from their ends, newest stamp first: the first that covers
    // the cell is the last one that wrote it.
    struct Cursor {
        const uint32_t* list;
        long at;  // index into list of the next candidate, −1 when done
    };
    Cursor cursors[64];
    std::vector<Cursor> many;
    Cursor* c = cursors;
    const size_t count = size_t(tx1 - tx0 + 1) * size_t(tz1 - tz0 + 1);
    if (count > std::size(cursors)) {
        many.resize(count);
        c = many.data();
    }
    int n = 0;
    for (int tz = tz0; tz <= tz1; ++tz)
        for (int tx = tx0; tx <= tx1; ++tx) {
            const std::vector<uint32_t>& list = m_tiles[size_t(tz) * size_t(m_tilesX) + size_t(tx)];
            long at = long(list.size()) - 1;
            while (at >= 0 && list[size_t(at)] >= near) --at;  // walked above, or not yet reached
            if (at >= 0) c[n++] = {list.data(), at};
        }
    for (;;) {
        int best = -1;
        uint32_t bestIndex = 0;
        for (int i = 0; i < n; ++i)
            if (c[i].at >= 0 && (best < 0 || c[i].list[c[i].at] > bestIndex)) {
                best = i;
                bestIndex = c[i].list[c[i].at];
            }
        if (best < 0) return field.currentAt(x, z);
        --c[best].at;
        if (covers(m_stamps[bestIndex], x, z, value)) return value;
    }
}

void StampBatch::apply(RippleField& field) {
    assert(field.rows() == m_rows && field.cols() == m_cols);
    if (!m_stamps.empty() && m_rows >= 3 && m_cols >= 3) {
        // Overlap: the cells the newest stamps cover, counted up to a few passes over the
        // interior. Light overlap: write every stamp forward, in order (the walk's bookkeeping
        // would cost more than the overwrites it saves); heavy: walk backwards.
        const int interiorRows = m_rows - 2;
        const size_t interior = size_t(interiorRows) * size_t(m_cols - 2);
        size_t work = 0, spans = 0;
        for (size_t k = m_stamps.size(); k-- > 0 && work < OVERLAP_SCAN * interior;)
            if (m_stamps[k].reach >= 0) {
                work += m_stamps[k].fp->ph.size();
                spans += m_stamps[k].fp->rows.size();
            }
        const double overlap = double(work) / double(interior);
        const bool backward = overlap >= 2.0 && overlap * double(work) / double(std::max<size_t>(spans, 1)) >= BACKWARD_SPAN_PASSES;
        work = std::max<size_t>(1, work);
        const size_t perRow = std::max<size_t>(1, work / size_t(interiorRows));
        const int minRows = int(std::min<size_t>(size_t(interiorRows), (MIN_CELLS_PER_BAND + perRow - 1) / perRow));
        parallelFor(1, m_rows - 1, std::max(1, minRows), [&](int z0, int z1) {
            if (backward) applyBandBackward(field, z0, z1);
            else applyBandForward(field, z0, z1);
        });
    }
    clear();
}

void StampBatch::applyBandForward(RippleField& field, int z0, int z1) {
    const int cols = m_cols;
    float* const cur = field.current().data();
    float* const prev = field.previous().data();
    for (const Stamp& s : m_stamps) {
        const int za = std::max(s.cz - s.reach, z0), zb = std::min(s.cz + s.reach + 1, z1);
        for (int z = za; z < zb; ++z) {
            const FootprintRow& r = s.fp->rows[size_t(z - s.cz + s.reach)];
            const int x0 = s.cx + r.dx0;
            const int a = std::max(x0, 1), b = std::min(x0 + r.count, cols - 1);
            if (a >= b) continue;
            const size_t row = size_t(z) * size_t(cols);
            writeCells(cur + row + a, prev + row + a, s.fp->ph.data() + r.offset + (a - x0), b - a, s.base, s.heightScale, s.af);
        }
    }
}

// Writes the cells of row z that stamp s reaches and no newer stamp has written, in runs merged
// across the coverage words, each in one go, and marks them final. Returns how many it wrote;
// `visited` grows by the cells it looked at.
int StampBatch::writeOpenCells(const Stamp& s, int z, float* cur, float* prev, long& visited) {
    const int cols = m_cols;
    const FootprintRow& r = s.fp->rows[size_t(z - s.cz + s.reach)];
    const int x0 = s.cx + r.dx0;
    const int a = std::max(x0, 1), b = std::min(x0 + r.count, cols - 1);
    if (a >= b) return 0;
    visited += b - a;
    uint64_t* bits = m_covered.data() + size_t(z) * size_t(m_words);
    const float* ph = s.fp->ph.data() + r.offset;  // PH of column x at ph[x − x0]
    float* curRow = cur + size_t(z) * size_t(cols);
    float* prevRow = prev + size_t(z) * size_t(cols);
    int runStart = 0, runEnd = 0, written = 0;
    const auto flush = [&] {
        if (runEnd > runStart)
            writeCells(curRow + runStart, prevRow + runStart, ph + (runStart - x0), runEnd - runStart, s.base, s.heightScale, s.af);
    };
    for (int w = a >> 6; w <= (b - 1) >> 6; ++w) {
        const int lo = std::max(a, w << 6), hi = std::min(b, (w + 1) << 6);
        const uint64_t mask = bitRange(lo - (w << 6), hi - (w << 6));
        uint64_t free = mask & ~bits[w];
        if (!free) continue;
        bits[w] |= mask;
        while (free) {
            const int first = std::countr_zero(free);
            const uint64_t rest = ~(free >> first);  // ones from the first covered bit up
            const int len = std::countr_zero(rest);  // rest != 0: the shift brought in zeros
            const int start = (w << 6) + first;
            written += len;
            if (start != runEnd) {
                flush();
                runStart = start;
            }
            runEnd = start + len;
            free &= len == 64 ? 0 : ~(((uint64_t(1) << len) - 1) << first);
        }
    }
    flush();
    return written;
}

// Closes the cells of rows [z0, z1) that no stamp reaches (reachableRows) and returns how many
// interior cells stay open; −1 (nothing closed) when the reach was not worth computing.
long StampBatch::closeUnreached(int z0, int z1) {
    const int cols = m_cols, words = m_words;
    thread_local std::vector<uint64_t> reach;
    if (!reachableRows(z0, z1, reach)) return -1;
    long left = 0;
    for (int z = z0; z < z1; ++z) {
        uint64_t* bits = m_covered.data() + size_t(z) * size_t(words);
        const uint64_t* in = reach.data() + size_t(z - z0) * size_t(words);
        int open = 0;
        for (int w = 0; w < words; ++w) {
            const int lo = std::max(1, w << 6), hi = std::min(cols - 1, (w + 1) << 6);
            const uint64_t interior = lo < hi ? bitRange(lo - (w << 6), hi - (w << 6)) : 0;
            open += std::popcount(in[w] & ~bits[w] & interior);
            bits[w] |= ~in[w];
        }
        m_rowLeft[size_t(z)] = open;
        left += open;
    }
    return left;
}

void StampBatch::applyBandBackward(RippleField& field, int z0, int z1) {
    float* const cur = field.current().data();
    float* const prev = field.previous().data();
    std::fill(m_covered.begin() + long(z0) * m_words, m_covered.begin() + long(z1) * m_words, 0);
    std::fill(m_rowLeft.begin() + z0, m_rowLeft.begin() + z1, m_cols - 2);
    const long bandCells = long(z1 - z0) * long(m_cols - 2);
    long left = bandCells;
    // Stagnation: cells looked at and written since the last check, one check per band's worth.
    long visited = 0, writtenSince = 0;
    bool reachTried = false;

    // --- newest stamp first; a cell is written by the first stamp that reaches it
    for (size_t k = m_stamps.size(); k-- > 0 && left > 0;) {
        const Stamp& s = m_stamps[k];
        const int za = std::max(s.cz - s.reach, z0), zb = std::min(s.cz + s.reach + 1, z1);
        for (int z = za; z < zb; ++z) {
            if (m_rowLeft[size_t(z)] == 0) continue;
            const int written = writeOpenCells(s, z, cur, prev, visited);
            m_rowLeft[size_t(z)] -= written;
            left -= written;
            writtenSince += written;
        }
        if (visited < bandCells) continue;
        // --- a band's worth of cells looked at and none written: the open cells may be ones no
        // stamp reaches; close those, once
        const bool stalled = writtenSince == 0;
        visited = 0;
        writtenSince = 0;
        if (!stalled || reachTried || left == 0) continue;
        reachTried = true;
        if (const long open = closeUnreached(z0, z1); open >= 0) left = open;
    }
}

// Bit masks of the cells of rows [z0, z1) that some stamp reaches (m_words per row, bit x of a
// row = column x). Per footprint, the stamp centres are set in row masks, and a target row is
// the OR over dz of the centre row z − dz dilated by that footprint row's half-width. False
// (nothing computed) when the stamps use more footprints than are worth it.
bool StampBatch::reachableRows(int z0, int z1, std::vector<uint64_t>& out) const {
    struct Group {
        const FootprintProfile* fp;
        int reach, words;  // centre rows z0 − reach .. z1 + reach, `words` each
        size_t offset;     // first word of its centre masks in `centres`
    };
    Group groups[MAX_REACH_FOOTPRINTS];
    int groupCount = 0;
    for (const Stamp& s : m_stamps) {
        if (s.reach < 0) continue;
        bool known = false;
        for (int g = 0; g < groupCount && !known; ++g) known = groups[g].fp == s.fp;
        if (known) continue;
        if (groupCount == MAX_REACH_FOOTPRINTS) return false;
        groups[groupCount++] = {s.fp, s.reach, 0, 0};
    }
    thread_local std::vector<uint64_t> centres, dilated;
    size_t total = 0;
    for (int g = 0; g < groupCount; ++g) {
        // Bit i of a centre row is column i − reach; dilating by up to 2·reach moves it up.
        groups[g].words = (m_cols + 4 * groups[g].reach + 63) / 64 + 1;
        groups[g].offset = total;
        total += size_t(z1 - z0 + 2 * groups[g].reach) * size_t(groups[g].words);
    }
    centres.assign(total, 0);
    int g = 0;
    for (const Stamp& s : m_stamps) {
        if (s.reach < 0) continue;
        if (groups[g].fp != s.fp)
            for (g = 0; groups[g].fp != s.fp; ++g) {
            }
        const Group& gr = groups[g];
        const int row = s.cz - (z0 - gr.reach);
        if (row < 0 || row >= z1 - z0 + 2 * gr.reach) continue;
        const int bit = s.cx + gr.reach;  // in [1, cols − 2 + 2·reach]: the stamp reaches the interior
        centres[gr.offset + size_t(row) * size_t(gr.words) + size_t(bit >> 6)] |= uint64_t(1) << (bit & 63);
    }

    const int words = m_words;
    out.assign(size_t(z1 - z0) * size_t(words), 0);
    for (g = 0; g < groupCount; ++g) {
        const Group& gr = groups[g];
        dilated.resize(size_t(gr.words));
        for (int z = z0; z < z1; ++z) {
            uint64_t* target = out.data() + size_t(z - z0) * size_t(words);
            for (int dz = -gr.reach; dz <= gr.reach; ++dz) {
                // Centre row z − dz, at index (z − dz) − (z0 − reach).
                const uint64_t* src = centres.data() + gr.offset + size_t(z - dz - z0 + gr.reach) * size_t(gr.words);
                bool any = false;
                for (int w = 0; w < gr.words && !any; ++w) any = src[w] != 0;
                if (!any) continue;
                // OR of the row shifted up by 0 .. 2h bits, by doubling: bit j is set when a
                // centre lies in columns j − reach − 2h .. j − reach, so column x is reached
                // when bit x + reach + h is.
                const int h = -gr.fp->rows[size_t(dz + gr.reach)].dx0;
                std::copy(src, src + gr.words, dilated.begin());
                for (int have = 1; have < 2 * h + 1;) {
                    const int shift = std::min(have, 2 * h + 1 - have);
                    const int q = shift >> 6, b = shift & 63;
                    for (int w = gr.words - 1; w >= q; --w) {
                        uint64_t v = dilated[size_t(w - q)] << b;
                        if (b && w - q - 1 >= 0) v |= dilated[size_t(w - q - 1)] >> (64 - b);
                        dilated[size_t(w)] |= v;
                    }
                    have += shift;
                }
                const int offset = gr.reach + h, q = offset >> 6, b = offset & 63;
                for (int w = 0; w < words; ++w) {
                    uint64_t v = dilated[size_t(w + q)] >> b;
                    if (b && w + q + 1 < gr.words) v |= dilated[size_t(w + q + 1)] << (64 - b);
                    target[w] |= v;
                }
            }
        }
    }
    return true;
}

void StampBatch::clear() {
    m_stamps.clear();
    if (m_indexed > 0)
        for (auto& t : m_tiles) t.clear();
    m_indexed = 0;
    m_maxReach = 0;
}

bool queueSphere(StampBatch& batch, const RippleField& field, FootprintCache& cache, float cellSize,
                 const BoundingSphere& def, SphereContact& contact, const SphereMotion& m) {
    assert(cellSize > 0.0f && def.radius > 0.0f);
    // stepSphere's decision, with the read of Vh(t) through the batch.
    RippleStamp st;
    if (!planStamp(field.rows(), field.cols(), cellSize, def, contact, m,
                   [&](int x, int z) { return batch.currentAt(field, x, z); }, st))
        return false;
    batch.push(cache.get(st.radiusCells), st.cx, st.cz, st.base, st.heightScale, st.accelerationFactor);
    return true;
}

} // namespace ob::interaction
