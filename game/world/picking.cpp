// Picking: pixel → ray, ray → water (march, then bisection), ray → body (Bullet) or fish.
#include "world/picking.h"

#include "behaviours/fish.h"
#include "physics/physics_world.h"
#include "sim/objects.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace ob::game {

Ray pixelRay(const gfx::CameraView& view, glm::ivec2 size, glm::vec2 pixel) {
    const glm::vec2 ndc(2.0f * pixel.x / float(std::max(size.x, 1)) - 1.0f, 1.0f - 2.0f * pixel.y / float(std::max(size.y, 1)));
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 through = glm::vec3(far) / far.w;
    return {view.position, glm::normalize(through - view.position)};
}

std::optional<glm::vec3> pickWater(const water::WaterQuery& water, const Ray& ray, float maxDistance) {
    // f(t): the ray's height above the surface under it. The march steps |f| / (|d_y| + L |d_xz|),
    // which cannot cross the surface while its slope stays under L; a sign change is then
    // closed by bisection to PICK_TOLERANCE_M.
    const auto f = [&](float t) {
        const glm::vec3 p = ray.at(t);
        return p.y - water.sample(p.x, p.z).height;
    };
    const float rate = std::abs(ray.direction.y) + PICK_MAX_SLOPE * std::hypot(ray.direction.x, ray.direction.z);
    constexpr int MAX_MARCH = 400, MAX_BISECT = 40;
    float t0 = 0.0f, f0 = f(0.0f);
    if (std::abs(f0) < PICK_TOLERANCE_M) return ray.origin;
    const float side = f0 > 0.0f ? 1.0f : -1.0f;  // above (1) or below (−1) the water
    for (int i = 0; i < MAX_MARCH && t0 < maxDistance; ++i) {
        // At grazing views |f| / rate shrinks geometrically: the step is at least
        // PICK_STEP_PER_M of the distance (a crest thinner than that may be stepped over).
        const float step = std::max(std::abs(f0) / rate, 1e-3f + PICK_STEP_PER_M * t0);
        const float t1 = std::min(t0 + step, maxDistance);
        const float f1 = f(t1);
        if (std::abs(f1) < PICK_TOLERANCE_M) return ray.at(t1);
        if (f1 * side < 0.0f) {
            float lo = t0, hi = t1;  // f(lo) on the start's side, f(hi) past the surface
            for (int k = 0; k < MAX_BISECT; ++k) {
                const float mid = 0.5f * (lo + hi);
                const float fm = f(mid);
                if (std::abs(fm) < PICK_TOLERANCE_M) return ray.at(mid);
                (fm * side > 0.0f ? lo : hi) = mid;
            }
            return ray.at(0.5f * (lo + hi));
        }
        t0 = t1;
        f0 = f1;
    }
    return std::nullopt;
}

std::optional<BodyPick> pickBody(ecs::World& world, const Ray& ray, float maxDistance) {
    std::optional<BodyPick> best;
    if (const auto* physicsWorld = world.resource<physics::PhysicsWorld>())
        if (auto hit = physicsWorld->rayCast(ray.origin, ray.at(maxDistance))) {
            auto& bodies = world.pool<Body>();
            for (size_t i = 0; i < bodies.size(); ++i)
                if (bodies.components()[i].id == hit->id)
                    best = BodyPick{bodies.entities()[i], hit->point, hit->fraction * maxDistance};
        }
    // Fish: a school is hit where the ray passes within a fish's length of one of them.
    auto& schools = world.pool<FishSchool>();
    for (size_t s = 0; s < schools.size(); ++s) {
        const FishSchool& school = schools.components()[s];
        const float reach = std::max(school.def.length, 0.3f);
        for (const glm::vec3& p : school.position) {
            const float t = glm::dot(p - ray.origin, ray.direction);
            if (t < 0.0f || t > maxDistance || (best && t >= best->distance)) continue;
            if (glm::length(ray.at(t) - p) <= reach) best = BodyPick{schools.entities()[s], p, t};
        }
    }
    return best;
}

} // namespace ob::game
