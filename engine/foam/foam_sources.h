// The foam map's six source laws (docs/splash_foam.md §2): what each adds to a coverage map
// where it stands. (a)–(c) in foam_sources.cpp, a hull's (d)–(f) in foam_wake.cpp.
//
// Coverage f ∈ [0, 1] per sample; n×n samples Δ apart, sample (i, j) at grid.origin() + (i, j)·Δ
// (i along x, j along z; row-major, index j·n + i). Each source adds S·dt (or a fixed amount)
// to a sample, clamped to 1:
//   (a) whitecaps  S = whitecap_weight · max(0, J_0 − J), J the ocean's Jacobian at the sample
//                  (bilinear in the periodic cascade tile, at rest points), J_0 = whitecap_jacobian;
//                  with whitecap_from_wind J_0 and the gain (times whitecap_weight / 2) follow from
//                  the wind and J's statistics (foam_whitecaps.h: Monahan's coverage)
//   (b) ripples    S = ripple_weight · max(0, |∇h| − s_0), |∇h| the ripple slope by central
//                  differences at the ripple cell nearest the sample, s_0 = ripple_slope
//   (c) drops      a landed drop of radius r adds splash_weight · π·(10·r)² / Δ², spread over the
//                  four samples around it by their bilinear weights
//   (d) wake       a hull sphere (centre c, radius R, horizontal speed U > 0) adds
//                  S = wake_weight · U / R to every sample within R of c that lies behind it
//                  ((p − c)·u ≤ 0): a point it passes at lateral offset y gains
//                  wake_weight·sqrt(1 − (y/R)²)·m(y) (before decay and the clamp), nothing ahead of it;
//                  m(y) = 1 − wake_streaks·(½ + ½·n(y)) (wakeStreaks) lays it in streaks along the track
//   (e) turbulent wake  a segment of a stern's track of age a adds S = wake_weight·e^(−a/a_s)/a_s ·
//                  (R/b)·sqrt(1 − (y/b)²)·m(y·R/b) to the samples beside it within b(a) = sqrt(R² + 2·K·a)
//                  (a_s = wake_turbulence_s, K = wake_diffusivity): it widens and thins with age, and
//                  adds at most wake_weight on the track (R/b ≤ 1)
//   (f) bow wave   above the bow-spray speed U_b a bow sphere (radius R, speed U) breaks its bow wave
//                  along two arms from its shoulders (c + ½R·û ± R·side), back at the Kelvin angle
//                  θ = asin(1/3) either side, 8·R·q long, q = min(1, U/U_b − 1): the samples within w/2
//                  of an arm (w = max(2Δ, 0.3 m)) gain S = bow_weight·q·U·sin θ / w, so a point an arm
//                  sweeps over gains bow_weight·q
#pragma once
#include "core/scrolling_grid.h"
#include "environment/environment_def.h"
#include "foam/foam_def.h"
#include "foam/foam_whitecaps.h"

#include <algorithm>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob::interaction {
class RipplePatch;
}
namespace ob::splash {
struct Landing;
}
namespace ob::water {
class CompositeWater;
}

namespace ob::foam {

/// Rows per worker-pool chunk of a pass over the map (sources and transport): 512² is 32 chunks
/// of 16 rows, ~8 µs each.
constexpr int ROW_CHUNK = 16;

/// How a landed drop's whitened disc relates to its radius (disc radius = this × r).
constexpr float DROP_FOAM_RADIUS_FACTOR = 10.0f;

/// The streaks of a wake (law (d), (e)): its foam is laid times m(y) = 1 − depth·(½ + ½·n(y)),
/// y the lateral offset from the track (m), n ∈ [−1, 1] a fixed sum of three sines of y
/// (wavelengths 0.9, 1.5, 2.6 m), so the foam lies in lines along the track as the bubbles of
/// a ship's wake gather where its longitudinal vortices converge.
float wakeStreaks(float y, float depth);

/// What one whole foam update reads (FoamMap::update); each part may be absent.
struct FoamInputs {
    std::span<const float> jacobian;  ///< (a) an ocean cascade's Jacobian, n×n floats row-major [j][i] at X = (i, j)·tile/n; empty: no whitecaps
    int jacobianN = 0;                ///< n
    float jacobianTile = 0.0f;        ///< tile, m
    float windSpeed = 0.0f;           ///< U10, m/s: with whitecap_from_wind, sets (a)'s threshold and gain (foam_whitecaps.h)
    glm::vec2 windDirection{1.0f, 0.0f};  ///< ŵ, the way the wind blows (any non-zero vector): the drift and streaks of §2.2
    glm::vec2 stokesDrift{0.0f};          ///< the sea's surface Stokes drift, m/s (ocean::stokesDrift), added to the wind drift
    float gravity = environment::STANDARD_ENVIRONMENT.gravity;  ///< g, m/s² (OceanDef::gravity)
    const interaction::RipplePatch* ripples = nullptr;  ///< (b) steep ripples of its Vh(t); null: none
    std::span<const float> rippleHeight;                ///< (b) its height level as read (a copy); empty: ripples->height()
    const water::CompositeWater* water = nullptr;       ///< the surface velocity at its time(); null: the velocity set last
};

/// The samples a source adds to: a map's coverage where it stands (see the layout above).
struct CoverageCells {
    ScrollingGrid grid;  ///< the map's placement: sample (i, j) at grid.origin() + (i, j)·grid.cell
    std::span<float> f;  ///< grid.n² samples, row-major
    /// f(i, j) ← min(1, f(i, j) + amount); (i, j) inside the map.
    void add(int i, int j, float amount) const {
        float& v = f[size_t(j) * size_t(grid.n) + size_t(i)];
        v = std::min(1.0f, v + amount);
    }
};

/// Sources (a) and (b) of one update, tabulated for the map where it stands (where each of its
/// columns and rows falls in the Jacobian tile and the ripple patch), added a row at a time:
/// the transport's sweep adds them to each row just before it moves it.
class RowSources {
public:
    /// The tables of `in`'s Jacobian and ripples (either may be absent) over dt seconds.
    RowSources(const FoamDef& def, const ScrollingGrid& grid, const FoamInputs& in, float dt);

    /// A worker's cache: the tile rows read at every column (the last two, reused by the rows
    /// between them) and the ripple row's slopes.
    class Rows {
    public:
        explicit Rows(const RowSources& sources) : m_s(sources) {}
        /// Row j with the sources' S·dt added (a clamp at 1 after each): out[i] from in[i] over the
        /// map's n samples (in == out: in place). Returns false (out untouched) when none reaches it.
        bool add(int j, const float* in, float* out);

    private:
        const float* tile(int r, int keep, int& slot);
        bool steepRow(int z);
        const RowSources& m_s;
        int m_tileRow[2] = {-1, -1};
        std::vector<float> m_upsampled[2], m_windowRow;
        int m_slopeRow = -1;   // the ripple row m_rippleSlope holds
        bool m_steep = false;  // some |∇h| in it above the threshold (else it adds nothing)
        std::vector<float> m_rippleSlope, m_gathered;
    };

    /// Adds them to every row of `f` (the map's coverage), rows split over the worker pool.
    void addTo(std::span<float> f) const;
    /// Source (a)'s law this update (derived from the wind, or the def's; rate 0: none).
    const WhitecapLaw& whitecaps() const { return m_law; }

private:
    void tabulateWhitecaps(const FoamDef& def, const FoamInputs& in, float dt);
    void tabulateRipples(const FoamDef& def, const interaction::RipplePatch& patch, std::span<const float> height, float dt);

    int m_mapN = 0;                       // the map's samples a side
    float m_cell = 0.0f;                  // Δ, m
    glm::vec2 m_origin{0.0f};             // its sample (0, 0), world m
    // (a) whitecaps: foam column i lies between samples c0[i] and c0[i] + 1 of a window of the
    // tile's columns (window[k]: the tile column of its sample k, periodic), at weight ct[i].
    const float* m_jacobian = nullptr;    // null: no whitecaps
    int m_n = 0;                          // the tile's samples a side
    float m_toTile = 0.0f;                // tile samples per metre
    std::vector<int> m_window, m_c0;
    std::vector<float> m_ct;
    // The least J of each tile row over the window (+∞ for rows the map does not reach): a foam
    // row between two tile rows whose least J is J_0 or more gains nothing (J is bilinear).
    std::vector<float> m_rowMin;
    float m_j0 = 0.0f, m_whitecapRate = 0.0f;
    WhitecapLaw m_law;                    // J_0 and the rate per second (before dt)
    // (b) steep ripples: the nearest ripple cell of foam column i and row j (rx, rz), for the
    // columns [iLo, iHi) and rows [jLo, jHi) that have an interior one (a central difference).
    const float* m_height = nullptr;      // null: no ripples
    int m_cols = 0;
    float m_inv2d = 0.0f;
    std::vector<int> m_rx, m_rz;
    int m_iLo = 0, m_iHi = 0, m_jLo = 0, m_jHi = 0;
    bool m_contiguous = false;            // rx[i] = rx[iLo] + i − iLo (the ripple and foam cells match)
    float m_slope0 = 0.0f, m_rippleRate = 0.0f;
};

/// (c) landed splash drops.
void addLandings(const FoamDef& def, const CoverageCells& cells, std::span<const splash::Landing> landings);
/// (d) one hull sphere: centre (m), velocity (m/s; its horizontal part counts), radius (m).
void addWake(const FoamDef& def, const CoverageCells& cells, const glm::vec3& centre, const glm::vec3& velocity,
             float radius, float dt);
/// (e) one segment of a stern's track, from its older end to its newer (world x, z, m), of age a
/// (s, at its middle), behind a stern sphere of radius R (m).
void addWakeTrail(const FoamDef& def, const CoverageCells& cells, glm::vec2 from, glm::vec2 to, float age, float radius,
                  float dt);
/// (f) a bow sphere's breaking bow wave: centre (m), velocity (m/s; its horizontal part counts),
/// radius (m), strength q = min(1, U/U_b − 1) (nothing when ≤ 0).
void addBowWave(const FoamDef& def, const CoverageCells& cells, const glm::vec3& centre, const glm::vec3& velocity,
                float radius, float strength, float dt);

} // namespace ob::foam
