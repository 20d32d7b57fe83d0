// The building blocks of the project's procedural models (model_shapes.cpp, model_props.cpp):
// grids, quads, boxes, lathes, cylinders and plates added to a ShapePart. Every surface is
// closed and wound counter-clockwise seen from outside; smooth normals are the area-weighted
// face normals of one surface patch, creases come from separate patches. Only + − × ÷ and
// sqrt: the generated files are the same bytes on every machine (built -ffp-contract=off).
#pragma once
#include "tools/model_shapes.h"

#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace ob::game::shape {

/// (cos, sin) of 2π·k/n, exact at quarter turns so poles and keels land on exact zeros.
glm::dvec2 circle(int k, int n);

using Grid = std::vector<std::vector<glm::dvec3>>;  ///< [row][column] points
using NormalAt = std::function<glm::dvec3(const glm::dvec3&)>;

/// A patch from a grid of points: cell (i, j) → triangles (i,j)(i+1,j)(i+1,j+1) and
/// (i,j)(i+1,j+1)(i,j+1), so the face normal is ∂row × ∂column; `wrap` joins the last
/// column to the first. Triangles with two equal corners (poles, tips) are left out.
/// Normals: `normalAt` if given, else the area-weighted face normals summed per position.
void addGrid(ShapePart& part, const Grid& grid, bool wrap, const NormalAt& normalAt = nullptr);
/// A flat convex quad a b c d, counter-clockwise seen from the side it faces.
void addQuad(ShapePart& part, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);
/// An axis-aligned box.
void addBox(ShapePart& part, const glm::dvec3& lo, const glm::dvec3& hi);

/// One point of a lathe profile: radius r and height z on the axis; a crease ends one
/// smooth run of the profile and starts the next (a hard edge).
struct ProfilePoint {
    double r, z;
    bool crease = false;
};

/// A surface of revolution about +z of a profile that starts and ends on the axis (r = 0),
/// so the surface is closed; walking the profile with the solid on its left keeps the
/// winding outward. `place` moves it into the model.
void addLathe(ShapePart& part, const std::vector<ProfilePoint>& profile, int segments, const glm::dmat4& place,
              const NormalAt& normalAt = nullptr);
/// A closed cylinder of radius r about +z from z0 to z1.
void addCylinder(ShapePart& part, double r, double z0, double z1, int segments, const glm::dmat4& place);
/// A flat plate: polygon `outline` (counter-clockwise in (u, v), star-shaped about its first
/// point) in the plane origin + p·u + q·v, `thickness` thick along u × v.
void addPlate(ShapePart& part, const std::vector<glm::dvec2>& outline, const glm::dvec3& origin, const glm::dvec3& u,
              const glm::dvec3& v, double thickness);
/// An empty part with its material.
ShapePart makePart(const char* name, glm::vec3 color, float metallic, float roughness);
/// Rigid placement: rotation taking +z to `axis` (one of ±x, +y, +z), then a translation.
glm::dmat4 placeAlong(char axis, const glm::dvec3& at);

} // namespace ob::game::shape
