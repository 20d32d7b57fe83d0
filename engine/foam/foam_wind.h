// The wind's part of the foam's velocity (docs/splash_foam.md §2.2): the surface's mean drift
// and the streak (Langmuir) cells' rolls, evaluated a map row at a time from tables of the
// rolls' phases by column and by row that scroll with the map.
#pragma once
#include "core/scrolling_grid.h"

#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec2.hpp>

namespace ob::foam {

/// The streak cells: STREAK_MODES (12) rolls of random spacing, slant and drift (foamStreakModes), so
/// that their lines wander, merge and part rather than lie as a grating. Wavenumbers spread evenly
/// over [k/R, k], k = 2π/L, R = STREAK_SPACING_RANGE (one per stratum, jittered: spacings L to
/// R·L); axes slanted off the wind by up to ±STREAK_SLANT rad (so each line meanders along the wind over tens of metres,
/// where rolls of different slant beat); each roll's lines move across the wind at its own speed,
/// so the pattern renews over STREAK_LIFE_S (the windrows' lifetime of minutes), and all of it
/// drifts with the surface (WindFlow::drift).
constexpr int STREAK_MODES = 12;
constexpr double STREAK_SPACING_RANGE = 4.0;
/// The draws' seed: of the first 400 seeds, the one whose rolls' autocorrelation across the wind
/// (Σ (V_m·|K_m|)²·cos(K_m·ĉ·r), normalised) has the lowest secondary peak out to 60 m (0.28;
/// median 0.48).
constexpr uint64_t STREAK_SEED = 322;
constexpr double STREAK_SLANT = 0.06;
constexpr double STREAK_LIFE_S = 120.0;

/// One roll of streak cells: u = V·(cos θ·ŵ − sin θ·ĉ), θ = K·(p − drift·t) + ω·t + β.
struct StreakMode {
    glm::dvec2 k{0.0};   ///< K, rad/m, world x and z: mostly across the wind (|K| = 2π/spacing)
    double speed = 0.0;  ///< V_m, m/s
    double omega = 0.0;  ///< ω, rad/s (on top of the drift's −K·drift)
    double phase = 0.0;  ///< β, rad
};

/// The wind's part of the foam's velocity, added to the water's in every mode:
///   u_w(p) = drift + Σ_m V_m·(cos θ_m·ŵ − sin θ_m·ĉ),   θ_m = K_m·(p − drift·t) + ω_m·t + β_m,   ĉ = (−ŵ_z, ŵ_x),
/// drift the surface's mean drift (wind drift and Stokes drift, m/s). Each other term is a roll of
/// streak (Langmuir) cells whose axes lie nearly along the wind, 2π/|K_m| apart: the surface
/// converges toward its lines θ_m = 2π·j (across the wind at up to V_m) and diverges between them;
/// along the wind it runs V_m faster on the lines and V_m slower between. Their mean over the
/// cells is 0: foam drifts at `drift` on average. V_m = V·sqrt(2/M)·(L_m/L)^½: the rolls' mean
/// square speed that of two rolls of V, the wider ones faster. The rolls are foamStreakModes().
struct WindFlow {
    glm::vec2 drift{0.0f};            ///< m/s, world x and z
    glm::vec2 direction{1.0f, 0.0f};  ///< ŵ, unit, the way the wind blows
    float streakSpeed = 0.0f;         ///< V, m/s; 0: no streak cells
    float streakSpacing = 0.0f;       ///< L, m, the finest rolls' spacing; ≤ 0: no streak cells
    bool streaks() const { return streakSpeed > 0.0f && streakSpacing > 0.0f; }
    bool operator==(const WindFlow&) const = default;
};

/// The STREAK_MODES rolls for a wind (fixed pseudo-random draws: the same every run).
std::vector<StreakMode> foamStreakModes(const WindFlow& wind);

/// The wind over a foam map's samples (FoamFlow's wind part): none at first.
class FoamWind {
public:
    explicit FoamWind(const ScrollingGrid& grid) : m_grid(grid) {}

    /// The wind (its rolls drawn anew when it changed).
    void set(const WindFlow& wind);
    /// The time t of the streak cells' phases (s; they drift and renew with it); 0 at first.
    void setTime(double t);
    const WindFlow& flow() const { return m_wind; }
    /// The rolls of the streak cells (empty without them).
    std::span<const StreakMode> modes() const { return m_modes; }
    /// Whether the wind adds anything.
    bool windy() const { return m_wind.streaks() || m_wind.drift != glm::vec2(0.0f); }
    /// The largest |x|, |z| component the wind adds anywhere, m/s.
    float max() const;
    /// Map row j's wind component (0: x, 1: z) at each of its n samples (out).
    void row(int j, int component, float* out) const;
    /// Map row j's gathering over a step dt by the streak cells (FoamFlow::windGatherRow).
    void gatherRow(int j, float dt, float* out) const;
    /// The map moved to `grid`: the phase tables follow it.
    void follow(const ScrollingGrid& grid);

private:
    void fillTime();
    void fillTables();                       // every entry of the tables below
    void fillTable(int axis, int lo, int hi);  // entries [lo, hi) of the column (0) or row (1) tables
    void scrollTables(glm::ivec2 shift);       // after the map moved by shift samples
    // cos, sin of θ_m's part from row j and the time.
    void rowPhase(size_t m, int j, float& c, float& s) const {
        const size_t k = m * size_t(m_grid.n) + size_t(j);
        c = m_rowCos[k] * m_timeCos[m] - m_rowSin[k] * m_timeSin[m];
        s = m_rowSin[k] * m_timeCos[m] + m_rowCos[k] * m_timeSin[m];
    }

    ScrollingGrid m_grid;              // the map's placement
    WindFlow m_wind;                   // set
    double m_time = 0.0;               // setTime
    std::vector<StreakMode> m_modes;   // the streak cells' rolls (set)
    std::vector<float> m_columnCos, m_columnSin;  // cos, sin of the x part of θ_m at each map column, [m][i] (refilled on a scroll)
    std::vector<float> m_rowCos, m_rowSin;        // cos, sin of the z part of θ_m at each map row, [m][j] (refilled on a scroll)
    std::vector<float> m_timeCos, m_timeSin;      // cos, sin of θ_m's part from the time, [m] (setTime)
};

} // namespace ob::foam
