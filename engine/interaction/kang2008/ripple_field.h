// Ripple field: linear convolution of a two-level height field, [Kang2008] eq. 1–2 (docs/references.md#ripple-layer).
// Row-major N×M floats, row = z, column = x; heights in metres; one cell per vertex.
#pragma once
#include "interaction/ripple_def.h"

#include <span>
#include <vector>

namespace ob::interaction {

// The edge (interaction/ripple_def.h): in every mode the outer ring of cells is held at 0.
// Fixed: interior cells follow eq. 1–2 exactly and waves reflect off the zero ring; Absorbing:
// a sponge band inside the ring ramps up friction, so waves leave the patch. Eq. 1–2 has no
// periodic form: Periodic is held as Fixed (a scene cannot ask for it).

/// N×M ripple height field with two time levels, Vh(t) and Vh(t−1), stepped by eq. 1–2.
class RippleField {
public:
    /// Default width of the absorbing sponge band, cells.
    static constexpr int DEFAULT_SPONGE_WIDTH = 16;

    /// rows (N, along z) and cols (M, along x) >= 1; spongeWidth in cells, used by Absorbing
    /// and clamped to half the smaller side. Both levels start at 0.
    RippleField(int rows, int cols, RippleBoundary boundary = RippleBoundary::Fixed,
                int spongeWidth = DEFAULT_SPONGE_WIDTH);

    /// Copies own their levels (the level pointers point into the copy's storage).
    RippleField(const RippleField& o) { *this = o; }
    RippleField& operator=(const RippleField& o);
    RippleField(RippleField&&) noexcept = default;  // the storage moves, its pointers stay valid
    RippleField& operator=(RippleField&&) noexcept = default;

    /// One step of eq. 1–2 with damping DF in [0, 1] (0 kills waves next step, 1 keeps them),
    /// then Vh(t−1) <- Vh(t), Vh(t) <- Vh(t+1) by swapping pointers. Allocates nothing;
    /// rows are split over the worker pool for large fields, bit-identical for any count.
    void step(float damping);

    /// Moves the patch by (dx, dz) whole cells in the world: the value at cell (x+dx, z+dz)
    /// moves to (x, z) in both levels, cells with no source become 0, so waves stay put in the
    /// world while the patch follows the camera. The outer ring stays 0.
    void scroll(int dx, int dz);

    /// Sets both levels to 0 everywhere.
    void clear();

    /// Changes the boundary; spongeWidth in cells (Absorbing only), clamped as in the constructor.
    void setBoundary(RippleBoundary boundary, int spongeWidth = DEFAULT_SPONGE_WIDTH);

    /// N: number of rows (z).
    int rows() const { return m_rows; }
    /// M: number of columns (x).
    int cols() const { return m_cols; }
    /// The boundary mode in use.
    RippleBoundary boundary() const { return m_boundary; }
    /// Sponge band width in cells after clamping (0 for Fixed).
    int spongeWidth() const { return m_spongeWidth; }

    /// Vh(t), N·M values row-major (index z·M + x), metres.
    std::span<float> current() { return {m_cur, m_cells}; }
    /// Vh(t), read-only.
    std::span<const float> current() const { return {m_cur, m_cells}; }
    /// Vh(t−1), N·M values row-major, metres.
    std::span<float> previous() { return {m_prev, m_cells}; }
    /// Vh(t−1), read-only.
    std::span<const float> previous() const { return {m_prev, m_cells}; }
    /// Vh(t) at column x, row z (both in range), metres.
    float currentAt(int x, int z) const { return m_cur[size_t(z) * size_t(m_cols) + size_t(x)]; }

    /// Sponge profile s(d) at distance d cells from the outer ring for a band of width w:
    /// sin²(π/2 · d/w) for 0 <= d < w, 1 from w inwards. The band's friction on the vertical
    /// velocity is 0.4·(1 − s_row·s_col), so waves leave without reflecting (see .cpp).
    static float spongeFactor(int d, int w);

private:
    void rebuildSponge();

    int m_rows, m_cols;
    size_t m_cells;
    RippleBoundary m_boundary;
    int m_spongeWidth = 0;
    std::vector<float> m_storage;  // both levels, allocated once: [0, N·M) and [N·M, 2·N·M)
    float* m_cur;                  // Vh(t)
    float* m_prev;                 // Vh(t−1); step() writes Vh(t+1) over it, then swaps
    std::vector<float> m_rowSponge, m_colSponge;  // s(d) per row and column, 1 away from the band
};

} // namespace ob::interaction
