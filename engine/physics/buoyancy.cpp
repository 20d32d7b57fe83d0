// Morison per probe sphere: Froude–Krylov buoyancy and inertia, drag, windage.
#include "physics/buoyancy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
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
    const float depth = p.surfaceHeight - p.centre.y;
    const float volume = submergedSphereVolume(p.radius, depth);
    const float full = 4.0f / 3.0f * float(M_PI) * p.radius * p.radius * p.radius;
    const float disc = float(M_PI) * p.radius * p.radius;
    out.submergedFraction = volume / full;
    out.addedMass = def.water_density * def.added_mass * volume;

    // Windage on the emerged part, toward the wind (horizontal; the body's own motion in still air).
    const float airArea = disc * (1.0f - out.submergedFraction);
    if (airArea > 0.0f && def.air_density > 0.0f) {
        const float c = 0.5f * def.air_density * def.air_drag * airArea * glm::length(p.velocity - p.wind);
        out.airDamping = glm::vec3(c);
        out.airTarget = c * p.wind;
    }
    out.damping = out.airDamping;
    out.dampingTarget = out.airTarget;
    if (volume <= 0.0f) return out;

    // Froude–Krylov: −∇p/ρ = g·ŷ + Du/Dt in the accelerating water; plus the inertia C_a·Du/Dt.
    const float bound = accelerationBound(def);
    glm::vec3 accel = p.waterAcceleration;
    if (const float a = glm::length(accel); a > bound) accel *= bound / a;
    accel.x *= p.horizontalInertia;
    accel.z *= p.horizontalInertia;
    const glm::vec3 up = def.buoyancy_along_normal ? glm::normalize(p.surfaceNormal) : glm::vec3(0.0f, 1.0f, 0.0f);
    out.force = def.water_density * volume * (p.hydrostatic * def.gravity * up + (1.0f + def.added_mass) * accel);

    // Drag toward the water's velocity on the submerged part of the cross-section (horizontally
    // as far as horizontalInertia lets it), and the buoyancy's stiffness ρ·g·(its waterplane)
    // on the vertical motion through the surface, both taken implicitly (implicitDamping).
    const float area = disc * out.submergedFraction;
    const float c = def.linear_drag * area + 0.5f * def.water_density * def.quadratic_drag * area * glm::length(p.velocity - p.waterVelocity);
    const float d = std::clamp(depth, -p.radius, p.radius);
    const float k = p.hydrostatic * def.water_density * def.gravity * float(M_PI) * (p.radius * p.radius - d * d);
    const glm::vec3 water(p.horizontalInertia * c, c + k * p.dt, p.horizontalInertia * c);
    out.damping += water;
    out.dampingTarget += water * p.waterVelocity;
    return out;
}

namespace {

glm::mat3 cross(glm::vec3 r) { return glm::mat3(0.0f, r.z, -r.y, -r.z, 0.0f, r.x, r.y, -r.x, 0.0f); }  // [r]×, column-major

// Solves A·x = y for a 6 × 6 symmetric positive definite A (Gaussian elimination, partial pivoting).
std::array<double, 6> solve6(std::array<std::array<double, 7>, 6> a) {
    for (int c = 0; c < 6; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 6; ++r)
            if (std::abs(a[size_t(r)][size_t(c)]) > std::abs(a[size_t(pivot)][size_t(c)])) pivot = r;
        std::swap(a[size_t(c)], a[size_t(pivot)]);
        if (a[size_t(c)][size_t(c)] == 0.0) continue;
        for (int r = c + 1; r < 6; ++r) {
            const double f = a[size_t(r)][size_t(c)] / a[size_t(c)][size_t(c)];
            for (int k = c; k < 7; ++k) a[size_t(r)][size_t(k)] -= f * a[size_t(c)][size_t(k)];
        }
    }
    std::array<double, 6> x{};
    for (int r = 5; r >= 0; --r) {
        double sum = a[size_t(r)][6];
        for (int k = r + 1; k < 6; ++k) sum -= a[size_t(r)][size_t(k)] * x[size_t(k)];
        x[size_t(r)] = a[size_t(r)][size_t(r)] != 0.0 ? sum / a[size_t(r)][size_t(r)] : 0.0;
    }
    return x;
}

} // namespace

void implicitDamping(const BodyResponse& body, glm::vec3 force, glm::vec3 torque, float dt, std::span<ProbeForce> probes) {
    // M·Δv = dt·(F + ΣD_i), I·Δω = dt·(τ + Σ r_i × D_i), D_i = −C_i·(v_i + Δv − [r_i]×Δω) + b_i.
    glm::mat3 a11(0.0f), a12(0.0f), a21(0.0f), a22(0.0f);
    glm::vec3 y1 = force, y2 = torque;
    for (const ProbeForce& p : probes) {
        if (p.damping == glm::vec3(0.0f)) continue;
        const glm::vec3 r = p.point - body.centre;
        const glm::mat3 c(p.damping.x, 0, 0, 0, p.damping.y, 0, 0, 0, p.damping.z), rx = cross(r);
        a11 += c;
        a12 -= c * rx;
        a21 += rx * c;
        a22 -= rx * c * rx;
        const glm::vec3 free = p.dampingTarget - p.damping * (body.velocity + glm::cross(body.angularVelocity, r));
        y1 += free;
        y2 += glm::cross(r, free);
    }
    std::array<std::array<double, 7>, 6> a{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {  // glm is column-major: m[column][row]
            a[size_t(i)][size_t(j)] = dt * a11[j][i] + (i == j ? body.mass[i] : 0.0f);
            a[size_t(i)][size_t(j + 3)] = dt * a12[j][i];
            a[size_t(i + 3)][size_t(j)] = dt * a21[j][i];
            a[size_t(i + 3)][size_t(j + 3)] = dt * a22[j][i] + body.inertia[j][i];
        }
        a[size_t(i)][6] = dt * y1[i];
        a[size_t(i + 3)][6] = dt * y2[i];
    }
    const std::array<double, 6> x = solve6(a);
    const glm::vec3 dv = glm::vec3(x[0], x[1], x[2]), dw = glm::vec3(x[3], x[4], x[5]);
    for (ProbeForce& p : probes) {
        if (p.damping == glm::vec3(0.0f)) continue;
        const glm::vec3 v = body.velocity + dv + glm::cross(body.angularVelocity + dw, p.point - body.centre);
        const glm::vec3 air = p.airTarget - p.airDamping * v;
        p.force += p.dampingTarget - p.damping * v;
        p.airForce += air;
    }
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
