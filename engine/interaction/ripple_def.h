// Interactive ripple layer settings, section [ripples] (docs/references.md#ripple-layer; [Kang2008] §III–V): the keys
// every solver reads, and each solver's own (its Def, interaction/<model>/, a base of RippleDef).
#pragma once
#include "core/schema.h"

#include "core/backend.h"
#include "environment/environment_def.h"
#include "interaction/ripple_solvers.h"

#include <string_view>

namespace ob::interaction {

/// Which solver steps the patch: an index into RippleModels, its words the solvers' NAMEs
/// ("kang2008": [Kang2008] eq. 1–2, the paper's scenes and benches; "ewave": dispersive water
/// waves, every Fourier mode at its own speed, docs/references.md#dispersive-ripples).
enum class RippleModel : uint8_t {};
constexpr std::array<const char*, RippleModels::COUNT> names(RippleModel) { return RippleModels::NAMES; }

/// The model whose word is `name` (a compile error when no solver has it).
consteval RippleModel rippleModel(std::string_view name) {
    for (std::size_t i = 0; i < RippleModels::COUNT; ++i)
        if (name == RippleModels::NAMES[i]) return RippleModel(i);
    throw "no ripple solver has this name";
}

/// What happens to waves at the patch edge.
enum class RippleBoundary : uint8_t {
    Fixed,      ///< the outer ring of cells is held at 0: waves reflect off it
    Absorbing,  ///< a sponge band inside the ring damps the waves, so they leave the patch
    Periodic,   ///< ewave only: the transform's own torus, waves leave one side and come back on the other
};
constexpr std::array<const char*, 3> names(RippleBoundary) { return {"fixed", "absorbing", "periodic"}; }

/// Where the patch is.
enum class RippleFollow : uint8_t {
    Fixed,   ///< at the Def's centre
    Camera,  ///< scrolls in whole cells under the camera
    Target,  ///< under the point the camera looks at (a followed ship)
    Ship,    ///< under the ship the camera's `follow` names ("" = the player's ship, else the first), wherever the camera is
};
constexpr std::array<const char*, 4> names(RippleFollow) { return {"fixed", "camera", "target", "ship"}; }

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

/// The ripple patch: a height field in a square of the world that objects disturb. Every
/// solver's own keys (Kang2008Def::damping, EWaveDef::decay_time, …) are inherited fields,
/// read whatever the model (a scene may keep another model's key).
struct RippleDef : RippleModels::Defs {
    bool enabled = true;                     ///< false: no ripple layer at all
    RippleModel model = rippleModel("ewave");  ///< a solver's NAME: "kang2008" (the paper's scenes) or "ewave"
    Backend backend = Backend::Auto;         ///< "cpu", "gpu" (compute shaders; either model, ewave up to 2048²), "auto": on a
                                             ///< hardware GPU the faster as measured there (kept per machine), else cpu
    int resolution = 256;                    ///< N, cells per side; power of two in [16, 4096]
    float cell_size = 0.25f;                 ///< Δ, metres per cell, [0.01, 100]
    int levels = 1;                          ///< nested grids, [1, 4]: level L has the same N, cells 4^L × cell_size and steps every
                                             ///< 4^L-th frame (interaction/ripple_levels.h, docs/ewave.md#levels); 1 = one grid. A
                                             ///< model that cannot be nested (RippleSolver::levelRefusal: kang2008) refuses > 1
    RippleBoundary boundary = RippleBoundary::Absorbing;  ///< "fixed", "absorbing" or "periodic" (ewave only, for tests)
    int sponge_width = 32;                   ///< absorbing band width, cells, [1, 512]; 32 reflects ≤ 5% of a ring's amplitude
    RippleFollow follow = RippleFollow::Fixed;  ///< "fixed" at `center`, "camera", "target" or "ship"
    glm::vec2 center{0.0f, 0.0f};            ///< patch centre when fixed, world [x, z] m
    bool hulls_obstruct = true;              ///< ships' hulls obstruct the layer, holding its water at their hollow (ewave; kang2008 ignores it; docs/ewave.md#hulls)
    RippleReferenceDef reference;            ///< [ripples.reference]: object B of eq. 6
    environment::EnvironmentDef environment; ///< g, ρ, σ of the waves: the scene's [environment], set when it is built (not a key)
};

template <class V> void describe(V& v, RippleDef& d) {
    v.field("enabled", d.enabled, "ripple layer on or off");
    v.field("model", d.model,
            "kang2008: [Kang2008] eq. 1-2 (the paper; a height field: vertical water velocity only, no horizontal); "
            "ewave: dispersive water waves (exact per Fourier mode; vertical and horizontal surface velocity)");
    v.field("backend", d.backend, "where the ripple step runs (either model; ewave on the GPU up to 2048 cells per side)");
    v.field("resolution", d.resolution, powerOfTwo(16, 4096), "cells per side (N)");
    v.field("cell_size", d.cell_size, range(0.01, 100), "metres per cell");
    // Each solver's keys, in the table's order, as fields of this table (not v.fields: they
    // are [ripples] keys like the others, for every visitor, the timeline's live set included).
    RippleModels::forEach([&]<class Model>() { describe(v, static_cast<typename Model::Def&>(d)); });
    v.field("levels", d.levels, range(1, 4),
            "ewave: nested grids of the same resolution, cells 4x coarser each (1 = one grid; docs/ewave.md#levels)");
    v.field("boundary", d.boundary, "border: fixed (reflects), absorbing (sponge) or periodic (ewave only)");
    v.field("sponge_width", d.sponge_width, range(1, 512), "absorbing band width (cells)");
    v.field("follow", d.follow, "patch stays at center, follows the camera, the point it looks at, or the ship the camera's follow names");
    v.field("center", d.center, any(), "patch centre when fixed, world [x, z] m");
    v.field("hulls_obstruct", d.hulls_obstruct,
            "ships' hulls obstruct the ripples, holding the water inside them at their hollow and pushing it aside (ewave; kang2008 ignores it)");
    v.section("reference", d.reference);
}

/// The checks across [ripples] keys of the Def's model (its keys read and in range).
std::vector<RippleDefError> validate(const RippleDef& def);

} // namespace ob::interaction
