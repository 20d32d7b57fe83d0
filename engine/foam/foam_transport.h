// The foam map's transport (docs/splash_foam.md §2): advection with the surface's velocity and
// exact decay, over the map's coverage.
//
//   ∂f/∂t + u·∇f = −f/τ,  τ = [foam] decay_s
//   step(dt)  f ← e^(−dt/τ) · f(x − u(x)·dt): semi-Lagrangian, linear between samples, 0 from
//             outside the map; the decay is exact for any dt (still water: f(t) = f(0)·e^(−t/τ)).
//             A uniform u reads one bilinear stencil; a per-sample u is split by axis (along x
//             with u_x, then along z with u_z; for a uniform u the same bilinear step). Where the
//             velocity is from the nodes and moves no sample over a cell a step, one sweep over
//             the rows in place, which can add the sources (a), (b) to each row before it moves it.
//             The flow's wind (FoamFlow::setWind: drift and streak cells) is added to its velocity
//             in every mode, and the streak cells' gathering multiplies the z pass
//             (FoamFlow::windGatherRow: continuity for the wind's part), clamped to 1.
// Rows are split over the worker pool (the sweep's from 256² only where this machine measured it
// faster: core/thread_choice.h); each sample's value depends only on the previous map, so the
// bits do not depend on the worker count.
#pragma once
#include "core/scrolling_grid.h"

#include <vector>

namespace ob::foam {

class FoamFlow;
class RowSources;

/// The transport's scratch rows and its choice of threads; the coverage is the caller's.
class FoamTransport {
public:
    /// Measures, for maps of 256² and more, whether the sweep is faster on one thread or on all
    /// (kept per size); `zeros` is a map of the grid's size, all 0 (it stays so).
    void chooseThreads(const ScrollingGrid& grid, int flowResolution, std::vector<float>& zeros);

    /// Advects the coverage `f` over `grid` by `flow` and decays it by e^(−dt/τ) (decayS = τ, s).
    void step(std::vector<float>& f, const ScrollingGrid& grid, const FoamFlow& flow, float decayS, float dt);
    /// Whether sweep() can take this step: the velocity is from the nodes, none crosses a cell.
    bool sweepFits(const ScrollingGrid& grid, const FoamFlow& flow, float dt) const;
    /// The step in one sweep over the rows, in place, the sources `s` (may be null) added to each
    /// row before it moves (the bits of s->addTo(f), then step()). Requires sweepFits().
    void sweep(std::vector<float>& f, const ScrollingGrid& grid, const FoamFlow& flow, const RowSources* s, float decayS,
               float dt);

private:
    void uniformStep(const std::vector<float>& f, const ScrollingGrid& grid, glm::vec2 u, float a, float dt);
    void splitStep(const std::vector<float>& f, const ScrollingGrid& grid, const FoamFlow& flow, float a, float dt);
    void expandNodeRows(const ScrollingGrid& grid, const FoamFlow& flow, int threads);

    std::vector<float> m_next;      // step(): the result, then swapped with the coverage
    std::vector<float> m_split;     // split step: the coverage after the x pass
    std::vector<float> m_zeros;     // split step: a row of zeros, the rows beyond the map's edges
    std::vector<float> m_nodeRows;  // sweep: the node rows expanded along x, [l][component][sample]
    std::vector<float> m_halo;      // sweep: copies of the rows around its chunks' boundaries
    int m_sweepThreads = 1 << 30;   // sweep: 1, or every worker (chooseThreads)
};

} // namespace ob::foam
