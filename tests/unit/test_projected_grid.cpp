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

TEST_CASE("looking at the sky from above the water shows no grid; from below the water it does", "[grid]") {
    glm::vec3 eye(0, 5, 0);
    CHECK_FALSE(projectedGridCorners(camera(eye, glm::vec3(0, 200, 10)), eye, 0.05f).visible);
    glm::vec3 diver(0, -5, 0);
    CHECK(projectedGridCorners(camera(diver, glm::vec3(0, 200, 10)), diver, 0.05f).visible);
}
