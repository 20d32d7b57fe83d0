// A square grid anchored to the world that follows a point in whole cells (the ripple solvers,
// the foam map): where it stands, how a world position maps to its cells, and the one routine
// that moves a grid's data when it scrolls, so what it holds stays put in the world.
#pragma once
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <type_traits>

namespace ob {

/// Cell (i, j) covers world x ∈ [(origin.x + i)·cell, …+cell), z likewise; n cells a side.
struct ScrollingGrid {
    glm::ivec2 originCell{0};  ///< world cell index of the grid's cell (0, 0)
    float cell = 1.0f;         ///< cell size, m
    int n = 0;                 ///< cells a side

    /// The grid of n cells of `cell` metres whose centre is the cell nearest `centre` (m).
    static ScrollingGrid centredOn(glm::vec2 centre, float cell, int n) {
        ScrollingGrid g{glm::ivec2(0), cell, n};
        g.originCell = g.originFor(centre);
        return g;
    }
    /// The origin cell that puts `centre` (m) in the grid's middle cell.
    glm::ivec2 originFor(glm::vec2 centre) const {
        return glm::ivec2(int(std::lround(centre.x / cell)), int(std::lround(centre.y / cell))) - glm::ivec2(n / 2);
    }
    /// World position (m) of cell (0, 0)'s corner.
    glm::vec2 origin() const { return glm::vec2(originCell) * cell; }
    /// Side length, m.
    float extent() const { return float(n) * cell; }
    /// Grid coordinates (cells, fractional) of a world position (m).
    glm::vec2 toGrid(glm::vec2 world) const { return world / cell - glm::vec2(originCell); }
    /// Moves the grid so its centre is the cell nearest `centre`; returns the shift in cells
    /// (new cell (i, j) is old cell (i + shift.x, j + shift.y)); scroll the data by it.
    glm::ivec2 centreOn(glm::vec2 centre) {
        const glm::ivec2 target = originFor(centre);
        const glm::ivec2 shift = target - originCell;
        originCell = target;
        return shift;
    }
};

/// Scrolls one row-major rows×cols level in place by `shift` cells: new (i, j) = old (i + dx,
/// j + dz), and cells that come from outside are `fill`. The one scroll routine of every grid.
template <class T>
void scrollCells(T* level, int rows, int cols, glm::ivec2 shift, T fill = T{}) {
    static_assert(std::is_trivially_copyable_v<T>);
    const int dx = shift.x, dz = shift.y;
    if (dx == 0 && dz == 0) return;
    if (std::abs(dx) >= cols || std::abs(dz) >= rows) {
        std::fill(level, level + size_t(rows) * size_t(cols), fill);
        return;
    }
    // Destination columns [xa, xb) take source columns [xa+dx, xb+dx).
    const int xa = std::max(0, -dx), xb = std::min(cols, cols - dx);
    auto shiftRow = [&](int z) {
        T* dst = level + size_t(z) * size_t(cols);
        const int sz = z + dz;
        if (sz < 0 || sz >= rows) {
            std::fill(dst, dst + cols, fill);
            return;
        }
        const T* src = level + size_t(sz) * size_t(cols);
        std::memmove(dst + xa, src + xa + dx, size_t(xb - xa) * sizeof(T));
        std::fill(dst, dst + xa, fill);
        std::fill(dst + xb, dst + cols, fill);
    };
    // Walk rows so that each source row is read before it is overwritten.
    if (dz >= 0)
        for (int z = 0; z < rows; ++z) shiftRow(z);
    else
        for (int z = rows - 1; z >= 0; --z) shiftRow(z);
}

} // namespace ob
