// Batched bounding-sphere stamps: many eq. 5 + eq. 7 footprints applied with the result of
// stampFootprint called for each in list order, each cell written at most once ([Kang2008]
// Table 2, docs/references.md#ripple-layer).
#pragma once
#include "interaction/kang2008/footprint_stamp.h"
#include "interaction/sphere_stamp.h"

#include <cstdint>
#include <vector>

namespace ob::interaction {

/// A list of stamps for one rows × cols field, applied together.
///
/// Why each cell needs one write: stampFootprint OVERWRITES a cell in both levels with values
/// that depend only on that stamp's own inputs (base, PH, SD·SHR·Δ, AF), never on what the
/// cell held. After a list of stamps, a cell therefore holds what the LAST stamp covering it
/// wrote; everything an earlier stamp wrote there is lost. apply() walks the list backwards
/// keeping one "already final" bit per cell, writes only cells no later stamp covers, and
/// stops as soon as every interior cell is final: a swarm of 100,000 spheres of SR 20 over a
/// 128² field is done after the last few hundred stamps. The values are computed with the
/// same float operations in the same order as stampFootprint, so the field gets its bits.
///
/// Where the stamps overlap little, or in short row spans, the walk's per-span bookkeeping
/// costs more than the overwrites it saves, and apply() writes every stamp forward instead,
/// in order: the same bits.
///
/// Cells no stamp reaches never become final, and would keep the walk going to the list's
/// start. When a band has looked at its cell count in spans without writing a cell, it marks
/// them: it dilates the stamp centres by each footprint's shape (row bit masks, shifted and
/// OR-ed), so that only cells some stamp reaches count as open, and the walk stops when those
/// are final.
///
/// Threads: the interior rows are split into bands; each band walks the whole list on its
/// own rows with its own bits, so any split gives the same field.
///
/// Reads between pushes: a sphere's Table 2 step reads Vh(t) at its centre (eq. 5's base at
/// first contact) after every earlier sphere has stamped. currentAt() answers that read from
/// the queued stamps (the last one covering the cell: a short walk back over the newest
/// stamps, then an index of stamps by the tile of their centre, built on first need) or else
/// from the field, so queueing spheres in order and applying once gives exactly the field and
/// contacts of stepSphere called for each in the same order.
///
/// Filling in parallel: grow() reserves slots that threads fill with set(); a first contact's
/// base can be set afterwards, in order, with setBase() from currentAt(…, k) (the value after
/// the first k stamps).
///
/// Allocates only while it grows to its largest list; footprints are referenced, not copied,
/// and must outlive apply() (FootprintCache keeps them). Reads (currentAt) extend the index:
/// one thread at a time.
class StampBatch {
public:
    /// An empty batch for fields of rows × cols cells (both >= 1).
    StampBatch(int rows, int cols);

    /// Queues stampFootprint(field, fp, cx, cz, base, heightScale, af). A stamp whose
    /// footprint misses the interior (it would write nothing) is dropped.
    void push(const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af);

    /// Appends `count` slots for set() and returns the index of the first.
    size_t grow(size_t count);
    /// Fills slot k (see push; a footprint that misses the interior is kept as an empty
    /// stamp). Slots may be filled from several threads, each slot once, before any read.
    void set(size_t k, const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af);
    /// Replaces stamp k's eq. 5 base, m (a first contact's base, read with currentAt(…, k)).
    /// Must come before any read that reaches past stamp k.
    void setBase(size_t k, float base) { m_stamps[k].base = base; }

    /// Vh(t) at column x, row z (in range) of `field` as if the first `k` queued stamps had
    /// been applied in order, m.
    float currentAt(const RippleField& field, int x, int z, size_t k) const;
    /// Vh(t) at (x, z) as if every queued stamp had been applied in order, m.
    float currentAt(const RippleField& field, int x, int z) const { return currentAt(field, x, z, m_stamps.size()); }

    /// Applies every queued stamp to `field` (rows × cols): bit for bit what stampFootprint
    /// for each, in push order, gives. Row bands run on the worker pool. Empties the batch.
    void apply(RippleField& field);

    /// Drops every queued stamp.
    void clear();

    /// Stamps queued.
    size_t size() const { return m_stamps.size(); }
    /// Rows (N, z) of the fields it applies to.
    int rows() const { return m_rows; }
    /// Columns (M, x) of the fields it applies to.
    int cols() const { return m_cols; }

private:
    struct Stamp {
        const FootprintProfile* fp = nullptr;
        int cx = 0, cz = 0;
        int reach = -1;  // rows cz − reach .. cz + reach carry the footprint; −1: writes nothing (and a slot not yet set)
        float base = 0.0f, heightScale = 0.0f, af = 0.0f;
    };
    Stamp makeStamp(const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af) const;
    bool covers(const Stamp& s, int x, int z, float& value) const;
    void indexUpTo(size_t n) const;
    void applyBandForward(RippleField& field, int z0, int z1);
    void applyBandBackward(RippleField& field, int z0, int z1);
    int writeOpenCells(const Stamp& s, int z, float* cur, float* prev, long& visited);
    long closeUnreached(int z0, int z1);
    bool reachableRows(int z0, int z1, std::vector<uint64_t>& out) const;
    int tileOf(int cell, int tiles) const;

    int m_rows, m_cols;
    int m_words;                  // 64-bit coverage words per row
    int m_tilesX, m_tilesZ;       // read index: stamps by the tile of their centre
    std::vector<Stamp> m_stamps;
    // The read index covers stamps [0, m_indexed); built lazily by reads that reach far back.
    mutable size_t m_indexed = 0;
    mutable int m_maxReach = 0;   // largest reach indexed
    mutable std::vector<std::vector<uint32_t>> m_tiles;  // stamp indices, ascending, per tile (row-major)
    std::vector<uint64_t> m_covered;  // rows × m_words bits: the cell's final value is written
    std::vector<int> m_rowLeft;       // interior cells of each row not yet final
};

/// stepSphere with the stamp queued in `batch` instead of written to `field`: the same Table 2
/// decision and contact update, with Vh(t) at the centre read through batch.currentAt. Queueing
/// spheres in order and then batch.apply(field) leaves the field, bit for bit, as stepSphere
/// for each in the same order. Returns true if it queued a stamp.
bool queueSphere(StampBatch& batch, const RippleField& field, FootprintCache& cache, float cellSize,
                 const BoundingSphere& def, SphereContact& contact, const SphereMotion& motion);

} // namespace ob::interaction
