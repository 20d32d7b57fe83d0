// Projected grid ([Lee2007] §3.4, after Johanson's projector): for flat water the grid is the
// camera's own screen-space grid; for displaced water its rest domain holds every rest point
// whose displaced point can be seen (checked by casting pixel rays, not by the frustum
// algebra the grid uses), for any roll, pitch and field of view; no cell folds or explodes.
#include "ocean/ocean_fft_cpu.h"
#include "gfx/projected_grid.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

using namespace ob::gfx;
using ob::ocean::OceanFftCpu;

namespace {

// A camera at eye with heading (radians about +y, 0 = +z), pitch and roll (radians), vertical fov.
glm::mat4 camera(glm::vec3 eye, float heading, float pitch, float roll = 0.0f, float fovDeg = 60.0f, float far = 20000.0f) {
    glm::vec3 forward(std::sin(heading) * std::cos(pitch), std::sin(pitch), std::cos(heading) * std::cos(pitch));
    glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    glm::vec3 up = glm::cross(right, forward);
    glm::vec3 rolledUp = std::cos(roll) * up - std::sin(roll) * right;
    glm::mat4 proj = glm::perspectiveRH_NO(glm::radians(fovDeg), 16.0f / 9.0f, 0.1f, far);
    return proj * glm::lookAtRH(eye, eye + forward, rolledUp);
}

glm::vec2 toNdc(const glm::mat4& vp, glm::vec3 p) {
    glm::vec4 c = vp * glm::vec4(p, 1.0f);
    return glm::vec2(c) / c.w;
}

// The grid's rest domain on the plane: the convex quad of its four corners.
struct Domain {
    glm::dvec2 p[4];  // in order around the quad: (0,0), (1,0), (1,1), (0,1)
    explicit Domain(const GridCorners& g) {
        const int order[4] = {0, 1, 3, 2};
        for (int i = 0; i < 4; ++i) {
            glm::dvec4 c = glm::dvec4(g.corner[size_t(order[i])]);
            p[i] = glm::dvec2(c.x, c.z) / c.w;
        }
    }
    // Distance of q inside the quad from its nearest edge (m; < 0 outside), either winding.
    double inside(glm::dvec2 q) const {
        double area = 0.0;
        for (int i = 0; i < 4; ++i) area += p[i].x * p[(i + 1) % 4].y - p[(i + 1) % 4].x * p[i].y;
        double worst = 1e300;
        for (int i = 0; i < 4; ++i) {
            glm::dvec2 a = p[i], e = glm::normalize(p[(i + 1) % 4] - a);
            worst = std::min(worst, (e.x * (q.y - a.y) - e.y * (q.x - a.x)) * (area > 0.0 ? 1.0 : -1.0));
        }
        return worst;
    }
};

} // namespace

TEST_CASE("over flat water the grid is the camera's screen grid: rows are screen rows, evenly spaced", "[grid]") {
    // With no displacement and the eye well above the plane the projector is the camera: the
    // screen-to-plane map is a homography, and in the camera's own (s, t) both screen axes
    // are affine, so grid lines are screen-aligned and evenly spaced (docs/references.md#projected-grid).
    glm::vec3 eye(3, 25, -5);
    glm::mat4 vp = camera(eye, 0.4f, glm::radians(-20.0f));
    GridCorners g = projectedGridCorners(vp, eye, {});
    REQUIRE(g.visible);
    const int n = 8;
    float prevY = -1e9f, step = 0.0f;
    for (int j = 0; j <= n; ++j) {
        float v = float(j) / n;
        glm::vec2 left = projectedGridPoint(g, {0.0f, v}, 1e-9f), right = projectedGridPoint(g, {1.0f, v}, 1e-9f);
        glm::vec2 mid = projectedGridPoint(g, {0.37f, v}, 1e-9f);
        float y = toNdc(vp, glm::vec3(left.x, 0, left.y)).y;
        INFO("row " << j);
        CHECK(toNdc(vp, glm::vec3(right.x, 0, right.y)).y == Approx(y).margin(1e-3));
        CHECK(toNdc(vp, glm::vec3(mid.x, 0, mid.y)).y == Approx(y).margin(1e-3));
        if (j == 1) step = y - prevY;
        if (j > 1) CHECK(y - prevY == Approx(step).epsilon(1e-3));
        CHECK(y > prevY);
        prevY = y;
    }
    // The grid reaches the screen's bottom and sides and, up the screen, the horizon.
    glm::vec2 nearLeft = projectedGridPoint(g, {0.0f, 0.0f}, 1e-9f);
    glm::vec2 ndc = toNdc(vp, glm::vec3(nearLeft.x, 0, nearLeft.y));
    CHECK(ndc.y <= -1.0f);
    CHECK(std::abs(ndc.x) >= 1.0f);
    CHECK(ndc.y > -1.2f);  // and not much beyond: the rows are spent on the screen
}

TEST_CASE("the grid holds every rest point whose displaced point a pixel ray can meet, for any camera", "[grid]") {
    // A surface point Y seen through a pixel lies on that pixel's ray, within the far plane,
    // inside the slab −down ≤ y ≤ up; its rest point is Y.xz minus a horizontal move of at
    // most `horizontal`. Every such rest point must be inside the grid's domain.
    std::mt19937 rng(20261201u);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    int cameras = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const float far = trial % 4 == 0 ? 2000.0f : 20000.0f;
        SurfaceBounds bounds{uni(rng) * 40.0f, uni(rng) * 40.0f, uni(rng) * 60.0f};
        if (trial % 5 == 0) bounds = {};
        const float height = bounds.up + 0.5f + 500.0f * uni(rng) * uni(rng);
        const glm::vec3 eye(2000.0f * uni(rng) - 1000.0f, trial % 7 == 0 ? -height : height, 2000.0f * uni(rng) - 1000.0f);
        const float heading = 6.2832f * uni(rng), pitch = glm::radians(-89.0f + 99.0f * uni(rng));
        const float roll = glm::radians(-35.0f + 70.0f * uni(rng)), fov = 30.0f + 70.0f * uni(rng);
        const glm::mat4 vp = camera(eye, heading, eye.y < 0 ? -pitch : pitch, roll, fov, far);
        const glm::dmat4 inv = glm::inverse(glm::dmat4(vp));
        GridCorners g = projectedGridCorners(vp, eye, bounds);
        INFO("trial " << trial << " eye " << eye.x << " " << eye.y << " " << eye.z << " pitch " << glm::degrees(pitch)
                      << " roll " << glm::degrees(roll) << " fov " << fov << " bounds " << bounds.up << " " << bounds.down
                      << " " << bounds.horizontal);
        const Domain domain(g);
        int hits = 0;
        double worst = 1e300;
        glm::dvec2 worstRest(0.0);
        glm::vec2 worstNdc(0.0f);
        for (int py = 0; py <= 12; ++py)
            for (int px = 0; px <= 16; ++px) {
                glm::vec2 ndc(-1.0f + 2.0f * px / 16.0f, -1.0f + 2.0f * py / 12.0f);
                glm::dvec4 n = inv * glm::dvec4(ndc, -1.0, 1.0), f = inv * glm::dvec4(ndc, 1.0, 1.0);
                glm::dvec3 a = glm::dvec3(n) / n.w, b = glm::dvec3(f) / f.w;
                // The part of the near-to-far segment inside the slab.
                double lo = 0.0, hi = 1.0;
                const double dy = b.y - a.y;
                for (int top = 0; top < 2; ++top) {
                    const double plane = top ? double(bounds.up) : -double(bounds.down);
                    if (std::abs(dy) < 1e-12) {
                        if (top ? a.y > plane : a.y < plane) lo = 2.0;
                        continue;
                    }
                    const double s = (plane - a.y) / dy;
                    if (top ? dy < 0.0 : dy > 0.0) lo = std::max(lo, s);  // entering the slab through this plane
                    else hi = std::min(hi, s);
                }
                if (lo > hi) continue;
                for (int k = 0; k <= 8; ++k) {
                    glm::dvec3 y = glm::mix(a, b, lo + (hi - lo) * k / 8.0);
                    for (int d = 0; d < 8; ++d) {
                        double angle = d * 3.14159265 / 4.0;
                        glm::dvec2 rest = glm::dvec2(y.x, y.z) - double(bounds.horizontal) * glm::dvec2(std::cos(angle), std::sin(angle));
                        if (domain.inside(rest) < worst) worst = domain.inside(rest), worstRest = rest, worstNdc = ndc;
                        ++hits;
                    }
                }
            }
        if (hits == 0) continue;  // no water can be on screen
        ++cameras;
        REQUIRE(g.visible);
        // Inside by a margin that grows with distance (rounding of metres-far points).
        INFO("worst rest point " << worstRest.x << " " << worstRest.y << " through pixel " << worstNdc.x << " " << worstNdc.y
             << "; domain " << domain.p[0].x << " " << domain.p[0].y << ", " << domain.p[1].x << " " << domain.p[1].y << ", "
             << domain.p[2].x << " " << domain.p[2].y << ", " << domain.p[3].x << " " << domain.p[3].y);
        CHECK(worst >= -1e-3);
    }
    CHECK(cameras > 300);
}

TEST_CASE("looking at the sky from above the water shows no grid, from below the water it does", "[grid]") {
    glm::vec3 eye(0, 5, 0);
    CHECK_FALSE(projectedGridCorners(camera(eye, 0.0f, glm::radians(60.0f)), eye, {}).visible);
    CHECK_FALSE(projectedGridCorners(camera(eye, 0.0f, glm::radians(60.0f)), eye, {2.0f, 2.0f, 3.0f}).visible);
    glm::vec3 diver(0, -5, 0);
    CHECK(projectedGridCorners(camera(diver, 0.0f, glm::radians(60.0f)), diver, {}).visible);
}

TEST_CASE("the grid has no NaN and no folded or exploding cells for heights 0.5-1000 m, pitches to -89 degrees, "
          "roll and big waves",
          "[grid]") {
    for (float height : {0.5f, 10.0f, 100.0f, 1000.0f})
        for (float pitchDeg : {10.0f, -0.5f, -3.0f, -20.0f, -60.0f, -89.0f, -90.0f})
            for (float roll : {0.0f, 35.0f})
                for (SurfaceBounds bounds : {SurfaceBounds{}, SurfaceBounds{20.0f, 20.0f, 60.0f}}) {
                    INFO("height " << height << " m, pitch " << pitchDeg << " deg, roll " << roll << ", bounds " << bounds.up);
                    glm::vec3 eye(5, bounds.up + height, -7);
                    glm::mat4 vp = camera(eye, 0.3f, glm::radians(pitchDeg), glm::radians(roll));
                    GridCorners g = projectedGridCorners(vp, eye, bounds);
                    if (!g.visible) {
                        CHECK(pitchDeg > 0.0f);
                        continue;
                    }
                    CHECK(g.minW > 0.0f);
                    CHECK(g.minW <= 1.0f);
                    const int n = 32;
                    std::vector<glm::vec2> pts;
                    for (int j = 0; j <= n; ++j)
                        for (int i = 0; i <= n; ++i) {
                            glm::vec2 p = projectedGridPoint(g, {float(i) / n, float(j) / n}, 0.5f * g.minW);
                            REQUIRE(std::isfinite(p.x));
                            REQUIRE(std::isfinite(p.y));
                            pts.push_back(p);
                        }
                    auto cross2 = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
                    float sign = 0.0f;
                    for (int j = 0; j < n; ++j)
                        for (int i = 0; i < n; ++i) {
                            glm::vec2 a = pts[size_t(j * (n + 1) + i)], b = pts[size_t(j * (n + 1) + i + 1)];
                            glm::vec2 c = pts[size_t((j + 1) * (n + 1) + i)];
                            float area = cross2(b - a, c - a);
                            if (sign == 0.0f) sign = area > 0 ? 1.0f : -1.0f;
                            REQUIRE(area * sign > 0.0f);
                        }
                    // Bounded: the far edge stays within the far plane's reach (plus the waves).
                    for (const glm::vec2& p : pts) CHECK(glm::length(p - glm::vec2(eye.x, eye.z)) < 20000.0f * 3.0f);
                }
}

TEST_CASE("the FFT's displacement bounds of a single mode are its crest, trough and orbit radius, and cascades add", "[grid][fft]") {
    // h̃0(K) = a (real), h̃0(−K) = 0, t = 0: h = 2a·cos(K·X) and D = 2a·sin(K·X)·K/k (eq. 1, 2,
    // 7, unnormalised sums), so the crest and the trough are 2a and the orbit radius is 2a·c.
    // Four cycles over 16 texels sample the crest, the trough and the largest |D| exactly.
    ob::ocean::OceanDef def;
    def.resolution = 16;
    def.patch_size = 100.0f;
    def.choppiness = 1.5f;
    for (int cascades : {1, 2}) {
        def.cascades = cascades;
        OceanFftCpu ocean(def, 1);
        for (int c = 0; c < cascades; ++c) {
            ocean.spectrum(c).clear();
            ocean.spectrum(c).setH0(c == 0 ? 4 : 0, c == 0 ? 0 : -4, {0.3f, 0.0f});
        }
        ocean.update(0.0);
        const ob::ocean::DisplacementBounds b = ocean.displacementBounds();
        INFO(cascades << " cascade(s)");
        CHECK(b.up == Approx(0.6 * cascades).epsilon(1e-5));
        CHECK(b.down == Approx(0.6 * cascades).epsilon(1e-5));
        CHECK(b.horizontal == Approx(1.5 * 0.6 * cascades).epsilon(1e-5));
    }
}
