// Surface current settings, section [currents] (docs/currents.md): a 2-D incompressible flow of
// the water's surface layer, stepped after Stam 1999, "Stable Fluids" (current_layer.h).
#pragma once
#include "core/schema.h"

#include <array>
#include <cstdint>
#include <vector>

namespace ob::currents {

/// What the layer's edge is to the flow (docs/currents.md#edges).
enum class CurrentEdge : uint8_t {
    Periodic,  ///< the patch is a torus for the pressure: what leaves one edge pushes on the opposite one
    Open,      ///< outflow: the pressure beyond the edge is the background's, so what leaves the patch is gone
};
constexpr std::array<const char*, 2> names(CurrentEdge) { return {"periodic", "open"}; }

/// A region where the flow is held towards a velocity ([[currents.sources]]): a river mouth or a
/// tidal inflow. Inside the disc the layer relaxes as u ← s + (u − s)·e^(−dt/time) (a one-cell
/// soft edge); the projection then turns the inflow into a divergence-free flow, so an inflow at
/// the patch's edge needs no outflow drawn by hand.
struct CurrentSource {
    glm::vec2 center{0.0f, 0.0f};    ///< world [x, z] of the disc's centre, m, each in [-1e5, 1e5]
    float radius = 10.0f;            ///< disc radius, m, [0.01, 1e4]
    glm::vec2 velocity{0.0f, 0.0f};  ///< the velocity the flow is held towards, [x, z] m/s, each in [-10, 10]
    float time = 10.0f;              ///< relaxation time towards it, s, [0.01, 1e6]
};

template <class V> void describe(V& v, CurrentSource& d) {
    v.field("center", d.center, range(-1e5, 1e5), "world [x, z] of the source disc's centre (m)");
    v.field("radius", d.radius, range(0.01, 1e4), "radius of the source disc (m)");
    v.field("velocity", d.velocity, range(-10, 10), "velocity the flow in the disc is held towards, [x, z] (m/s)");
    v.field("time", d.time, range(0.01, 1e6), "relaxation time towards that velocity (s)");
}

/// The surface current layer: a square grid of `resolution`² cells of `cell_size` m that follows
/// the camera's point in whole cells, carrying the horizontal momentum ρ·depth·u per area of a
/// layer `depth` m thick. The background flow is `uniform` plus the wind drift the layer tends to
/// (wind_drift·U10); departures from it (sources, bodies' impulses, walls) decay in decay_time.
struct CurrentsDef {
    bool enabled = true;                   ///< false: no current layer at all
    int resolution = 128;                  ///< cells a side, power of two in [16, 1024]
    float cell_size = 0.5f;                ///< Δ, m, [0.05, 100]: 128 × 0.5 m covers the default ripple patch (51 m) and
                                           ///< resolves the swirl of a stir of 0.6 m (a harbour basin: 2 m cells)
    float depth = 1.0f;                    ///< d, thickness of the layer that carries the momentum, m, [0.05, 1000]; the
                                           ///< draft of what floats: the water a small craft pushes and is pushed by
    glm::vec2 uniform{0.0f, 0.0f};         ///< background current (tide, river), [x, z] m/s, each in [-10, 10]
    float decay_time = 120.0f;             ///< e-folding time of the departure from the background by bottom friction and
                                           ///< mixing, s, [0, 1e6]; 0 = no decay. 120 s: a jet of a few m/s fades within
                                           ///< a few hundred metres of travel, as a harbour's wake and outflow plumes do
    float wind_drift = 0.03f;              ///< the drift the wind drives the surface at, fraction of U10, [0, 0.1] (Wu 1975: 3 %)
    float wind_time = 300.0f;              ///< relaxation time of the layer's drift towards wind_drift·U10, s, [1, 1e6].
                                           ///< The wind stress τ = ρ_a·C_D·U10² (ρ_a = 1.225 kg/m³, C_D = 1.3e-3) brings
                                           ///< a slab of thickness h to 0.03·U10 in t = 0.03·ρ·h/(ρ_a·C_D·U10): at
                                           ///< U10 = 10 m/s, 300 s for h ≈ 0.15 m, the wind-drift skin where Wu's 3 %
                                           ///< is measured; the whole 2 m layer would take ~3900 s (an hour). 300 s is
                                           ///< the skin's order, minutes, so a change of wind shows within a scene
    CurrentEdge edge = CurrentEdge::Periodic;  ///< "periodic" or "open" (an outflow edge: nothing wraps; docs/currents.md#edges)
    std::vector<CurrentSource> sources;    ///< [[currents.sources]]: discs the flow is held towards a velocity in; default none
    bool arrows = false;                   ///< the overlay draws the flow as arrows (drawn by the view)
};

template <class V> void describe(V& v, CurrentsDef& d) {
    v.field("enabled", d.enabled, "surface current layer on or off");
    v.field("resolution", d.resolution, powerOfTwo(16, 1024), "cells per side of the current grid");
    v.field("cell_size", d.cell_size, range(0.05, 100), "cell size of the current grid (m)");
    v.field("depth", d.depth, range(0.05, 1000), "thickness of the layer that carries the current's momentum (m)");
    v.field("uniform", d.uniform, range(-10, 10), "background current [x, z] (m/s)", LIVE);
    v.field("decay_time", d.decay_time, range(0, 1e6), "e-folding time of departures from the background flow (s); 0 = none", LIVE);
    v.field("wind_drift", d.wind_drift, range(0, 0.1), "surface drift the wind drives, fraction of U10 (Wu 1975: 0.03)", LIVE);
    v.field("wind_time", d.wind_time, range(1, 1e6), "relaxation time of the drift towards wind_drift·U10 (s)");
    v.field("edge", d.edge, "the grid's edge: periodic (the pressure wraps) or open (outflow: what leaves is gone)");
    v.list("sources", d.sources, "discs where the flow is held towards a velocity (center, radius, velocity, time)");
    v.field("arrows", d.arrows, "draw the current as arrows in the overlay", LIVE);
}

} // namespace ob::currents
