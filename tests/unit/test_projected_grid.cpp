// Projected grid (seed 000 §3.4): grid points lie where the camera's pixel rays meet the
// water plane, cover the screen below the horizon, and the w clamp bounds the horizon.
#include "ocean/projected_grid.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

using namespace ob::ocean;

namespace {

glm::mat4 camera(glm::vec3 eye, glm::vec3 target, glm::mat4* projOut = nullptr) {
    glm::mat4 proj = glm::perspectiveRH_NO(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 20000.0f);
    if (projOut) *projOut = proj;
    return proj * glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
}

// Screen position (NDC xy) of a world point.
glm::vec2 toNdc(const glm::mat4& vp, glm::vec3 p) {
    glm::vec4 c = vp * glm::vec4(p, 1.0f);
    return glm::vec2(c) / c.w;
}

} // namespace

TEST_CASE("projected grid corners land on the screen corners (plus margin) on the plane y = 0", "[grid]") {
    glm::vec3 eye(3, 10, -5);
    glm::mat4 vp = camera(eye, glm::vec3(3, 0, 5));  // 45° down: the horizon is above the screen
    GridCorners g = projectedGridCorners(vp, eye, 0.0f);
    REQUIRE(g.visible);
    const glm::vec2 expected[4] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    for (int i = 0; i < 4; ++i) {
        glm::vec2 xz = projectedGridPoint(g, glm::vec2(i & 1, i >> 1), 1e-6f);
        glm::vec2 ndc = toNdc(vp, glm::vec3(xz.x, 0, xz.y));
        CHECK(ndc.x == Approx(expected[i].x).margin(1e-3));
        CHECK(ndc.y == Approx(expected[i].y).margin(1e-3));
    }
}

TEST_CASE("every grid point is the plane hit of the pixel ray through its screen position", "[grid]") {
    glm::vec3 eye(0, 25, 0);
    glm::mat4 vp = camera(eye, glm::vec3(10, 0, 60));
    GridCorners g = projectedGridCorners(vp, eye, 0.0f);
    REQUIRE(g.visible);
    glm::mat4 inv = glm::inverse(vp);
    for (float u : {0.0f, 0.3f, 0.77f, 1.0f})
        for (float v : {0.0f, 0.5f, 0.9f}) {
            glm::vec2 xz = projectedGridPoint(g, {u, v}, 1e-6f);
            glm::vec3 p(xz.x, 0, xz.y);
            // The ray from the eye through p, continued, is a pixel ray: p is on the screen
            // inside [-1, 1]² and the ray from the eye to it hits y = 0 exactly at p.
            glm::vec2 ndc = toNdc(vp, p);
            CHECK(std::abs(ndc.x) <= 1.0f + 1e-3f);
            CHECK(std::abs(ndc.y) <= 1.0f + 1e-3f);
            glm::vec4 farH = inv * glm::vec4(ndc, 1.0f, 1.0f);
            glm::vec3 dir = glm::normalize(glm::vec3(farH) / farH.w - eye);
            float t = -eye.y / dir.y;
            glm::vec3 hit = eye + t * dir;
            CHECK(hit.x == Approx(p.x).margin(1e-3 * (1 + t)));
            CHECK(hit.z == Approx(p.z).margin(1e-3 * (1 + t)));
        }
}

TEST_CASE("with the horizon on screen the grid stops at it and the w clamp bounds the far edge", "[grid]") {
    glm::vec3 eye(0, 5, 0);
    glm::mat4 vp = camera(eye, glm::vec3(0, 5, 100));  // level: the horizon is the middle row
    GridCorners g = projectedGridCorners(vp, eye, 0.1f);
    REQUIRE(g.visible);
    glm::vec2 nearXz = projectedGridPoint(g, {0.5f, 0.0f}, 1e-4f);
    glm::vec2 farXz = projectedGridPoint(g, {0.5f, 1.0f}, 1e-4f);
    CHECK(nearXz.y > 0.0f);        // in front of the camera
    CHECK(farXz.y > 1000.0f);      // reaches far toward the horizon
    CHECK(std::isfinite(farXz.y));
    CHECK(farXz.y <= nearXz.y * 1.0001f / 1e-4f);  // |w| ≥ minW bounds the distance
    // Monotone: rows farther up the screen lie farther away.
    float prev = 0.0f;
    for (float v = 0.0f; v <= 1.0f; v += 0.125f) {
        float z = projectedGridPoint(g, {0.5f, v}, 1e-4f).y;
        CHECK(z > prev);
        prev = z;
    }
}

TEST_CASE("looking at the sky from above the water shows no grid, from below the water it does", "[grid]") {
    glm::vec3 eye(0, 5, 0);
    CHECK_FALSE(projectedGridCorners(camera(eye, glm::vec3(0, 200, 10)), eye, 0.05f).visible);
    glm::vec3 diver(0, -5, 0);
    CHECK(projectedGridCorners(camera(diver, glm::vec3(0, 200, 10)), diver, 0.05f).visible);
}

TEST_CASE("the grid covers the water to the horizon for heights 1-1000 m and pitches down to 0.5 degrees, "
          "with no NaN and no inverted or exploding cells",
          "[grid]") {
    const float minW = 2e-5f;
    for (float height : {1.0f, 10.0f, 100.0f, 1000.0f})
        for (float pitchDeg : {-0.5f, -3.0f, -20.0f, -60.0f, -89.0f}) {
            INFO("height " << height << " m, pitch " << pitchDeg << " deg");
            glm::vec3 eye(5, height, -7);
            float pitch = glm::radians(pitchDeg);
            glm::vec3 dir(0.3f * std::cos(pitch), std::sin(pitch), 0.95f * std::cos(pitch));
            glm::mat4 vp = camera(eye, eye + dir);
            GridCorners g = projectedGridCorners(vp, eye, 0.1f);
            REQUIRE(g.visible);
            const int n = 32;
            std::vector<glm::vec2> pts;
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    glm::vec2 p = projectedGridPoint(g, {float(i) / n, float(j) / n}, minW);
                    REQUIRE(std::isfinite(p.x));
                    REQUIRE(std::isfinite(p.y));
                    pts.push_back(p);
                }
            // Every cell keeps the orientation of the first (no fold-over), and its area is
            // positive: no inverted or degenerate triangles.
            auto cross2 = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
            float sign = 0.0f;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    glm::vec2 a = pts[size_t(j * (n + 1) + i)], b = pts[size_t(j * (n + 1) + i + 1)];
                    glm::vec2 c = pts[size_t((j + 1) * (n + 1) + i)];
                    float area = cross2(b - a, c - a);
                    if (sign == 0.0f) sign = area > 0 ? 1.0f : -1.0f;
                    INFO("cell " << i << ", " << j << " a " << a.x << "," << a.y << " b " << b.x << "," << b.y << " c " << c.x << "," << c.y);
                    REQUIRE(area * sign > 0.0f);
                }
            // Near edge: below the screen's bottom edge; far edge: within a hair of the
            // horizon (or above the screen's top when the horizon is off screen).
            glm::vec2 nearMid = pts[size_t(n / 2)], farMid = pts[size_t(n * (n + 1) + n / 2)];
            CHECK(toNdc(vp, glm::vec3(nearMid.x, 0, nearMid.y)).y <= -1.0f);
            glm::vec2 farNdc = toNdc(vp, glm::vec3(farMid.x, 0, farMid.y));
            glm::vec4 horizonClip = vp * glm::vec4(dir.x, 0, dir.z, 0);
            float horizonY = horizonClip.y / horizonClip.w;
            if (horizonY < 1.1f) CHECK(farNdc.y > horizonY - 0.01f);
            else CHECK(farNdc.y >= 1.0f);
            // The far edge is bounded: the |w| clamp caps the distance (no exploding cells).
            float farDist = glm::length(farMid - glm::vec2(eye.x, eye.z));
            CHECK(farDist < 1e6f * std::max(height, 1.0f));
        }
}
