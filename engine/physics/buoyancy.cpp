// Morison per probe sphere: Froude–Krylov buoyancy and inertia, drag, windage.
#include "physics/buoyancy.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace ob::physics {

float submergedSphereVolume(float radius, float depth) {
    float h = std::clamp(radius + depth, 0.0f, 2.0f * radius);
    return float(M_PI) * h * h * (3.0f * radius - h) / 3.0f;
}

namespace {

// A drag −c·r (c ≥ 0 in N·s/m, r the relative velocity) taken implicitly over dt for a mass m:
// backward Euler of m·dr/dt = −c·r gives −c/(1 + c·dt/m)·r, which slows r and never reverses it.
glm::vec3 implicitDrag(float c, glm::vec3 relative, float mass, float dt) {
    if (mass > 0.0f && dt > 0.0f) c /= 1.0f + c * dt / mass;
    return -c * relative;
}

} // namespace

ProbeForce probeForce(const PhysicsDef& def, const ProbeState& p) {
    ProbeForce out;
    out.point = p.centre;
    // The surface is locally a plane through surfaceHeight; depth measured vertically.
    const float depth = p.surfaceHeight - p.centre.y;
    const float volume = submergedSphereVolume(p.radius, depth);
    const float full = 4.0f / 3.0f * float(M_PI) * p.radius * p.radius * p.radius;
    const float disc = float(M_PI) * p.radius * p.radius;
    out.submergedFraction = volume / full;

    // Windage on the emerged part (horizontal wind; the body's own motion in still air).
    const float airArea = disc * (1.0f - out.submergedFraction);
    if (airArea > 0.0f && def.air_density > 0.0f) {
        const glm::vec3 relative = p.velocity - p.wind;
        const float c = 0.5f * def.air_density * def.air_drag * airArea * glm::length(relative);
        out.airForce = implicitDrag(c, relative, p.massShare, p.dt);
        out.force = out.airForce;
    }
    if (volume <= 0.0f) return out;

    // Froude–Krylov: −∇p/ρ = g·ŷ + Du/Dt in the accelerating water; plus the inertia C_a·Du/Dt.
    const float bound = accelerationBound(def);
    glm::vec3 accel = p.waterAcceleration;
    if (const float a = glm::length(accel); a > bound) accel *= bound / a;
    accel.x *= p.horizontalInertia;
    accel.z *= p.horizontalInertia;
    const glm::vec3 up = def.buoyancy_along_normal ? glm::normalize(p.surfaceNormal) : glm::vec3(0.0f, 1.0f, 0.0f);
    out.force += def.water_density * volume * (def.gravity * up + (1.0f + def.added_mass) * accel);
    out.addedMass = def.water_density * def.added_mass * volume;

    // Drag against the water's velocity, on the submerged part of the cross-section.
    const glm::vec3 relative = p.velocity - p.waterVelocity;
    const float area = disc * out.submergedFraction;
    const float c = def.linear_drag * area + 0.5f * def.water_density * def.quadratic_drag * area * glm::length(relative);
    out.force += implicitDrag(c, relative, p.massShare, p.dt);
    return out;
}

} // namespace ob::physics
