// The physical world's constants, section [environment]: every part that needs g, ρ or σ
// (bodies, ocean dispersion, Gerstner waves, ewave ripples, splash drops, fish) gets them from
// here, copied into its own Def when the scene is built (game/world/scene.cpp applyEnvironment).
#pragma once
#include "core/schema.h"

namespace ob::environment {

/// Gravity and the properties of the water and the air. Read once at start.
struct EnvironmentDef {
    float gravity = 9.81f;           ///< g, m/s², downward, [0.1, 100]
    float water_density = 1025.0f;   ///< ρ of sea water, kg/m³, [1, 20000]
    float air_density = 1.225f;      ///< ρ_air at sea level (ISA, 15 °C), kg/m³, [0, 100]
    float surface_tension = 0.074f;  ///< σ of the water surface, N/m, [0, 1]; capillary waves: ω² = g·k + (σ/ρ)·k³
    float water_viscosity = 1.0e-6f; ///< ν, kinematic viscosity of water, m²/s, [0, 1]
};

template <class V> void describe(V& v, EnvironmentDef& d) {
    v.field("gravity", d.gravity, range(0.1, 100), "gravity g, m/s² (bodies, waves, drops, fish)");
    v.field("water_density", d.water_density, range(1, 20000), "water density ρ, kg/m³");
    v.field("air_density", d.air_density, range(0, 100), "air density, kg/m³");
    v.field("surface_tension", d.surface_tension, range(0, 1), "surface tension σ of the water, N/m (capillary waves)");
    v.field("water_viscosity", d.water_viscosity, range(0, 1), "kinematic viscosity of water, m²/s");
}

/// The standard environment (the defaults above): the starting value of every Def that holds a
/// copy of one of its constants, replaced by the scene's [environment] when the scene is built.
inline constexpr EnvironmentDef STANDARD_ENVIRONMENT{};

/// σ/ρ, m³/s²: the capillary term of the dispersion ω² = g·k + (σ/ρ)·k³.
inline double capillarity(const EnvironmentDef& d) { return double(d.surface_tension) / double(d.water_density); }

/// The text a key that moved here is refused with ("moved to environment.gravity").
inline std::string movedHere(const char* key) { return std::string("moved to environment.") + key; }

} // namespace ob::environment
