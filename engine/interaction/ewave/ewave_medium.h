// The water the ewave field's waves run in (EWaveField, ewave_field.h): its restoring forces, its
// depth and its own viscosity.
#pragma once
#include "environment/environment_def.h"

namespace ob::interaction {

/// The water the waves run in: its restoring forces, its depth and its own viscosity, in the
/// dispersion ω² = (g·k + (σ/ρ)·k³)·tanh(k·d) (d = 0: deep, tanh = 1) and the damping 2νk².
struct EWaveMedium {
    double gravity;           ///< g, m/s², > 0
    double capillarity;       ///< σ/ρ, m³/s², >= 0
    double depth = 0.0;       ///< d, m, >= 0; 0 = deep water (no bottom)
    double viscosity = 0.0;   ///< ν, kinematic, m²/s, >= 0: every wave's amplitude decays as exp(−2νk²t) (Lamb §348)
    /// g, σ/ρ and ν of an [environment], over water `depth` m deep (0 = deep).
    static EWaveMedium of(const environment::EnvironmentDef& env, double depth = 0.0) {
        return {double(env.gravity), environment::capillarity(env), depth, double(env.water_viscosity)};
    }
    /// A default [environment]'s g and σ/ρ, deep and without viscosity (a field's medium until told otherwise).
    static EWaveMedium ideal() { return {double(environment::EnvironmentDef{}.gravity), environment::capillarity({})}; }
    /// ω(k), rad/s, for a wavenumber k in rad/m.
    double omega(double k) const;
};

} // namespace ob::interaction
