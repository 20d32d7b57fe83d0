// Persistent foam settings, section [foam] (docs/splash_foam.md; laws in foam_map.h and its parts).
#pragma once
#include "core/schema.h"

namespace ob::foam {

/// A foam coverage map centred on the ripple patch, advected with the surface and fed by
/// whitecaps, steep ripples, splash drops and hulls, decaying exponentially.
struct FoamDef {
    bool enabled = true;            ///< false: no foam map at all
    int resolution = 256;           ///< cells per side of the map's square; power of two in [16, 4096]
    float extent_m = 0.0f;          ///< side of the map's square, metres, [0, 1e5]; 0 = the ripple patch's side (N·Δ)
    int flow_resolution = 32;       ///< intervals per side of the grid the surface velocity is evaluated on (bilinear between); power of two in [1, 4096], at most resolution (more counts as resolution)
    int flow_refresh_steps = 4;     ///< K: update() re-evaluates each node row of the velocity grid every K steps (in turn, a K-th a step) and carries it between by linear extrapolation in time from its last two values; 1 = every node every step, [1, 64]
    float decay_s = 6.0f;           ///< τ: with no sources coverage falls as exp(−t/τ), s, [0.01, 1e4]
    bool whitecap_from_wind = true; ///< true: the threshold and gain of the whitecaps derived from [ocean] wind_speed so their coverage is Monahan's W(U10) (foam_whitecaps.h; whitecap_weight scales the gain, whitecap_jacobian unused); false: the two keys below as given
    float whitecap_weight = 2.0f;   ///< coverage per second per unit of Jacobian below whitecap_jacobian, 1/s, [0, 1000]; with whitecap_from_wind: the factor on the derived gain (2 = as derived)
    float whitecap_jacobian = 0.5f; ///< the ocean's Jacobian J below which whitecaps feed foam, [-10, 10] (whitecap_from_wind = false)
    float ripple_weight = 4.0f;     ///< coverage per second per unit of ripple slope above ripple_slope, 1/s, [0, 1000]
    float ripple_slope = 0.5f;      ///< ripple slope |∇h| above which ripples break into foam, [0, 100]
    float splash_weight = 1.0f;     ///< coverage of a landed drop's whitened disc (radius 10·r) per area, [0, 100]
    float wake_weight = 1.0f;       ///< coverage a hull's stern leaves along its track (behind it), and the most its turbulent wake adds after, [0, 100]
    float wake_streaks = 0.6f;      ///< depth of the wake's streaks along the track: its foam is laid times 1 − depth·(½ + ½·n(y)), n ∈ [−1, 1] across it, [0, 1]
    float wake_turbulence_s = 3.0f; ///< a_s: the turbulent wake behind a stern keeps adding foam at a rate ∝ exp(−age/a_s) for 4·a_s, s, [0, 100]; 0 = none
    float wake_diffusivity = 0.3f;  ///< K: the turbulent wake's half-width grows as b(age)² = R² + 2·K·age, m²/s, [0, 100]
    float bow_weight = 0.6f;        ///< coverage a breaking bow wave leaves along its two arms, times min(1, U/U_bow − 1), [0, 100]
    float wind_drift = 0.03f;       ///< the surface's wind drift down-wind, a fraction of [ocean] wind_speed (the spectrum's Stokes drift is added to it), [0, 0.2]
    float streak_speed = 0.008f;    ///< V/U10: the wind's streak (Langmuir) cells, 12 rolls of mean square speed that of two of V = this × wind_speed, converge the surface toward wandering lines along the wind (and speed it down-wind there), [0, 0.1]; 0 = none
    float streak_spacing_m = 3.0f;  ///< L: the finest streak rolls' spacing, m (the others' spread to 4·L; foam_flow.h), [0.1, 1000]
};

template <class V> void describe(V& v, FoamDef& d) {
    v.field("enabled", d.enabled, "persistent foam on or off");
    v.field("resolution", d.resolution, powerOfTwo(16, 4096), "cells per side of the map");
    v.field("extent_m", d.extent_m, range(0, 1e5), "side of the map's square (m); 0 = the ripple patch's side");
    v.field("flow_resolution", d.flow_resolution, powerOfTwo(1, 4096), "intervals per side of the surface-velocity grid (bilinear between)");
    v.field("flow_refresh_steps", d.flow_refresh_steps, range(1, 64), "steps between evaluations of a velocity node (extrapolated linearly in time between)");
    v.field("decay_s", d.decay_s, range(0.01, 1e4), "decay time τ of exp(−t/τ) (s)");
    v.field("whitecap_from_wind", d.whitecap_from_wind, "whitecap threshold and gain from the wind (Monahan's coverage)");
    v.field("whitecap_weight", d.whitecap_weight, range(0, 1000), "whitecap source per unit of Jacobian below the threshold (1/s); from the wind: 2 = the derived gain");
    v.field("whitecap_jacobian", d.whitecap_jacobian, range(-10, 10), "Jacobian below which whitecaps make foam");
    v.field("ripple_weight", d.ripple_weight, range(0, 1000), "steep-ripple source per unit of slope above the threshold (1/s)");
    v.field("ripple_slope", d.ripple_slope, range(0, 100), "ripple slope above which ripples make foam");
    v.field("splash_weight", d.splash_weight, range(0, 100), "foam of a landed drop, times its whitened area");
    v.field("wake_weight", d.wake_weight, range(0, 100), "foam a hull's stern leaves along its track");
    v.field("wake_streaks", d.wake_streaks, range(0, 1), "depth of the wake's streaks along the track");
    v.field("wake_turbulence_s", d.wake_turbulence_s, range(0, 100), "how long the turbulent wake behind a stern keeps adding foam (s); 0 = none");
    v.field("wake_diffusivity", d.wake_diffusivity, range(0, 100), "how fast the turbulent wake widens (m²/s)");
    v.field("bow_weight", d.bow_weight, range(0, 100), "foam a breaking bow wave leaves along its arms");
    v.field("wind_drift", d.wind_drift, range(0, 0.2), "surface wind drift down-wind, fraction of the wind speed (plus the spectrum's Stokes drift)");
    v.field("streak_speed", d.streak_speed, range(0, 0.1), "speed of the wind's streak cells converging foam into lines along the wind, fraction of the wind speed; 0 = none");
    v.field("streak_spacing_m", d.streak_spacing_m, range(0.1, 1000), "spacing of the finest streak cells' lines along the wind (m); the others' spread to 4 times it");
}

} // namespace ob::foam
