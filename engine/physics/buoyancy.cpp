// Archimedes and drag per probe sphere.
#include "physics/buoyancy.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace ob::physics {

float submergedSphereVolume(float radius, float depth) {
    float h = std::clamp(radius + depth, 0.0f, 2.0f * radius);
    return float(M_PI) * h * h * (3.0f * radius - h) / 3.0f;
}

ProbeForce probeForce(const PhysicsDef& def, const ProbeState& p) {
    ProbeForce out;
    out.point = p.centre;
    // The surface is locally a plane through surfaceHeight; depth measured vertically.
    float depth = p.surfaceHeight - p.centre.y;
    float volume = submergedSphereVolume(p.radius, depth);
    float full = 4.0f / 3.0f * float(M_PI) * p.radius * p.radius * p.radius;
    out.submergedFraction = volume / full;
    if (volume <= 0.0f) return out;
    glm::vec3 up = def.buoyancy_along_normal ? glm::normalize(p.surfaceNormal) : glm::vec3(0.0f, 1.0f, 0.0f);
    out.force = def.water_density * def.gravity * volume * up;
    // Drag against the water (moving vertically with the surface), on the submerged part.
    glm::vec3 relative = p.velocity - glm::vec3(0.0f, p.surfaceVelocity, 0.0f);
    float speed = glm::length(relative);
    float area = float(M_PI) * p.radius * p.radius * out.submergedFraction;
    out.force -= relative * (def.linear_drag * area + 0.5f * def.water_density * def.quadratic_drag * area * speed);
    return out;
}

} // namespace ob::physics
