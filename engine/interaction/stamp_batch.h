// Batched bounding-sphere stamps: many eq. 5 + eq. 7 footprints applied with the result of
// stampFootprint called for each in list order, each cell written at most once (seed 001
// Table 2, SPEC §2.5).
#pragma once
#include "interaction/ripple_field.h"
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
/// Threads: the interior rows are split into bands; each band walks the whole list on its
/// own rows with its own bits, so any split gives the same field.
///
/// Reads between pushes: a sphere's Table 2 step reads Vh(t) at its centre (eq. 5's base at
/// first contact) after every earlier sphere has stamped. currentAt() answers that read from
/// the queued stamps (the last one covering the cell, through an index of stamps by the tile
/// of their centre) or else from the field, so queueing spheres in order and applying once
/// gives exactly the field and contacts of stepSphere called for each in the same order.
///
/// Allocates only while it grows to its largest list; footprints are referenced, not copied,
/// and must outlive apply() (FootprintCache keeps them).
class StampBatch {
public:
    /// An empty batch for fields of rows × cols cells (both >= 1).
    StampBatch(int rows, int cols);

    /// Queues stampFootprint(field, fp, cx, cz, base, heightScale, af). A stamp whose
    /// footprint misses the interior (it would write nothing) is dropped.
    void push(const FootprintProfile& fp, int cx, int cz, float base, float heightScale, float af);

    /// Vh(t) at column x, row z (in range) of `field` as if every queued stamp had been
    /// applied in order, m.
    float currentAt(const RippleField& field, int x, int z) const;

    /// Applies every queued stamp to `field` (rows × cols): bit for bit what stampFootprint
    /// for each, in push order, gives. Row bands run on the worker pool. Empties the batch.
    void apply(RippleField& field);

    /// Drops every queued stamp.
    void clear();

    /// Stamps queued.
    size_t size() const { return m_stamps.size(); }
    int rows() const { return m_rows; }
    int cols() const { return m_cols; }

private:
    struct Stamp {
        const FootprintProfile* fp;
        int cx, cz;
        int reach;  // rows cz − reach .. cz + reach carry the footprint
        float base, heightScale, af;
    };
    // Row z's interior cells a stamp covers, clipped to columns [1, cols − 1): [a, b).
    bool rowSpan(const Stamp& s, int z, int& a, int& b, const float*& ph) const;
    void applyBand(RippleField& field, int z0, int z1);
    int tileOf(int cell, int tiles) const;

    int m_rows, m_cols;
    int m_words;                  // 64-bit coverage words per row
    int m_tilesX, m_tilesZ;       // query index: stamps by the tile of their centre
    int m_maxReach = 0;           // largest reach queued since the last clear
    std::vector<Stamp> m_stamps;
    std::vector<std::vector<uint32_t>> m_tiles;  // stamp indices, ascending, per tile (row-major)
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
