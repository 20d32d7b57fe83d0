// Splash particle settings, section [splash] (docs/splash_foam.md; laws in splash_particles.h).
#pragma once
#include "core/schema.h"
#include "environment/environment_def.h"

namespace ob::splash {

/// Drops thrown up where bodies cross the water, flown ballistically with linear drag, and
/// stamped back into the ripple layer where they land.
struct SplashDef {
    bool enabled = true;          ///< false: no splash particles at all
    int max_particles = 100000;   ///< live drops at most, [0, 10,000,000]; emission beyond is dropped (counted)
    float emission_scale = 1.0f;  ///< multiplies every drop count (impacts and bow spray), [0, 100]
    float drag = 0.8f;            ///< k, linear drag rate of a drop, 1/s, [0, 100]: dv/dt = g − k·v (terminal speed g/k)
    float drop_size = 0.004f;     ///< mean drop radius, m, [1e-4, 0.1]; radii spread uniformly over [0.5, 1.5]× it
    float min_speed = 1.0f;       ///< impacts slower than this along the surface normal throw no drops, m/s, [0, 100]
    float max_life = 10.0f;       ///< a drop still airborne after this long is removed (expired), s, [0.1, 1000]
    float bow_speed = 3.0f;       ///< bow spray starts above this horizontal speed, m/s, [0.01, 100]
    float ripple_energy = 0.2f;   ///< ε, fraction of a landing drop's kinetic energy given to the ripple layer, [0, 1]
    float spray_wind = 11.0f;     ///< breaking crests throw wind spray above this wind speed U10, m/s, [0, 100]; 11: Beaufort force 6, where its sea criteria first name spray
    int spray_per_step = 150;     ///< wind spray drops thrown per simulation step at most (the budget), [0, 100,000]
    environment::EnvironmentDef environment;  ///< g and ρ of the flight and the drops: the scene's [environment], set when it is built (not a key)
};

template <class V> void describe(V& v, SplashDef& d) {
    v.field("enabled", d.enabled, "splash particles on or off");
    v.field("max_particles", d.max_particles, range(0, 10000000), "live drops at most");
    v.field("emission_scale", d.emission_scale, range(0, 100), "multiplies every drop count");
    v.field("drag", d.drag, range(0, 100), "linear drag rate k of a drop (1/s)");
    v.field("drop_size", d.drop_size, range(1e-4, 0.1), "mean drop radius (m)");
    v.field("min_speed", d.min_speed, range(0, 100), "slowest impact that splashes, normal speed (m/s)");
    v.field("max_life", d.max_life, range(0.1, 1000), "airborne drops expire after this long (s)");
    v.field("bow_speed", d.bow_speed, range(0.01, 100), "bow spray above this horizontal speed (m/s)");
    v.field("ripple_energy", d.ripple_energy, range(0, 1), "fraction of a landing drop's kinetic energy put into ripples");
    v.field("spray_wind", d.spray_wind, range(0, 100), "breaking crests throw spray above this wind speed (m/s)");
    v.field("spray_per_step", d.spray_per_step, range(0, 100000), "wind spray drops per step at most");
}

} // namespace ob::splash
