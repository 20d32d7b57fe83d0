// Swept-sphere touches and gate crossings (goal_geometry.h).
#include "goals/goal_geometry.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace ob::game {

bool sweptSphereTouchesSphere(glm::vec3 from, glm::vec3 to, float r, glm::vec3 centre, float radius) {
    const glm::vec3 path = to - from;
    const float length2 = glm::dot(path, path);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(centre - from, path) / length2, 0.0f, 1.0f) : 0.0f;
    const glm::vec3 closest = from + t * path;
    const float reach = r + radius;
    return glm::dot(closest - centre, closest - centre) <= reach * reach;
}

bool sweptSphereTouchesBox(glm::vec3 from, glm::vec3 to, float r, glm::vec3 centre, glm::quat rotation, glm::vec3 half) {
    const glm::quat toBox = glm::conjugate(rotation);
    const glm::vec3 a = toBox * (from - centre), b = toBox * (to - centre);
    const glm::vec3 extent = half + glm::vec3(r);
    float enter = 0.0f, leave = 1.0f;
    for (int i = 0; i < 3; ++i) {
        const float d = b[i] - a[i];
        if (std::abs(d) < 1e-9f) {
            if (std::abs(a[i]) > extent[i]) return false;  // parallel to this slab and outside it
            continue;
        }
        float t0 = (-extent[i] - a[i]) / d, t1 = (extent[i] - a[i]) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave) return false;
    }
    return true;
}

int gateCrossing(glm::vec2 port, glm::vec2 starboard, glm::vec2 from, glm::vec2 to) {
    const glm::vec2 gate = starboard - port;
    const glm::vec2 ahead(gate.y, -gate.x);  // the right way through, (x, z)
    const float before = glm::dot(from - port, ahead), after = glm::dot(to - port, ahead);
    int way = 0;
    if (before < 0.0f && after >= 0.0f) way = 1;
    else if (before > 0.0f && after <= 0.0f) way = -1;
    if (way == 0) return 0;
    // Where the path meets the gate's line: between the buoys?
    const glm::vec2 at = from + (before / (before - after)) * (to - from);
    const float along = glm::dot(at - port, gate) / glm::dot(gate, gate);
    return along >= 0.0f && along <= 1.0f ? way : 0;
}

} // namespace ob::game
