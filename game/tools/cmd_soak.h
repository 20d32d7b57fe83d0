// `oceanbox soak`: a scene simulated headless (no rendering) for a long time, with the
// state's invariants checked as it goes: finite fields and bodies, bounded heights, floating
// bodies afloat, flat memory.
#pragma once
#include "world/scene.h"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ob::game {

class Sandbox;

/// Arguments of `oceanbox soak SCENE --seconds S [--check-every N] [--stats F.json]`.
struct SoakOptions {
    double seconds = 3600.0;  ///< simulated seconds, > 0 (steps = seconds · step_hz, rounded)
    int checkEvery = 1;       ///< invariants every N steps, >= 1 (the last step is always checked)
    std::string stats;        ///< JSON summary ("" = none)
};

/// Bounds the soak holds the state to, from the scene's physics (see soakBounds).
struct SoakBounds {
    std::vector<float> cascadeHeight;  ///< |h| of each FFT cascade map, m: 8 σ of its t = 0 map (twice its Hs)
    float gerstnerAmplitude = 0.0f;    ///< Σ a_m of the Gerstner waves, m: their sum can never exceed it
    float ripple = 0.0f;               ///< |Vh| of the ripple patch, m: 4 × the largest stamp source (radius · SHR; an object's spheres summed, cannon balls and fish included)
    float surface = 0.0f;              ///< |y| of the composite surface, m: the three layers' bounds added
    float seaHs = 0.0f;                ///< significant wave height of the FFT cascades together, m (4 σ)
};

/// What a soak measured.
struct SoakReport {
    uint64_t steps = 0;
    double simulatedSeconds = 0.0;
    double wallSeconds = 0.0;
    std::vector<float> maxCascadeHeight;  ///< max |h| seen per cascade, m
    float maxRipple = 0.0f;               ///< max |Vh| seen, m
    float warmupRipple = 0.0f;            ///< max |Vh| seen in the warm-up, m
    float maxSurface = 0.0f;              ///< max |y| of the surface under the bodies, m
    float minFloatingDepth = std::numeric_limits<float>::infinity();  ///< lowest (centre − surface) of a floating body, m (inf: none)
    double rssStartMiB = 0.0;             ///< after the sandbox is built
    double rssWarmMiB = 0.0;              ///< after the warm-up (the first 60 simulated s, at most 1/10 of the run)
    double rssEndMiB = 0.0;
    double rssMaxMiB = 0.0;
};

/// The bounds for a freshly built sandbox (maps at t = 0).
SoakBounds soakBounds(Sandbox& sandbox);

/// Checks every invariant of the sandbox's current state against `bounds`, folding the
/// maxima into `report`. Throws ob::RuntimeError naming the step, the quantity and where
/// (cell, cascade, body) when one does not hold.
void checkSoakInvariants(Sandbox& sandbox, const SoakBounds& bounds, SoakReport& report);

/// Resident set size of this process (MiB), from /proc/self/statm; 0 where unreadable.
double residentMiB();

/// Runs the soak; returns 0, throws ob::RuntimeError at the first broken invariant (exit 1).
int soakCommand(const SceneDef& scene, const std::string& scenePath, const SoakOptions& options);

} // namespace ob::game
