// Batched bounding-sphere stamps (seed 001 eq. 5, 7 and Table 2; SPEC §2.5): the list is
// applied backwards, each cell written once by the last stamp that covers it.
#include "interaction/stamp_batch.h"

#include "core/parallel.h"
#include "core/simd.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>

namespace ob::interaction {

namespace {

// Side of the query index's tiles, cells. A read looks at the tiles within the largest
// queued reach of its cell: 3–4 per axis for SR 20.
constexpr int TILE = 16;

// A band of rows is worth a worker when it holds at least this many cells of work (as for
// RippleField::step: below it, waking a worker costs more than it saves).
constexpr size_t MIN_CELLS_PER_BAND = 32768;

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

void StampBatch::push(const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af) {
    if (fp.rows.empty()) return;
    const int reach = int(fp.rows.size() / 2);  // rows dz = −reach .. reach; the dz = 0 row is the widest, ±reach
    // The interior is rows [1, rows − 2] × columns [1, cols − 2]; outside its bounding box a
    // stamp writes nothing. (Centres are clamped to ±1e9 by the callers: no overflow.)
    if (cz + reach < 1 || cz - reach > m_rows - 2 || cx + reach < 1 || cx - reach > m_cols - 2) return;
    const uint32_t index = uint32_t(m_stamps.size());
    m_stamps.push_back({&fp, cx, cz, reach, base, heightScale, af});
    m_maxReach = std::max(m_maxReach, reach);
    m_tiles[size_t(tileOf(cz, m_tilesZ)) * size_t(m_tilesX) + size_t(tileOf(cx, m_tilesX))].push_back(index);
}

float StampBatch::currentAt(const RippleField& field, int x, int z) const {
    assert(field.rows() == m_rows && field.cols() == m_cols && x >= 0 && x < m_cols && z >= 0 && z < m_rows);
    // Stamps never write the outer ring.
    if (m_stamps.empty() || x < 1 || z < 1 || x > m_cols - 2 || z > m_rows - 2) return field.currentAt(x, z);
    // A stamp covering (x, z) has its centre within m_maxReach of it, so in one of these tiles
    // (a centre off the field is filed under the nearest edge tile, which the clamped range
    // still includes).
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
            if (!list.empty()) c[n++] = {list.data(), long(list.size()) - 1};
        }
    for (;;) {
        int best = -1;
        uint32_t bestIndex = 0;
        for (int k = 0; k < n; ++k)
            if (c[k].at >= 0 && (best < 0 || c[k].list[c[k].at] > bestIndex)) {
                best = k;
                bestIndex = c[k].list[c[k].at];
            }
        if (best < 0) return field.currentAt(x, z);
        --c[best].at;
        const Stamp& s = m_stamps[bestIndex];
        const int dz = z - s.cz;
        if (dz < -s.reach || dz > s.reach) continue;
        const FootprintRow& r = s.fp->rows[size_t(dz + s.reach)];
        const int i = x - (s.cx + r.dx0);
        if (i < 0 || i >= r.count) continue;
        return s.base + s.fp->ph[size_t(r.offset + i)] * s.heightScale;  // eq. 5, as stampFootprint writes it
    }
}

void StampBatch::apply(RippleField& field) {
    assert(field.rows() == m_rows && field.cols() == m_cols);
    if (!m_stamps.empty() && m_rows >= 3 && m_cols >= 3) {
        // Work: the cells the stamps cover, but no more than a few passes over the interior
        // (past that, later stamps have made the field final and the walk stops).
        size_t queued = 0;
        for (const Stamp& s : m_stamps) queued += s.fp->ph.size();
        const int interiorRows = m_rows - 2;
        const size_t interior = size_t(interiorRows) * size_t(m_cols - 2);
        const size_t work = std::max<size_t>(1, std::min(queued, 4 * interior));
        const size_t perRow = std::max<size_t>(1, work / size_t(interiorRows));
        const int minRows = int(std::min<size_t>(size_t(interiorRows), (MIN_CELLS_PER_BAND + perRow - 1) / perRow));
        parallelFor(1, m_rows - 1, std::max(1, minRows), [&](int z0, int z1) { applyBand(field, z0, z1); });
    }
    clear();
}

void StampBatch::applyBand(RippleField& field, int z0, int z1) {
    const int cols = m_cols, words = m_words;
    float* const cur = field.current().data();
    float* const prev = field.previous().data();
    std::fill(m_covered.begin() + long(z0) * words, m_covered.begin() + long(z1) * words, 0);
    std::fill(m_rowLeft.begin() + z0, m_rowLeft.begin() + z1, cols - 2);
    long left = long(z1 - z0) * long(cols - 2);

    // --- newest stamp first; a cell is written by the first stamp that reaches it
    for (size_t k = m_stamps.size(); k-- > 0 && left > 0;) {
        const Stamp& s = m_stamps[k];
        const int za = std::max(s.cz - s.reach, z0), zb = std::min(s.cz + s.reach + 1, z1);
        for (int z = za; z < zb; ++z) {
            if (m_rowLeft[size_t(z)] == 0) continue;
            const FootprintRow& r = s.fp->rows[size_t(z - s.cz + s.reach)];
            const int x0 = s.cx + r.dx0;
            const int a = std::max(x0, 1), b = std::min(x0 + r.count, cols - 1);
            if (a >= b) continue;
            uint64_t* bits = m_covered.data() + size_t(z) * size_t(words);
            const float* ph = s.fp->ph.data() + r.offset;  // PH of column x at ph[x − x0]
            float* curRow = cur + size_t(z) * size_t(cols);
            float* prevRow = prev + size_t(z) * size_t(cols);
            // Runs of cells not yet final, merged across words, each written in one call.
            int runStart = 0, runEnd = 0, written = 0;
            const auto flush = [&] {
                if (runEnd > runStart)
                    writeRun(curRow + runStart, prevRow + runStart, ph + (runStart - x0), runEnd - runStart, s.base,
                             s.heightScale, s.af);
            };
            for (int w = a >> 6; w <= (b - 1) >> 6; ++w) {
                const int lo = std::max(a, w << 6), hi = std::min(b, (w + 1) << 6);
                const uint64_t mask = bitRange(lo - (w << 6), hi - (w << 6));
                uint64_t free = mask & ~bits[w];
                if (!free) continue;
                bits[w] |= mask;
                written += std::popcount(free);
                while (free) {
                    const int first = std::countr_zero(free);
                    const uint64_t rest = ~(free >> first);  // ones from the first covered bit up
                    const int len = std::countr_zero(rest);  // rest != 0: the shift brought in zeros
                    const int start = (w << 6) + first;
                    if (start == runEnd) {
                        runEnd = start + len;
                    } else {
                        flush();
                        runStart = start;
                        runEnd = start + len;
                    }
                    free &= len == 64 ? 0 : ~(((uint64_t(1) << len) - 1) << first);
                }
            }
            flush();
            m_rowLeft[size_t(z)] -= written;
            left -= written;
        }
    }
}

void StampBatch::clear() {
    if (m_stamps.empty()) return;
    m_stamps.clear();
    for (auto& t : m_tiles) t.clear();
    m_maxReach = 0;
}

bool queueSphere(StampBatch& batch, const RippleField& field, FootprintCache& cache, float cellSize,
                 const BoundingSphere& def, SphereContact& contact, const SphereMotion& m) {
    assert(cellSize > 0.0f && def.radius > 0.0f);
    // stepSphere (sphere_stamp.cpp) step for step, with the read of Vh(t) through the batch.
    const int cx = int(std::clamp(std::floor(m.gridX + 0.5f), -1.0e9f, 1.0e9f));
    const int cz = int(std::clamp(std::floor(m.gridZ + 0.5f), -1.0e9f, 1.0e9f));
    const bool inside = cx >= 0 && cx < field.cols() && cz >= 0 && cz < field.rows();
    // The read only matters at first contact; it is cheap either way but not free.
    const bool mayTouch = contact.phase != ContactPhase::Contact;
    const float ripple = inside && mayTouch ? batch.currentAt(field, cx, cz) : 0.0f;
    if (!updateContact(contact, m.centreY, def.radius, m.surfaceY, ripple)) return false;

    float sd = float(int(def.direction));
    if (def.direction == SphereDirection::Auto) sd = m.verticalVelocity > 0.0f ? 1.0f : -1.0f;
    const float af = def.afFromMotion ? accelerationFactor(m.mass, m.speed, def.radius, def.reference.weight,
                                                           def.reference.speed, def.reference.size)
                                      : def.accelerationFactor;
    const FootprintProfile& fp = cache.get(def.radius / cellSize);
    batch.push(fp, cx, cz, contact.baseRipple, sd * def.heightRatio * cellSize, af);
    return true;
}

} // namespace ob::interaction
