// Obstacles in the ripple layer: bodies that cut the water surface (fixed walls and pillars,
// floating hulls) as footprints on the water plane, rasterised into a per-cell mask, and the
// iWave obstruction (Tessendorf, "Interactive Water Surfaces", 2004, §obstructions) that the
// solvers apply after each step: the state inside the mask is scaled to 0 (soft edge of one
// cell), and what that removed from each level's sum is spread back evenly, so the projection
// leaves the mean level (the k = 0 mode) as it was. A floating hull's footprint displaces: what
// its mask removes goes just outside its outline, across from where it was taken (the water the
// hull pushes aside), so the hull reflects and a moving hull makes its own displacement wave. docs/ewave.md#obstacles.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <span>
#include <vector>

namespace ob::interaction {

/// A body's footprint on the water plane (world x, z in metres): a rectangle or an ellipse.
struct ObstacleShape {
    enum class Kind : uint8_t { Rect, Ellipse };
    Kind kind = Kind::Rect;
    glm::vec2 centre{0.0f};       ///< world (x, z), m
    glm::vec2 axis{1.0f, 0.0f};   ///< unit world (x, z) of the shape's first axis; the second is (−axis.y, axis.x)
    glm::vec2 half{0.5f};         ///< half extents (Rect) or semi-axes (Ellipse) along the two axes, m, > 0
    bool displaces = false;       ///< a floating hull: what its mask removes is pushed out of it (pushedOut), not spread

    /// A disc of `radius` m at `centre`.
    static ObstacleShape disc(glm::vec2 centre, float radius) { return {Kind::Ellipse, centre, {1.0f, 0.0f}, glm::vec2(radius)}; }
    /// Signed distance (m) of world point `p` from the outline: < 0 inside. Exact for a
    /// rectangle; for an ellipse a first-order estimate (exact on its axes), enough for the
    /// one-cell soft edge it shapes.
    float distance(glm::vec2 p) const;
    /// The point `offset` m outside the outline across from p (world, m): p taken radially from
    /// the centre onto the outline, then moved along the outline's normal there. Where a hull
    /// pushes the water at p aside.
    glm::vec2 pushedOut(glm::vec2 p, float offset) const;
};

/// How far outside its outline (cells) a displacing footprint puts the water its mask removes:
/// past the one-cell soft edge, so that it lands in open water.
inline constexpr float DISPLACEMENT_OFFSET_CELLS = 1.5f;

/// One cell of a ripple grid that an obstacle covers: its row-major index (z·cols + x), the
/// fraction of the water's state it keeps after a step, in [0, 1) (0 inside a body, between 0
/// and 1 on the one-cell soft edge), and where what it removes goes: spread evenly over the
/// grid (`to` = SPREAD_EVENLY: fixed bodies), or pushed out of a displacing hull to the point
/// just outside its outline across from the cell, shared bilinearly by the 2 × 2 cells from
/// `to` (the lower corner's index) with fractions (fx, fz). Cells not listed are open water
/// (keep 1). A cell may be listed more than once (overlapping bodies): the factors multiply.
struct ObstructionCell {
    static constexpr uint32_t SPREAD_EVENLY = 0xffffffffu;
    uint32_t index = 0;
    float keep = 0.0f;
    uint32_t to = SPREAD_EVENLY;  ///< row-major index of the lower corner of the 2 × 2 cells that take the removed water
    float fx = 0.0f, fz = 0.0f;   ///< bilinear fractions toward the next column and row, [0, 1)
    uint32_t cols = 0;            ///< the grid's row length: `to` + cols is the next row
};

/// The cells of a rows × cols grid that `shapes` cover, appended to `out` (cleared first).
/// `toGrid` maps a world (x, z) in m to grid coordinates (cell centres at integers);
/// cellSize in m. keep = clamp(0.5 + distance/cellSize, 0, 1): a linear edge one cell wide,
/// centred on the outline, so a body moving smoothly changes the mask smoothly. A displacing
/// shape's cells send what they remove along the outline's normal to DISPLACEMENT_OFFSET_CELLS
/// outside it (evenly over the grid where that falls off the grid).
template <class ToGrid>
void rasteriseObstacles(std::span<const ObstacleShape> shapes, int rows, int cols, float cellSize, ToGrid&& toGrid,
                        std::vector<ObstructionCell>& out);

/// Scales each listed cell of a rows·cols level by its keep factor and returns what that
/// removed from the level's sum, Σ f·(1 − keep) (in the level's units times cells).
template <class T> double obstructLevel(std::span<T> level, std::span<const ObstructionCell> cells) {
    double removed = 0.0;
    for (const ObstructionCell& c : cells) {
        const T before = level[c.index];
        level[c.index] = before * T(c.keep);
        removed += double(before) - double(level[c.index]);
    }
    return removed;
}

/// obstructLevel, then what it removed put back, so the level's sum (its k = 0 mode, the mean
/// water level or the mean vertical velocity) is what it was before, up to rounding: a fixed
/// body's removals as one even share on every cell, a displacing hull's on the cells just
/// outside it across from where they were taken (after every cell is scaled, so none is lost).
template <class T> void obstructKeepingMean(std::span<T> level, std::span<const ObstructionCell> cells) {
    const bool displacing = std::any_of(cells.begin(), cells.end(), [](const ObstructionCell& c) { return c.to != ObstructionCell::SPREAD_EVENLY; });
    if (!displacing) {  // fixed bodies only: one even share (the path every scene without hulls takes)
        const double removed = obstructLevel(level, cells);
        if (removed == 0.0) return;
        const T share = T(removed / double(level.size()));
        for (T& f : level) f += share;
        return;
    }
    std::vector<double> removed(cells.size());
    double even = 0.0;
    for (size_t i = 0; i < cells.size(); ++i) {
        const ObstructionCell& c = cells[i];
        const T before = level[c.index];
        level[c.index] = before * T(c.keep);
        removed[i] = double(before) - double(level[c.index]);
        if (c.to == ObstructionCell::SPREAD_EVENLY) even += removed[i];
    }
    for (size_t i = 0; i < cells.size(); ++i) {
        const ObstructionCell& c = cells[i];
        if (c.to == ObstructionCell::SPREAD_EVENLY || removed[i] == 0.0) continue;
        // Bilinear shares; the last takes the rest, so the four add up to what was removed.
        const double r = removed[i], fx = c.fx, fz = c.fz;
        const double a = r * (1.0 - fx) * (1.0 - fz), b = r * fx * (1.0 - fz), d = r * (1.0 - fx) * fz;
        level[c.to] += T(a);
        level[c.to + 1] += T(b);
        level[c.to + c.cols] += T(d);
        level[c.to + c.cols + 1] += T(r - a - b - d);
    }
    if (even != 0.0) {
        const T share = T(even / double(level.size()));
        for (T& f : level) f += share;
    }
}

// Where a displacing shape's cell at `world` (grid coordinates `g`) puts what it removes:
// pushedOut by DISPLACEMENT_OFFSET_CELLS; c.to stays SPREAD_EVENLY where that is off the grid.
inline void displaceTo(const ObstacleShape& s, glm::vec2 world, glm::vec2 g, float cellSize, int rows, int cols, ObstructionCell& c) {
    const glm::vec2 t = g + (s.pushedOut(world, DISPLACEMENT_OFFSET_CELLS * cellSize) - world) / cellSize;
    const int tx = int(std::floor(t.x)), tz = int(std::floor(t.y));
    if (tx < 0 || tz < 0 || tx + 1 >= cols || tz + 1 >= rows) return;
    c.to = uint32_t(tz) * uint32_t(cols) + uint32_t(tx);
    c.fx = t.x - float(tx);
    c.fz = t.y - float(tz);
    c.cols = uint32_t(cols);
}

// --- rasteriseObstacles: each shape's bounding square of cells, distance per cell centre
template <class ToGrid>
void rasteriseObstacles(std::span<const ObstacleShape> shapes, int rows, int cols, float cellSize, ToGrid&& toGrid,
                        std::vector<ObstructionCell>& out) {
    out.clear();
    for (const ObstacleShape& s : shapes) {
        const float reach = glm::length(s.half) + cellSize;  // the outline and its soft edge lie within
        const glm::vec2 lo = toGrid(s.centre - glm::vec2(reach)), hi = toGrid(s.centre + glm::vec2(reach));
        const int x0 = std::max(0, int(std::floor(lo.x))), x1 = std::min(cols - 1, int(std::ceil(hi.x)));
        const int z0 = std::max(0, int(std::floor(lo.y))), z1 = std::min(rows - 1, int(std::ceil(hi.y)));
        const glm::vec2 g0 = toGrid(s.centre);  // the shape's centre in grid coordinates
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 world = s.centre + (glm::vec2(float(x), float(z)) - g0) * cellSize;
                const float d = s.distance(world);
                const float keep = std::clamp(0.5f + d / cellSize, 0.0f, 1.0f);
                if (keep >= 1.0f) continue;
                ObstructionCell c{uint32_t(z) * uint32_t(cols) + uint32_t(x), keep};
                if (s.displaces) displaceTo(s, world, glm::vec2(float(x), float(z)), cellSize, rows, cols, c);
                out.push_back(c);
            }
    }
}

} // namespace ob::interaction
