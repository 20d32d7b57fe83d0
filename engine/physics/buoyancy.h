// Water and air forces on a body from its probe spheres (no Bullet here), after Morison et al.
// (1950): Froude–Krylov buoyancy along the pressure gradient, the inertia of the accelerating
// water, drag against the water's full 3-D velocity, and windage on the emerged part.
#pragma once
#include "physics/physics_def.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>

namespace ob::physics {

/// Volume (m³) of a sphere of radius r below a plane when its centre is `depth` metres below
/// it (negative: above). The cap of height h = clamp(r + depth, 0, 2r): V = π h² (3r − h) / 3.
float submergedSphereVolume(float radius, float depth);

/// One probe sphere of a body, in world space this step.
struct ProbeState {
    glm::vec3 centre{0.0f};       ///< world centre, m
    float radius = 0.5f;          ///< m
    glm::vec3 velocity{0.0f};     ///< the body's velocity at the centre, m/s
    float surfaceHeight = 0.0f;   ///< water height under the centre, m
    glm::vec3 surfaceNormal{0.0f, 1.0f, 0.0f};
    glm::vec3 waterVelocity{0.0f};      ///< the water's velocity at the centre (WaterQuery::velocityAt), m/s
    glm::vec3 waterAcceleration{0.0f};  ///< its rate Du/Dt along the probe, m/s² (bounded by g: accelerationBound)
    glm::vec3 wind{0.0f};               ///< the air's velocity at the probe, m/s
    /// How much of the accelerating water's horizontal push the probe takes, [0, 1] (a ship's
    /// probes: 0, its hull model stands for its horizontal hydrodynamics; 1 otherwise).
    float horizontalInertia = 1.0f;
    /// How much of the hydrostatic buoyancy ρ·V·g the probe carries, [0, 1] (a hull's probes:
    /// 0, hullBuoyancy stands for it from the hull's own shape; 1 otherwise).
    float hydrostatic = 1.0f;
    float dt = 0.0f;                    ///< the step, s (the buoyancy's stiffness is taken as k·dt)
};

/// The forces on one probe, applied at `point`: the explicit part `force`, and the damping
/// D = −C·v' + b (C = diag(damping)) the body's implicit solve takes at the end of the step.
struct ProbeForce {
    glm::vec3 force{0.0f};        ///< N: the water's buoyancy and inertia (explicit); after implicitDamping, + D
    glm::vec3 airForce{0.0f};     ///< N: the air's part of `force` (windage), after implicitDamping
    glm::vec3 point{0.0f};        ///< world point of application (the probe centre), m
    float submergedFraction = 0.0f;  ///< 0..1 of the probe's volume under the surface
    float addedMass = 0.0f;          ///< ρ·C_a·V_submerged, kg: the water the probe drags along (PhysicsDef::added_mass)
    glm::vec3 damping{0.0f};      ///< C, N·s/m per axis: water drag + air drag + the buoyancy's stiffness k·dt (vertical)
    glm::vec3 dampingTarget{0.0f};  ///< b, N: Σ c·(the velocity each drag pulls toward), the water's, the wind's
    glm::vec3 airDamping{0.0f};   ///< the air's part of C and b: c_a, and c_a·wind
    glm::vec3 airTarget{0.0f};
};

/// A rigid body's response over a step, for implicitDamping: its effective mass per world axis
/// (with the added mass where it applies), its effective inertia tensor (world), its centre
/// and velocities.
struct BodyResponse {
    glm::vec3 mass{1.0f};          ///< kg per world axis
    glm::mat3 inertia{1.0f};       ///< kg·m², world
    glm::vec3 centre{0.0f};        ///< m
    glm::vec3 velocity{0.0f};      ///< m/s
    glm::vec3 angularVelocity{0.0f};  ///< rad/s
};

/// Backward Euler of the body's damping: solves the 6 × 6 system for the step's change of
/// velocity and angular velocity with every probe's damping D_i = −C_i·v_i' + b_i taken at the
/// end of the step (v_i' the probe point's velocity then), under the explicit force and torque
/// (gravity included), and adds each D_i to its probe's force (its air part to airForce too).
/// Stable for any coefficients and step: the drags cannot reverse a relative motion, the
/// buoyancy's stiffness cannot pump the heave, whatever a body's density, size or the step rate.
void implicitDamping(const BodyResponse& body, glm::vec3 force, glm::vec3 torque, float dt, std::span<ProbeForce> probes);

/// A wave's particle acceleration cannot exceed g before it breaks (a·ω² ≤ g): the bound on
/// Du/Dt the caller's estimate is clamped to, m/s².
inline float accelerationBound(const PhysicsDef& def) { return def.gravity; }

/// Per probe, V the submerged volume, A its share of the cross-section (π r² times the
/// submerged fraction), ρ the water's, u the water's velocity, v the probe's:
///   Froude–Krylov + inertia  ρ·V·(g·ŷ + (1 + C_a)·Du/Dt)   (ŷ → the surface normal with buoyancy_along_normal)
///   drag                     −(linear_drag·A + ½ρ·C_d·A·|v − u|)·(v − u)
///   windage                  ½ρ_a·C_da·A_air·|w − v|·(w − v), A_air = π r² − A, horizontal wind w
/// The added mass's other half, −ρ·V·C_a·dv/dt, depends on the body's own acceleration: the
/// caller adds `addedMass` to the body's inertia (implicitly, see sim/objects.cpp).
ProbeForce probeForce(const PhysicsDef& def, const ProbeState& probe);

/// A box hull (beam x, depth y, length z, m) cut into cells.x × cells.y columns running keel to
/// deck; its nodes are the cells' corners on the hull's plan, (cells.x + 1)·(cells.y + 1) of them.
struct HullGrid {
    glm::vec3 size{3.0f, 1.5f, 10.0f};
    glm::ivec2 cells{4, 8};
    int nodeCount() const { return (cells.x + 1) * (cells.y + 1); }
    /// Node n's plan position (x across, z along), hull frame, m; nodes run along x fastest.
    glm::vec2 node(int n) const;
};

/// The hull's hydrostatic buoyancy and where it acts.
struct HullBuoyancy {
    glm::vec3 force{0.0f};   ///< N, ρ·g·V straight up
    glm::vec3 point{0.0f};   ///< the centre of buoyancy, world, m
    float volume = 0.0f;     ///< submerged volume V, m³
};

/// The buoyancy of a box hull at a pose over water whose height above each node is
/// nodeHeights[n] (m): each column is wet from its keel (its deck, capsized) to where the water
/// plane through the nodes crosses it, integrated with 2 × 2 Gauss points per cell — exact for a
/// plane surface, so the hull's centre of buoyancy moves with heel as the box's own waterplane
/// makes it: GM = KB + BM − KG with BM = I/V, I = L·B³/12 (not the probe spheres' lattice).
HullBuoyancy hullBuoyancy(const PhysicsDef& def, const HullGrid& hull, glm::vec3 position, const glm::quat& rotation,
                          std::span<const float> nodeHeights);

} // namespace ob::physics
