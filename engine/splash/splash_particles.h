// Splash particles: drops thrown up where bodies cross the water surface, flown ballistically
// with linear drag (exact for any step), and handed back as landings the caller stamps into
// the ripple layer and the foam map. The CPU simulation is the reference. docs/splash_foam.md.
//
// Laws (g and ρ: the Def's environment, 9.81 m/s² and 1025 kg/m³ by default; an impact is a body of mass m, radius R, velocity v
// meeting a surface of unit normal n moving up at w):
//   normal speed   v_n = |(v − w·ŷ)·n|                                          m/s
//   energy         E   = ½·m·v_n²                                                J
//   Froude number  Fr  = v_n² / (g·R)
//   threshold      no drops when v_n < [splash] min_speed (a body resting on the water throws none)
//   drop count     N   = floor(emission_scale · 8 · sqrt(E / 1 J))   (then capped by max_particles)
//   crown height   H   = R · sqrt(Fr)          (m; the drag-free apex of the fastest drop)
//   crown speed    u_c = sqrt(2·g·H)
//   each drop      speed u = u_c·(0.5 + 0.5ξ), ξ uniform [0, 1); elevation above the horizon
//                  60°–80° (entry, a crown opening outward) or 75°–89° (exit, a plume), azimuth
//                  stratified round the ring of radius R about the body, launched at the surface;
//                  plus 0.3× the body's horizontal velocity; radius r = drop_size·(0.5 + ξ).
//   bow spray      a hull sphere moving at horizontal speed U > U_min = [splash] bow_speed throws
//                  emission_scale · 100 · (R / 1 m)² · (U/U_min − 1) drops per second, at 30°–60°
//                  to either side, speed 0.6·U·(0.5 + 0.5ξ), plus half the hull's velocity
//   wind spray     above U10 > U_s = [splash] spray_wind, breaking crests (points of area A each)
//                  throw emission_scale · 5 · (U10/U_s − 1) drops per second per m² of crest,
//                  at most [splash] spray_per_step a step; each from a random crest, downwind at
//                  (0.2 + 0.3ξ)·U10 within ±20° of the wind, up at (1 + 2ξ) m/s
//   flight         dv/dt = −g·ŷ − k·v (k = [splash] drag), integrated by its exact solution:
//                  v(t+Δt) = a·v − g·b·ŷ,  x(t+Δt) = x + b·v − g·c·ŷ,
//                  a = e^(−kΔt), b = (1 − a)/k, c = (Δt − b)/k   (k → 0: b = Δt, c = Δt²/2);
//                  wind spray drags against the air instead, dv/dt = −g·ŷ − k·(v − w), w = 0.75·U10
//                  (the log profile 1 m up, roughness 1 mm), by linearity the same step plus
//                  (1 − a)·w to v and (Δt − b)·w to x (splash drops fly still air: a short hop)
//   landing        a descending drop at or below the water height lands (removed, reported);
//                  on water that stays at the emission height every drop of an impact lands within
//                  T = 2·u_c/g of it (linear drag only shortens the flight); any drop airborne
//                  after [splash] max_life expires.
//   ripple stamp   a landing of mass m_d and speed s lowers Vh(t) of its ripple cell (area Δ²) by
//                  d = sqrt(2·ε·½·m_d·s² / (ρ·g·Δ²)), so the potential energy ½·ρ·g·Δ²·d² it adds
//                  is ε = [splash] ripple_energy of the drop's kinetic energy.
// Determinism: every random draw comes from one splitmix64 stream seeded by the scene's seed, in
// emission order; the flight is element-wise, so the bits do not depend on the worker count.
#pragma once
#include "splash/splash_def.h"
#include "water/water_query.h"

#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob {
class StateHasher;
}
namespace ob::interaction {
class RipplePatch;
}

namespace ob::splash {

/// Drops per √J of impact energy at emission_scale 1.
constexpr float DROPS_PER_SQRT_JOULE = 8.0f;
/// Bow spray drops per second per m² of hull radius² at U = 2·U_min, emission_scale 1.
constexpr float BOW_DROPS_PER_SECOND = 100.0f;
/// Fraction of the body's horizontal velocity an impact's drops carry.
constexpr float TANGENT_CARRY = 0.3f;
/// Wind spray drops per second per m² of breaking crest at U10 = 2·U_s, emission_scale 1.
constexpr float SPRAY_DROPS_PER_M2_SECOND = 5.0f;
/// The air the spray flies in, as a fraction of U10: the log profile 1 m above a sea of roughness 1 mm.
constexpr float SPRAY_AIR_FRACTION = 0.75f;

/// Which way a body crossed the surface.
enum class Crossing : uint8_t {
    None,   ///< no crossing this step
    Entry,  ///< the body's lowest point went from above the surface to at or below it
    Exit,   ///< the body's lowest point went from below the surface to above it (it left the water)
};

/// A body meeting the water surface (one bounding sphere), in world coordinates.
struct Impact {
    glm::vec3 centre{0.0f};           ///< body centre, m (drops start on the ring of radius R about (x, z))
    glm::vec3 velocity{0.0f};         ///< body velocity, m/s
    float radius = 0.0f;              ///< R, m, > 0
    float mass = 0.0f;                ///< m, kg, >= 0
    float surfaceHeight = 0.0f;       ///< y of the water under the centre, m (drops start there)
    glm::vec3 surfaceNormal{0, 1, 0}; ///< unit normal of the water there
    float surfaceVelocity = 0.0f;     ///< vertical velocity of the water there, m/s
    Crossing kind = Crossing::Entry;  ///< Entry: a crown; Exit: a plume shed as the body leaves
};

/// Tracks one sphere against the surface step by step and reports when it crosses it (the
/// emitters' trigger). The first update only records: a body spawned in or on the water never
/// reports, nor does one that stays in contact (a floating hull, a ball at rest).
class SurfaceCrossing {
public:
    /// Sphere centre y and radius, the water's y under it (m); returns the crossing of this step.
    Crossing update(float centreY, float radius, float surfaceY);

private:
    bool m_known = false;
    bool m_below = false;  // lowest point at or below the surface at the last update
};

/// A drop that came down on the water this step.
struct Landing {
    glm::vec3 position{0.0f};  ///< where it met the surface (x, water height, z), m
    glm::vec3 velocity{0.0f};  ///< its velocity then, m/s
    float radius = 0.0f;       ///< drop radius, m
    float mass = 0.0f;         ///< drop mass ρ·4/3·π·r³, kg
};

/// Normal speed v_n of an impact, m/s (see the laws above).
float impactNormalSpeed(const Impact& impact);
/// Drop count N of an impact before the capacity cap (0 below min_speed).
int impactDropCount(const Impact& impact, const SplashDef& def);
/// Crown height H = R·sqrt(Fr), m, under gravity g (m/s²).
float crownHeight(const Impact& impact, float gravity);
/// Crown speed u_c = sqrt(2·g·H), m/s, under gravity g (m/s²): no drop of the impact is launched faster upward.
float crownSpeed(const Impact& impact, float gravity);

/// Live drops as structure-of-arrays (one float array per quantity, index = drop), world metres.
class SplashParticles {
public:
    /// seed: the scene's seed ([sim] seed); equal seeds and calls give bit-identical states.
    SplashParticles(const SplashDef& def, uint64_t seed);

    /// Throws the drops of one impact (entry crown or exit plume); returns how many were added.
    int emitImpact(const Impact& impact);
    /// Bow spray of one hull sphere over a step of dt seconds (centre at the waterline, m;
    /// velocity m/s; radius m); returns how many drops were added (0 at or below bow_speed).
    int emitBowSpray(const glm::vec3& centre, const glm::vec3& velocity, float radius, float dt);

    /// Wind spray off breaking crests over a step of dt s: `crests` are world (x, z) points
    /// breaking now, each standing for `crestArea` m² of sea; wind is U10 (m/s, x and z); the
    /// launch height is read from `water`. Returns the drops added (0 at or below spray_wind).
    int emitWindSpray(std::span<const glm::vec2> crests, float crestArea, glm::vec2 wind, float dt,
                      const water::WaterQuery& water);

    /// Flies every drop dt seconds, then lands the descending drops at or below the water (read
    /// from `water`, only for drops below `ceiling`, an upper bound of the surface height in m:
    /// pass it to skip the queries of drops high above the sea) and expires those older than
    /// max_life. This step's landings replace the last step's (landings()).
    void step(float dt, const water::WaterQuery& water, float ceiling = 3.4e38f);

    /// The drops that landed in the last step, in drop order.
    std::span<const Landing> landings() const { return m_landings; }
    /// Live drops.
    int size() const { return int(m_x.size()); }
    /// Position and velocity arrays, size() each (m, m/s); radius (m) and age (s).
    std::span<const float> x() const { return m_x; }
    std::span<const float> y() const { return m_y; }
    std::span<const float> z() const { return m_z; }
    std::span<const float> vx() const { return m_vx; }
    std::span<const float> vy() const { return m_vy; }
    std::span<const float> vz() const { return m_vz; }
    std::span<const float> radius() const { return m_radius; }
    std::span<const float> age() const { return m_age; }

    /// Counters since construction.
    struct Stats {
        uint64_t emitted = 0;  ///< drops added
        uint64_t dropped = 0;  ///< drops not added because max_particles were alive
        uint64_t landed = 0;   ///< drops that landed
        uint64_t expired = 0;  ///< drops removed by max_life
        uint64_t spray = 0;    ///< of the added, wind spray
    };
    const Stats& stats() const { return m_stats; }
    const SplashDef& def() const { return m_def; }
    /// Changes the settings from the next call on (live drops stay).
    void setDef(const SplashDef& def) { m_def = def; }
    /// Removes every drop (the random stream goes on).
    void clear();

    /// Feeds every live drop, the random stream's state and the counters to h.
    void hash(StateHasher& h) const;

private:
    float uniform();  // next draw of the stream, [0, 1)
    bool push(const glm::vec3& p, const glm::vec3& v, float r, bool spray = false);
    void blowSpray(float dt, float a, float b);
    void removeDead();

    SplashDef m_def;
    uint64_t m_rng;
    std::vector<float> m_x, m_y, m_z, m_vx, m_vy, m_vz, m_age, m_radius;
    std::vector<uint8_t> m_spray;      // per drop: 1 = wind spray (flies in the air m_air)
    glm::vec2 m_air{0.0f};             // the air's velocity, m/s (x, z), at the last wind spray
    std::vector<uint8_t> m_dead;       // per drop, set by step() and cleared by removeDead()
    std::vector<int> m_candidates;     // step(): drops whose water height is read
    std::vector<glm::vec2> m_candidateXZ;  // their (x, z)
    std::vector<water::WaterSample> m_samples;  // the water under them
    std::vector<Landing> m_landings;
    Stats m_stats;
};

/// Stamps landings into the ripple layer (the ripple stamp law above, ε = energyFraction, g and ρ
/// the patch Def's environment): each
/// lowers Vh(t) of the interior cell nearest it (RipplePatch::addCrater: with ewave levels the same
/// volume on every coarse level that holds it); landings outside every level are skipped.
/// Returns the energy the law put in, Σ ε·½·m_d·s², J. A GPU patch takes them at its next step.
double stampLandings(interaction::RipplePatch& patch, std::span<const Landing> landings, float energyFraction);

} // namespace ob::splash
