// Projected grid ([Lee2007] §3.4, eq. 11; after Johanson's projector): a regular grid whose
// points, interpolated in homogeneous coordinates between four corners on the mean water
// plane y = 0, are dense near the camera and sparse toward the horizon. The corners come from
// a projector that sees every rest point whose displaced surface point can be on screen.
#pragma once
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ob::gfx {

/// How far the drawn surface can stand from its rest points (each ≥ 0, m): the grid reaches
/// this far past the view. The layers' bounds add (the view converts ocean::DisplacementBounds).
struct SurfaceBounds {
    float up = 0.0f;          ///< largest rise above y = 0
    float down = 0.0f;        ///< largest fall below y = 0
    float horizontal = 0.0f;  ///< largest horizontal move of a point

    SurfaceBounds& operator+=(const SurfaceBounds& o) {
        up += o.up, down += o.down, horizontal += o.horizontal;
        return *this;
    }
};

/// The four corners of the grid on the plane y = 0, homogeneous (x, 0, z, w), w > 0, scaled
/// together so the largest w is 1. Order: (u, v) = (0,0), (1,0), (0,1), (1,1); v = 0 is the
/// edge nearest the camera, v = 1 the edge farthest from it.
struct GridCorners {
    std::array<glm::vec4, 4> corner{};
    float minW = 1.0f;     ///< smallest w over the grid (at v = 1): a |w| clamp below it never acts
    bool visible = false;  ///< false when no water can be on screen (e.g. above it, looking up)
};

/// The grid for a camera (`viewProjection`, any roll, pitch and field of view, OpenGL clip
/// space; `eye` its position) over water displaced within `bounds`. The grid covers the
/// vertical projection of (view frustum ∩ slab −down ≤ y ≤ up), widened by the horizontal
/// bound, plus a small safety margin: every rest point whose displaced point can lie in the
/// frustum. Its lines are those of a projector above the eye's footprint looking along the
/// camera's heading: rows are lines across the heading spaced evenly in 1/(distance from an
/// apex behind the eye), columns are rays from that apex (the camera's own perspective when
/// the projector can be the camera; the apex moves back when waves reach behind the view).
GridCorners projectedGridCorners(const glm::mat4& viewProjection, const glm::vec3& eye, const SurfaceBounds& bounds);

/// World (x, z) of grid point (u, v) ∈ [0, 1]²: bilinear interpolation of the homogeneous
/// corners, then the division by w with w clamped from below by `minW` ([Lee2007]: the
/// division never overflows). Mirrors the vertex shader (shaders/common_water.glsl).
glm::vec2 projectedGridPoint(const GridCorners& corners, glm::vec2 uv, float minW);

} // namespace ob::gfx
