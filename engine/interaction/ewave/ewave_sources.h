// The ewave field's sources (EWaveField, ewave_field.h): the bounding spheres' stamps as smooth
// vertical accelerations on v, summed in float beside the state until the field next reads or
// steps v (docs/ewave.md).
#pragma once
#include "interaction/sphere_stamp.h"

#include <span>
#include <utility>
#include <vector>

namespace ob::interaction {

/// A bounding sphere's stamp as an ewave source: a vertical acceleration `accel` (m/s²) on v
/// over a biweight bump of radius `radiusCells` centred at grid (gx, gz), for one step.
struct EWaveSource {
    float gx = 0.0f, gz = 0.0f;  ///< exact centre, cells (column x, row z)
    float radiusCells = 0.0f;    ///< R, cells
    float accel = 0.0f;          ///< m/s² at the centre, + lifts the water
};

/// How a Table 2 stamp (planStamp: the same decision, SD, SHR, AF, SR as kang2008) enters the
/// ewave state. Eq. 5 would raise the water at the centre by D = SD·SHR·SR·Δ (PH = SR there);
/// here the sphere is a moving surface pressure over its footprint, p = −ρ·(g·D + SD·v²/2)·w(r):
/// the hydrostatic pressure of that displacement plus the stagnation pressure of the sphere's
/// vertical speed v (a ball entering or leaving the water at speed pushes far harder than
/// one at rest; a sphere moving level has v = 0). In deep water a pressure patch of radius
/// R = SR·Δ drives v̂ by −|k|·p̂/ρ with |k| ≈ 1/R, so while the sphere stamps the water's
/// vertical velocity gains (g·SD·SHR + SD·min(v²/(2R), 15·g))·w(r) per second (the cap keeps a
/// fast ball's splash a ring, not a jet linear waves cannot carry): a sphere at rest settles
/// into a dip of about D, a moving one leaves a Kelvin wake, a falling ball rings the water.
/// Eq. 7's AF scales it by (1 + AF) (clamped at 0): AF > 0 a stronger push, AF < 0 a weaker
/// one. Eq. 5's base height is not used (a pressure acts on whatever the water does).
/// (gx, gz): the sphere's exact grid position (not the snapped centre cell), so a moving
/// source makes no grid noise. gravity g in m/s², verticalVelocity in m/s.
EWaveSource ewaveSource(const RippleStamp& stamp, float gx, float gz, float cellSize, float gravity,
                        float verticalVelocity = 0.0f);

/// The sources' velocity not yet in v: float, rows·cols row-major, nonzero only in the rows
/// [rows0, rows1) the sources since the last applyTo wrote. Each source adds dt·accel·w(r) with
/// the biweight w(r) = (1 − r²/R²)² for r < R (smooth at its edge, so it makes no grid noise; no
/// square root or cosine per cell) at its exact sub-cell centre; cells outside the field are
/// skipped. Summed in float (8 cells a vector operation, twice double's): a source's share is a
/// forcing, rounded once to 2^-24 of itself, not the state that must keep its energy.
class EWaveSources {
public:
    /// Footprint (cells in the sources' bounding squares) from which add() splits over the workers:
    /// a hundred SR-20 spheres (a band's hand-off costs about as much as a few thousand cells).
    static constexpr size_t PARALLEL_MIN_CELLS = size_t(1) << 17;

    /// rows (z) × cols (x) cells, nothing queued.
    EWaveSources(int rows, int cols);

    /// Adds each of `sources` over dt seconds, in order (row bands on the workers when there are
    /// many and threads() > 1: a cell receives its sources in the same order whatever the split,
    /// so the bits do not depend on it).
    void add(std::span<const EWaveSource> sources, float dt);
    /// Scales what is queued at cell `index` (z·cols + x) by `factor` in [0, 1].
    void scale(size_t index, float factor) { m_sum[index] *= factor; }
    /// v += the queued sum (v: rows·cols doubles, row-major), the sum back to 0. Returns the rows
    /// it wrote, [first, second) (empty when nothing was queued).
    std::pair<int, int> applyTo(double* v);
    /// The workers add() may split over (1 or workerCount(); the field measures it per size).
    int threads() const { return m_threads; }
    void setThreads(int threads) { m_threads = threads; }

private:
    int m_rows, m_cols;
    std::vector<float> m_sum;
    int m_rows0 = 0, m_rows1 = 0;  // the rows written since the last applyTo
    int m_threads = 1;
};

} // namespace ob::interaction
