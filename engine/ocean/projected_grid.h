// Projected grid (seed 000 §3.4, eq. 11; after Johanson): a regular screen-space grid laid on
// the mean water plane y = 0 through the four corner rays, interpolated in homogeneous
// coordinates, so vertices are dense near the camera and sparse up to the horizon.
#pragma once
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace ob::ocean {

/// The four corners of the grid on the plane y = 0, homogeneous (x, 0, z, w), w ≥ 0,
/// scaled together so the largest w is 1. Order: (u, v) = (0,0), (1,0), (0,1), (1,1);
/// v = 0 is the grid edge nearest the camera, v = 1 the edge at the horizon.
struct GridCorners {
    std::array<glm::vec4, 4> corner{};
    bool visible = false;  ///< false when no water is on screen (camera looking away from it)
};

/// The grid over the part of the screen where the water plane is seen (below the horizon
/// from above the water, above it from below), extended by `margin` (NDC units) past the
/// screen edges (4·margin at the edge nearest the camera) so displaced waves never show a gap. `viewProjection` must have no roll.
GridCorners projectedGridCorners(const glm::mat4& viewProjection, const glm::vec3& eye, float margin);

/// World (x, z) of grid point (u, v) ∈ [0, 1]²: bilinear interpolation of the homogeneous
/// corners, then the division by w with |w| clamped from below by `minW` (seed 000: the
/// horizon never overflows). Mirrors the vertex shader (shaders/water_surface.vert).
glm::vec2 projectedGridPoint(const GridCorners& corners, glm::vec2 uv, float minW);

} // namespace ob::ocean
