// Interactive ripple layer settings, section [ripples] (SPEC §2.5; seed 001 §III–V).
#pragma once
#include "core/schema.h"

#include <string>

namespace ob::interaction {

/// Eq. 6 reference object B, section [ripples.reference].
struct RippleReferenceDef {
    float weight = 10.0f;  ///< Bw, kg, > 0
    float speed = 5.0f;    ///< Bv, m/s, > 0
    float size = 0.5f;     ///< Bs, radius, m, > 0
};

template <class V> void describe(V& v, RippleReferenceDef& d) {
    v.field("weight", d.weight, range(1e-6, 1e9), "reference weight Bw (kg)");
    v.field("speed", d.speed, range(1e-6, 1e6), "reference speed Bv (m/s)");
    v.field("size", d.size, range(1e-6, 1e6), "reference size Bs (m)");
}

/// The ripple patch: a height field in a square of the world that objects disturb.
struct RippleDef {
    bool enabled = true;                 ///< false: no ripple layer at all
    std::string model = "ewave";         ///< "kang2008": seed 001 eq. 1–2 (the paper's scenes); "ewave": dispersive
                                         ///< water waves, every mode at its own speed (SPEC §2.5b)
    std::string backend = "auto";        ///< "cpu", "gpu" (compute shaders; either model, ewave up to 2048²), "auto": gpu on a
                                         ///< hardware GPU from 2048² cells, else cpu
    int resolution = 256;                ///< N, cells per side; power of two in [16, 4096]
    float cell_size = 0.25f;             ///< Δ, metres per cell, [0.01, 100]
    float damping = 0.95f;               ///< kang2008: DF of eq. 2, [0, 1]: 0 kills a wave next step, 1 never damps
    float decay_time = 3.0f;             ///< ewave: e-folding time of every wave's amplitude, s, [0, 1e6]; 0 = no decay
    float viscosity = 1.0e-3f;           ///< ewave: effective viscosity, m²/s, [0, 10]: a wave of wavenumber k also
                                         ///< decays as exp(−2νk²t) (short waves first); 0 = none
    std::string boundary = "absorbing";  ///< "fixed" (border held at 0, reflects), "absorbing" (sponge band), or
                                         ///< "periodic" (ewave only: the transform's torus, for tests)
    int sponge_width = 32;               ///< absorbing band width, cells, [1, 512]; 32 reflects ≤ 5% of a ring's amplitude
    std::string follow = "fixed";        ///< "fixed" at `center`; "camera": scrolls in whole cells under the camera;
                                         ///< "target": under the point the camera looks at (a followed ship)
    glm::vec2 center{0.0f, 0.0f};        ///< patch centre when fixed, world [x, z] m
    RippleReferenceDef reference;        ///< [ripples.reference]: object B of eq. 6
};

template <class V> void describe(V& v, RippleDef& d) {
    v.field("enabled", d.enabled, "ripple layer on or off");
    v.field("model", d.model, Choices{"kang2008", "ewave"},
            "kang2008: seed 001 eq. 1-2 (the paper); ewave: dispersive water waves (exact per Fourier mode)");
    v.field("backend", d.backend, Choices{"auto", "cpu", "gpu"}, "where the ripple step runs (either model; ewave on the GPU up to 2048 cells per side)");
    v.field("resolution", d.resolution, powerOfTwo(16, 4096), "cells per side (N)");
    v.field("cell_size", d.cell_size, range(0.01, 100), "metres per cell");
    v.field("damping", d.damping, range(0, 1), "kang2008: damping factor DF (eq. 2)");
    v.field("decay_time", d.decay_time, range(0, 1e6), "ewave: e-folding time of a wave's amplitude (s; 0 = none)");
    v.field("viscosity", d.viscosity, range(0, 10), "ewave: effective viscosity, damps short waves (m2/s; 0 = none)");
    v.field("boundary", d.boundary, Choices{"fixed", "absorbing", "periodic"},
            "border: fixed (reflects), absorbing (sponge) or periodic (ewave only)");
    v.field("sponge_width", d.sponge_width, range(1, 512), "absorbing band width (cells)");
    v.field("follow", d.follow, Choices{"fixed", "camera", "target"},
            "patch stays at center, follows the camera, or the point it looks at");
    v.field("center", d.center, any(), "patch centre when fixed, world [x, z] m");
    v.section("reference", d.reference);
}

} // namespace ob::interaction
