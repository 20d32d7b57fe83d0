// The depth decay of a cascade's velocity by bands of |K| (docs/velocity_bands.md): each
// mode's e^{−k·depth} fitted by B ≤ 4 exponentials e^{−k_b·depth}, one per band of the cascade.
#pragma once
#include "ocean/spectrum.h"

#include <array>
#include <span>
#include <vector>

namespace ob::ocean {

/// A mode of wavenumber k under the surface moves as Σ_b g_b(k)·e^{−k_b·depth} (Σ_b g_b = 1, exact
/// at the surface), g_b fitted by least squares to e^{−k·depth} over the probes' depths
/// [0, VELOCITY_FIT_DEPTH]. Band b's velocity maps are the cascade's modes weighted by g_b;
/// the last band is the cascade's whole velocity less the others (no maps of its own).
/// Knots k_b: evenly spaced in √k over the cascade's modes up to VELOCITY_FIT_CAP, at most
/// VELOCITY_KNOT_SPACING apart in √k, so that B = 4 covers a tile from 0.03 to 5 rad/m to a
/// few percent at 0–3 m (docs/velocity_bands.md gives the error per depth).
struct VelocityBands {
    static constexpr int MAX_BANDS = 4;   ///< B at most
    int count = 1;                        ///< B, bands, [1, MAX_BANDS]
    std::array<float, MAX_BANDS> k{};     ///< knot k_b of each band, rad/m, ascending (count used)
    int quarter = 0;                      ///< N/2 + 1: the weights' quarter grid side
    /// g_b(|K|) of the count − 1 bands with maps, a quarter grid each (|m| rows, |n| columns),
    /// [(b·quarter + |m|)·quarter + |n|].
    std::vector<float> weights;

    /// Bands with maps of their own: count − 1.
    int mappedBands() const { return count - 1; }
    /// Packed complex transforms their maps take: (w_b, u_b) one each, the v_b two to a transform.
    int transforms() const { return mappedBands() + (mappedBands() + 1) / 2; }
};

/// Depth over which the weights are fitted, metres: where bodies' probes sit.
constexpr double VELOCITY_FIT_DEPTH = 3.0;
/// Largest knot, rad/m: shorter waves decay to e^{−5·depth} < 8 % of their surface velocity
/// 0.5 m down, so the knots are spent on the longer ones.
constexpr double VELOCITY_FIT_CAP = 5.0;
/// Widest gap between two knots in √k, (rad/m)^½.
constexpr double VELOCITY_KNOT_SPACING = 0.55;

/// The bands of a tile of `resolution` points a side and side `patchSize` metres whose modes
/// lie in `band` (cascadeBand). O(N²) (a table of the weights in √k, read per mode).
VelocityBands velocityBands(int resolution, double patchSize, WaveBand band);

/// g_b(k) of every band (count values, summing to 1) for wavenumber k, rad/m: the fit itself.
void bandWeights(const VelocityBands& bands, double k, std::span<double> out);

/// The decay the bands give a mode of wavenumber k at `depth` metres: Σ_b g_b(k)·e^{−k_b·depth}.
double bandDecay(const VelocityBands& bands, double k, double depth);

} // namespace ob::ocean
