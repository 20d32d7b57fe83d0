// Morison per probe sphere: Froude–Krylov buoyancy and inertia, drag, windage.
#include "physics/buoyancy.h"

#include <algorithm>
#include <cmath>
#include <vector>
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
    out.force += def.water_density * volume * (p.hydrostatic * def.gravity * up + (1.0f + def.added_mass) * accel);
    out.addedMass = def.water_density * def.added_mass * volume;

    // Drag against the water's velocity, on the submerged part of the cross-section.
    const glm::vec3 relative = p.velocity - p.waterVelocity;
    const float area = disc * out.submergedFraction;
    const float c = def.linear_drag * area + 0.5f * def.water_density * def.quadratic_drag * area * glm::length(relative);
    out.force += implicitDrag(c, relative, p.massShare, p.dt);
    return out;
}

glm::vec2 HullGrid::node(int n) const {
    const int i = n % (cells.x + 1), j = n / (cells.x + 1);
    return {size.x * (float(i) / float(cells.x) - 0.5f), size.z * (float(j) / float(cells.y) - 0.5f)};
}

HullBuoyancy hullBuoyancy(const PhysicsDef& def, const HullGrid& hull, glm::vec3 position, const glm::quat& rotation,
                          std::span<const float> nodeHeights) {
    // The world's up in the hull's frame: a point (x, y, z) of the hull is at world height
    // P.y + r·(x, y, z), so the water plane crosses the column (x, z) at local y
    // w = (h − P.y − r.x·x − r.z·z)/r.y, linear in x and z.
    const glm::vec3 r = glm::conjugate(rotation) * glm::vec3(0.0f, 1.0f, 0.0f);
    const float half = 0.5f * hull.size.y;
    const float ry = std::abs(r.y) < 1e-4f ? std::copysign(1e-4f, r.y) : r.y;  // on its side: columns wholly in or out
    std::vector<float> waterline(nodeHeights.size());
    for (size_t n = 0; n < nodeHeights.size(); ++n) {
        const glm::vec2 q = hull.node(int(n));
        waterline[n] = std::clamp((nodeHeights[n] - position.y - r.x * q.x - r.z * q.y) / ry, -2.0f * half, 2.0f * half);
    }
    // Per Gauss point: the wet part of the column is [−D/2, w] upright, [w, D/2] capsized.
    const float g = 0.5f / std::sqrt(3.0f);
    const float weight = hull.size.x * hull.size.z / float(4 * hull.cells.x * hull.cells.y);
    const int row = hull.cells.x + 1;
    float volume = 0.0f;
    glm::vec3 moment(0.0f);
    for (int j = 0; j < hull.cells.y; ++j)
        for (int i = 0; i < hull.cells.x; ++i) {
            const int n = j * row + i;
            const float w00 = waterline[size_t(n)], w10 = waterline[size_t(n + 1)], w01 = waterline[size_t(n + row)],
                        w11 = waterline[size_t(n + row + 1)];
            const glm::vec2 lo = hull.node(n), hi = hull.node(n + row + 1);
            for (float u : {0.5f - g, 0.5f + g})
                for (float v : {0.5f - g, 0.5f + g}) {
                    const float w = (1 - u) * (1 - v) * w00 + u * (1 - v) * w10 + (1 - u) * v * w01 + u * v * w11;
                    const float wet = std::clamp(r.y > 0.0f ? w + half : half - w, 0.0f, 2.0f * half);
                    const float y = r.y > 0.0f ? -half + 0.5f * wet : half - 0.5f * wet;
                    volume += weight * wet;
                    moment += weight * wet * glm::vec3(glm::mix(lo.x, hi.x, u), y, glm::mix(lo.y, hi.y, v));
                }
        }
    HullBuoyancy out;
    out.volume = volume;
    out.point = position + rotation * (volume > 0.0f ? moment / volume : glm::vec3(0.0f));
    out.force = glm::vec3(0.0f, def.water_density * def.gravity * volume, 0.0f);
    return out;
}

} // namespace ob::physics
