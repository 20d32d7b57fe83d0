// Spectral ocean settings, section [ocean]: one field per scene key (docs/references.md#spectral-ocean; [Lee2007] §2.1,
// [CodingTower]). Formulas behind each key: engine/ocean/spectrum.h.
#pragma once
#include "core/backend.h"
#include "core/schema.h"
#include "environment/environment_def.h"

#include <cstdint>
#include <string>
#include <glm/vec2.hpp>

namespace ob::ocean {

/// Which closed form the spectrum Ph(K) follows (engine/ocean/spectrum.h).
enum class SpectrumKind : uint8_t { Phillips, Jonswap };
constexpr std::array<const char*, 2> names(SpectrumKind) { return {"phillips", "jonswap"}; }

/// The wind-driven FFT ocean (Tessendorf): spectrum, grid, cascades, time evolution.
struct OceanDef {
    Backend backend = Backend::Auto;   ///< where the FFT runs: "auto" (gpu on a hardware GPU, else cpu) | "cpu" (FFTW) | "gpu"
    SpectrumKind spectrum = SpectrumKind::Phillips; ///< "phillips" (SPEC eq. 5) | "jonswap" (Hasselmann 1973, fetch-limited, cos² spreading)
    int resolution = 256;              ///< N, grid points per side of every cascade; power of two in [16, 2048]
    float patch_size = 250.0f;         ///< L, side of the first (largest) cascade's periodic tile, metres, [1, 100000]
    float amplitude = 0.0009f;         ///< A, dimensionless Phillips constant, [0, 1]; eq. 5 is applied with A·(2π/L)² per mode, so heights do not depend on N or L; 0.0009 gives the Pierson–Moskowitz Hs ≈ 0.21·V²/g (unused by jonswap)
    float wind_speed = 10.0f;          ///< V, wind speed 10 m above the sea, m/s, [0, 60]; sets L_w = V²/g, the largest wave
    glm::vec2 wind_direction{1.0f, 0.0f}; ///< direction the wind blows toward, [x, z] in the water plane; any non-zero vector (normalised on use)
    float small_wave_cutoff = 0.0f;    ///< l, metres, [0, 100]: waves shorter than ~l are damped by exp(−k²l²); 0 = auto, l = 0.001·V²/g ([CodingTower])
    float choppiness = 1.0f;           ///< c, horizontal displacement strength, [0, 10]: points move to X + λ·D with λ = −c (SPEC eq. 7: λ < 0 sharpens crests); 0 = no displacement
    std::uint64_t seed = 1;            ///< seed of the Gaussian noise ξ (eq. 4); equal seeds give equal seas at any resolution
    float gravity = environment::STANDARD_ENVIRONMENT.gravity;             ///< g, m/s², > 0; dispersion ω = sqrt(g·k) (eq. 3): environment.gravity, set when the scene is built (not a key)
    int cascades = 1;                  ///< number of tiles, [1, 4]; cascade c has side L/φ^(2c) (φ = golden ratio, never commensurate) and its own band of k
    float fetch = 100000.0f;           ///< F, JONSWAP fetch: distance the wind has blown over water, metres, [100, 10000000]
    float peak_enhancement = 3.3f;     ///< γ, JONSWAP peak enhancement factor, [1, 10] (1 = Pierson–Moskowitz shape)
};

template <class V> void describe(V& v, OceanDef& d) {
    v.field("backend", d.backend, "where the ocean FFT runs");
    v.field("spectrum", d.spectrum, "wave spectrum: Phillips (eq. 5) or JONSWAP");
    v.field("resolution", d.resolution, powerOfTwo(16, 2048), "grid points per side (N); memory grows as N² (every grid of a scene at its maximum: ~5.6 GB)");
    v.field("patch_size", d.patch_size, range(1, 100000), "side of the largest tile, metres (L)");
    v.field("amplitude", d.amplitude, range(0, 1), "Phillips constant A (dimensionless)", LIVE);
    v.field("wind_speed", d.wind_speed, range(0, 60), "wind speed at 10 m, m/s (V)", LIVE);
    v.field("wind_direction", d.wind_direction, direction(), "direction the wind blows toward, [x, z]", LIVE);
    v.field("small_wave_cutoff", d.small_wave_cutoff, range(0, 100), "damping length l of short waves, metres; 0 = 0.001·V²/g", LIVE);
    v.field("choppiness", d.choppiness, range(0, 10), "horizontal displacement strength (λ = −choppiness)", LIVE);
    v.field("seed", d.seed, "seed of the spectrum noise");
    if constexpr (requires { v.refuse("", std::string()); }) v.refuse("gravity", environment::movedHere("gravity"));
    v.field("cascades", d.cascades, range(1, 4), "number of tiles of sizes L/φ^(2c)");
    v.field("fetch", d.fetch, range(100, 10000000), "JONSWAP fetch, metres", LIVE);
    v.field("peak_enhancement", d.peak_enhancement, range(1, 10), "JONSWAP peak enhancement γ", LIVE);
}

} // namespace ob::ocean
