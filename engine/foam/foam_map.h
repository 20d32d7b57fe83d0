// Persistent foam: a coverage map in world space over the ripple patch, advected with the
// surface's horizontal velocity, fed by six sources, decaying exponentially. docs/splash_foam.md.
//
//   ∂f/∂t + u·∇f = −f/τ + S,  f ∈ [0, 1] the coverage, τ = [foam] decay_s, u the surface's
//   horizontal velocity, S the sources.
//
// FoamMap is the facade the sandbox holds; its parts, each with its laws in its header:
//   storage    the coverage, n×n samples Δ = extent/n apart, sample (i, j) at grid().origin() +
//              (i, j)·Δ (i along x, j along z; row-major, index j·n + i); it scrolls in whole
//              samples (centerOn, core/scrolling_grid.h), like the ripple patch, so foam stays put
//              in the world
//   sources    foam_sources.h: (a) whitecaps, (b) steep ripples, (c) drops, (d)–(f) a hull's wake,
//              turbulent wake and bow wave
//   flow       foam_flow.h: the velocity, still, uniform, per sample or from a grid of nodes fixed
//              in the world, which update() refreshes from the water; plus the wind's drift and streak
//              cells (WindFlow), which update() sets from the wind
//   transport  foam_transport.h: the semi-Lagrangian step and exact decay
// update() is the whole step in one sweep over the map: sources (a), (b), then the step, rows of
// both formed as it goes.
#pragma once
#include "core/scrolling_grid.h"
#include "foam/foam_def.h"
#include "foam/foam_flow.h"
#include "foam/foam_sources.h"
#include "foam/foam_transport.h"

#include <optional>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob {
class StateHasher;
}

namespace ob::foam {

/// The foam coverage map (see the parts above).
class FoamMap {
public:
    /// A map of def.resolution² samples over a square of side `extent` metres (the caller resolves
    /// def.extent_m) centred on the sample nearest `centre` (world x, z). Coverage starts at 0, the
    /// flow still.
    FoamMap(const FoamDef& def, float extent, glm::vec2 centre = glm::vec2(0.0f));

    /// Where the map stands: n = grid().n samples a side, grid().cell metres apart.
    const ScrollingGrid& grid() const { return m_grid; }
    /// Moves the map so its centre is the sample nearest `worldCentre` (scrolls the coverage, new
    /// samples 0; the flow follows).
    void centerOn(glm::vec2 worldCentre);

    /// Coverage at world (x, z), bilinear between samples, 0 outside the map: "is there foam here".
    float sample(float x, float z) const;
    /// Coverage of every sample, row-major (index j·n + i), [0, 1]; writable (tests, tools).
    std::span<float> coverage() { return m_f; }
    std::span<const float> coverage() const { return m_f; }
    /// Mean coverage over the map.
    double mean() const;

    /// The velocity it moves with; set it here, or let update() take it from the water.
    FoamFlow& flow() { return m_flow; }
    const FoamFlow& flow() const { return m_flow; }

    // --- sources (laws in foam_sources.h), each clamped to coverage 1
    /// (a) whitecaps and (b) steep ripples of `in` (its water is not read): update() without the step.
    void addSources(const FoamInputs& in, float dt);
    /// (c) landed splash drops.
    void addLandings(std::span<const splash::Landing> landings) { foam::addLandings(m_def, cells(), landings); }
    /// (d) one hull sphere: centre (m), velocity (m/s; its horizontal part counts), radius (m).
    void addWake(const glm::vec3& centre, const glm::vec3& velocity, float radius, float dt) {
        foam::addWake(m_def, cells(), centre, velocity, radius, dt);
    }
    /// (e) one segment of a stern's track (world x, z, m, older end first), of age a (s), radius R (m).
    void addWakeTrail(glm::vec2 from, glm::vec2 to, float age, float radius, float dt) {
        foam::addWakeTrail(m_def, cells(), from, to, age, radius, dt);
    }
    /// (f) a bow sphere's breaking bow wave, strength q = min(1, U/U_b − 1) (nothing when ≤ 0).
    void addBowWave(const glm::vec3& centre, const glm::vec3& velocity, float radius, float strength, float dt) {
        foam::addBowWave(m_def, cells(), centre, velocity, radius, strength, dt);
    }

    /// Advects by the flow and decays over dt seconds.
    void step(float dt);
    /// One whole update over dt: the flow from in.water (FoamFlow::refresh; none: as set last),
    /// then sources (a), (b) and the step in one sweep where the flow allows it. The same bits as
    /// addSources(in, dt), then step(dt). The same as prepare(in, dt), then sweep().
    void update(const FoamInputs& in, float dt);
    /// update()'s first half, which reads the water: the flow refreshed, the wind set, the sources'
    /// tables made (whitecaps() is this update's from here on). copyInputs: `in`'s Jacobian and the
    /// ripple heights are copied, so sweep() reads nothing of the caller's; else they must stay as
    /// they are until sweep() returns.
    void prepare(const FoamInputs& in, float dt, bool copyInputs);
    /// update()'s second half, the sweep over the map: reads only the map, its flow and what
    /// prepare() made, and writes only the map, so with copied inputs it may run on another thread
    /// while the water moves on ([sim] pipelined). Nothing without a prepare().
    void sweep();

    /// The wind's part of the foam's velocity for wind U10 (m/s) blowing toward `direction` over
    /// a sea of surface Stokes drift `stokes` (m/s): drift wind_drift·U10·ŵ + stokes, streak cells
    /// of speed streak_speed·U10 and spacing streak_spacing_m (foam_flow.h, WindFlow). update()
    /// sets it from its inputs; step() moves with the last one set.
    WindFlow windFlow(float windSpeed, glm::vec2 direction, glm::vec2 stokes) const;

    /// Source (a)'s law at the last update or addSources (rate 0: none yet, or no whitecaps).
    const WhitecapLaw& whitecaps() const { return m_whitecaps; }

    const FoamDef& def() const { return m_def; }
    /// Changes the weights, decay and flow settings from the next call on (resolution stays).
    void setDef(const FoamDef& def);
    /// Feeds the coverage and the map's placement to h.
    void hash(StateHasher& h) const;

private:
    CoverageCells cells() { return CoverageCells{m_grid, m_f}; }

    FoamDef m_def;
    ScrollingGrid m_grid;     // where it stands
    std::vector<float> m_f;   // coverage, grid.n² row-major
    FoamFlow m_flow;
    FoamTransport m_transport;
    double m_time = 0.0;  // s of update() steps so far: the streak cells' phases (FoamFlow::setWindTime)
    WhitecapLaw m_whitecaps;
    std::optional<RowSources> m_sources;  // prepare()'s tables, until sweep()
    std::vector<float> m_jacobianCopy, m_rippleCopy;  // prepare()'s copies of its inputs (copyInputs)
    float m_sweepDt = 0.0f;               // prepare()'s dt, s
};

} // namespace ob::foam
