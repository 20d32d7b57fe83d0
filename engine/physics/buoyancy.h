// Water forces on a body from its probe spheres (no Bullet here): Archimedes on each
// sphere's submerged cap, linear and quadratic drag against the water's vertical motion.
#pragma once
#include "physics/physics_def.h"

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
    float surfaceVelocity = 0.0f; ///< vertical velocity of the water there, m/s
};

/// The water's force on one probe, applied at `point`.
struct ProbeForce {
    glm::vec3 force{0.0f};   ///< N
    glm::vec3 point{0.0f};   ///< world point of application (the probe centre), m
    float submergedFraction = 0.0f;  ///< 0..1 of the probe's volume under the surface
};

/// Buoyancy ρ·g·V (up, or along the surface normal) plus drag against the relative velocity
/// (v − w·ŷ, w the water's vertical velocity), scaled by the submerged fraction.
ProbeForce probeForce(const PhysicsDef& def, const ProbeState& probe);

} // namespace ob::physics
