// Obstacles in the ripple layer: bodies that cut the water surface (fixed walls and pillars,
// floating hulls) as footprints on the water plane, rasterised into a per-cell mask, and the
// iWave obstruction (Tessendorf, "Interactive Water Surfaces", 2004, §obstructions) that the
// solvers apply after each step: the state inside the mask is scaled to its level (soft edge of
// one cell), and what that moved in each level's sum is spread back evenly, so the projection
// leaves the mean level (the k = 0 mode) as it was. A fixed body's level is 0; a floating hull's
// height level is its hollow (the surface its draft depresses, deepest on its keel line), and no
// pressure source acts inside it: the hull is the pressure that holds its water there, whose
// uniform part, the volume it displaces, lifts the whole grid as every source's does.
// docs/ewave.md#obstacles.
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
    bool displaces = false;       ///< a floating hull: its water is held at its hollow (hollowLevel), no source acts inside it
    float hollow = 0.0f;          ///< displacing: depth of the hull's hollow on its keel line, m, >= 0

    /// A disc of `radius` m at `centre`.
    static ObstacleShape disc(glm::vec2 centre, float radius) { return {Kind::Ellipse, centre, {1.0f, 0.0f}, glm::vec2(radius)}; }
    /// Signed distance (m) of world point `p` from the outline: < 0 inside. Exact for a
    /// rectangle; for an ellipse a first-order estimate (exact on its axes), enough for the
    /// one-cell soft edge it shapes.
    float distance(glm::vec2 p) const;
    /// The height a displacing footprint holds the water at, world point `p` inside it, m:
    /// −hollow·(1 − ρ²), ρ the shape's own norm of p (Euclidean over the semi-axes for an
    /// ellipse, the larger ratio for a rectangle: 0 at the centre, 1 on the outline). The hull's
    /// draft as a pressure head, deepest on its keel line and 0 at its waterline (a ship's
    /// parabolic sections and waterlines, Wigley's hull); 0 outside and for a fixed body.
    float hollowLevel(glm::vec2 p) const;
};

/// One cell of a ripple grid that an obstacle covers: its row-major index (z·cols + x), the
/// fraction of the water's state it keeps after a step, in [0, 1) (0 inside a body, between 0
/// and 1 on the one-cell soft edge), and the height it holds the water at. Cells not listed are
/// open water (keep 1). A cell may be listed more than once (overlapping bodies): the factors
/// multiply.
struct ObstructionCell {
    uint32_t index = 0;
    float keep = 0.0f;
    float level = 0.0f;      ///< the height the masked water is held at, m: 0, or a hull's hollow (ObstacleShape::hollowLevel)
    bool displaces = false;  ///< a floating hull's cell (no pressure source acts on it: EWaveField::scaleQueuedSources)
};

/// The cells of a rows × cols grid that `shapes` cover, appended to `out` (cleared first).
/// `toGrid` maps a world (x, z) in m to grid coordinates (cell centres at integers);
/// cellSize in m. keep = clamp(0.5 + distance/cellSize, 0, 1): a linear edge one cell wide,
/// centred on the outline, so a body moving smoothly changes the mask smoothly. A displacing
/// shape's cells hold the water at its hollowLevel at the cell's centre.
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

/// Scales each listed cell of a level towards its target and puts back what that moved, as one
/// even share on every cell, so the level's sum (its k = 0 mode, the mean water level or the
/// mean vertical velocity) is what it was before, up to rounding. `heights`: the level is a
/// height and each cell's target is its ObstructionCell::level (a hull's hollow),
/// f = level + keep·(f − level); otherwise (velocities) 0, f = keep·f. The even share is the
/// volume a hull displaces: a pressure's uniform part moves no water locally (an ewave source's
/// v̂(0) is dropped alike), and a share pushed just outside the hull instead made the projection
/// a pump (docs/ewave.md#hulls).
template <class T> void obstructKeepingMean(std::span<T> level, std::span<const ObstructionCell> cells, bool heights = false) {
    double removed = 0.0;
    for (const ObstructionCell& c : cells) {
        const T before = level[c.index];
        const T target = heights ? T(c.level) : T(0);
        level[c.index] = target == T(0) ? before * T(c.keep) : target + (before - target) * T(c.keep);
        removed += double(before) - double(level[c.index]);
    }
    if (removed == 0.0) return;
    const T share = T(removed / double(level.size()));
    for (T& f : level) f += share;
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
                if (s.displaces) {
                    c.level = s.hollowLevel(world);
                    c.displaces = true;
                }
                out.push_back(c);
            }
    }
}

} // namespace ob::interaction
