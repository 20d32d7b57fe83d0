// Projected grid corners: the region of the mean plane the displaced water can be seen from,
// and the projector (apex, heading) whose grid covers it.
#include "gfx/projected_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace ob::gfx {

// Safety margins on the bounds: float rounding in the shader, and the grid's straight edges
// between vertices (metres, plus a fraction of each bound).
constexpr double BOUND_SCALE = 1.02;
constexpr double VERTICAL_MARGIN = 0.05;
constexpr double HORIZONTAL_MARGIN = 0.1;

namespace {

// Clip space back to the world.
struct Unprojector {
    glm::dmat4 inv;
    glm::dvec3 operator()(double x, double y, double z) const {
        glm::dvec4 p = inv * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(p) / p.w;
    }
};

// The slab the displaced water stays in (bottom ≤ y ≤ top) and how far it reaches sideways, m,
// with their margins.
struct Slab {
    double top, bottom, reach;
};

Slab slabOf(const SurfaceBounds& bounds) {
    return {double(bounds.up) * BOUND_SCALE + VERTICAL_MARGIN, -(double(bounds.down) * BOUND_SCALE + VERTICAL_MARGIN),
            double(bounds.horizontal) * BOUND_SCALE + HORIZONTAL_MARGIN};
}

// The vertices of (frustum ∩ slab), seen from above: frustum corners inside the slab, and the
// points where the frustum's 12 edges cross the slab's two planes. They span the plane region
// any visible displaced point lies over.
std::vector<glm::dvec2> seenPoints(const Unprojector& unproject, const Slab& slab) {
    std::array<glm::dvec3, 8> corner;
    for (int i = 0; i < 8; ++i) corner[size_t(i)] = unproject(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    std::vector<glm::dvec2> seen;
    for (const glm::dvec3& c : corner)
        if (c.y >= slab.bottom && c.y <= slab.top) seen.emplace_back(c.x, c.z);
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4}) {
            if (i & bit) continue;
            const glm::dvec3 &p = corner[size_t(i)], &q = corner[size_t(i | bit)];
            for (double y : {slab.bottom, slab.top}) {
                const double dp = p.y - y, dq = q.y - y;
                if ((dp < 0.0) == (dq < 0.0)) continue;
                const glm::dvec3 hit = glm::mix(p, q, dp / (dp - dq));
                seen.emplace_back(hit.x, hit.z);
            }
        }
    return seen;
}

// The projector's frame on the plane: its heading (the camera's, or its screen-up direction
// looking straight down or up), its side (screen right, seen from above) and the eye's foot.
struct Projector {
    glm::dvec3 forward;
    glm::dvec2 heading, side, foot;
};

Projector projectorOf(const Unprojector& unproject, const glm::vec3& eye) {
    Projector p;
    p.forward = glm::normalize(unproject(0, 0, 1) - unproject(0, 0, -1));
    p.heading = glm::dvec2(p.forward.x, p.forward.z);
    if (glm::length(p.heading) < 1e-3) {
        const glm::dvec3 screenUp = unproject(0, 1, -1) - unproject(0, -1, -1);
        p.heading = glm::dvec2(screenUp.x, screenUp.z);
    }
    p.heading = glm::length(p.heading) > 1e-12 ? glm::normalize(p.heading) : glm::dvec2(0.0, 1.0);
    p.side = glm::dvec2(-p.heading.y, p.heading.x);
    p.foot = glm::dvec2(eye.x, eye.z);
    return p;
}

// Each seen point widened by the horizontal reach: an octagon around it that holds the disc of
// that radius, as (a, b): along and across the heading from the eye's footprint.
std::vector<glm::dvec2> widenedRegion(const std::vector<glm::dvec2>& seen, double reach, const Projector& pr) {
    std::vector<glm::dvec2> region;
    region.reserve(seen.size() * 8);
    const double octagon = reach / std::cos(M_PI / 8.0);
    for (const glm::dvec2& p : seen)
        for (int k = 0; k < 8; ++k) {
            const double angle = (double(k) + 0.5) * M_PI / 4.0;
            const glm::dvec2 d = p + octagon * glm::dvec2(std::cos(angle), std::sin(angle)) - pr.foot;
            region.emplace_back(glm::dot(d, pr.heading), glm::dot(d, pr.side));
        }
    return region;
}

// The apex's distance a0 behind the footprint: the camera's own (its height times the tangent
// of its pitch toward the plane, so rows follow screen rows), moved back until the nearest
// region point is `nearGap` in front of it (waves reaching behind the view, a low eye); looking
// straight down the camera's a0 → ∞, capped where the grid is affine to rounding.
double apexDistance(const std::vector<glm::dvec2>& region, const glm::vec3& eye, const Projector& pr, const Slab& slab) {
    double aMin = region[0].x, aMax = region[0].x;
    for (const glm::dvec2& r : region) aMin = std::min(aMin, r.x), aMax = std::max(aMax, r.x);
    const double height = std::abs(double(eye.y));
    const double towardPlane = eye.y >= 0.0f ? -pr.forward.y : pr.forward.y;  // sine of the pitch toward the plane
    double a0 = 0.0;
    if (towardPlane > 0.0) a0 = height * towardPlane / std::max(std::sqrt(1.0 - towardPlane * towardPlane), 1e-6);
    const double nearGap = std::max(0.5 * (height + slab.top - slab.bottom), 0.5);
    return std::max(std::min(a0, 16.0 * (aMax - aMin) + nearGap), nearGap - aMin);
}

// Grid space: t = 1/(a + a0) (rows), s = b/(a + a0) (columns); a point is
// apex + (heading + s·side)/t, so in homogeneous form (apex·t + heading + s·side, t): linear in
// (s, t). The corners span the region's (s, t).
GridCorners cornersOver(const std::vector<glm::dvec2>& region, double a0, const Projector& pr) {
    double sMin = 1e300, sMax = -1e300, tMin = 1e300, tMax = -1e300;
    for (const glm::dvec2& r : region) {
        const double t = 1.0 / (r.x + a0), s = r.y * t;
        sMin = std::min(sMin, s), sMax = std::max(sMax, s);
        tMin = std::min(tMin, t), tMax = std::max(tMax, t);
    }
    const glm::dvec2 apex = pr.foot - a0 * pr.heading;
    const auto homogeneous = [&](double s, double t) {
        const glm::dvec2 xz = (apex * t + pr.heading + s * pr.side) / tMax;  // scaled so w = 1 at the near edge
        return glm::vec4(float(xz.x), 0.0f, float(xz.y), float(t / tMax));
    };
    GridCorners out;
    out.corner = {homogeneous(sMin, tMax), homogeneous(sMax, tMax), homogeneous(sMin, tMin), homogeneous(sMax, tMin)};
    out.minW = float(tMin / tMax);
    out.visible = true;
    return out;
}

} // namespace

GridCorners projectedGridCorners(const glm::mat4& viewProjection, const glm::vec3& eye, const SurfaceBounds& bounds) {
    const Unprojector unproject{glm::inverse(glm::dmat4(viewProjection))};
    const Slab slab = slabOf(bounds);
    const std::vector<glm::dvec2> seen = seenPoints(unproject, slab);
    if (seen.empty()) return GridCorners{};
    const Projector projector = projectorOf(unproject, eye);
    const std::vector<glm::dvec2> region = widenedRegion(seen, slab.reach, projector);
    return cornersOver(region, apexDistance(region, eye, projector, slab), projector);
}

glm::vec2 projectedGridPoint(const GridCorners& corners, glm::vec2 uv, float minW) {
    const auto& c = corners.corner;
    glm::vec4 p = glm::mix(glm::mix(c[0], c[1], uv.x), glm::mix(c[2], c[3], uv.x), uv.y);
    float w = std::max(p.w, minW);
    return glm::vec2(p.x, p.z) / w;
}

} // namespace ob::gfx
