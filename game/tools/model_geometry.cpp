// The procedural models' building blocks (model_geometry.h).
#include "tools/model_geometry.h"

#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

namespace ob::game::shape {

namespace {

constexpr double PI = 3.14159265358979323846;

// sin and cos by their Taylor series after reduction to [−π, π]: only + − × ÷, so the
// generated files do not depend on which libm variant a machine picks.
glm::dvec2 cosSin(double angle) {
    const double x = angle - 2.0 * PI * std::floor((angle + PI) / (2.0 * PI));
    const double x2 = x * x;
    double s = x, c = 1.0, st = x, ct = 1.0;
    for (int n = 1; n <= 14; ++n) {
        st *= -x2 / double((2 * n) * (2 * n + 1));
        ct *= -x2 / double((2 * n - 1) * (2 * n));
        s += st;
        c += ct;
    }
    return {c, s};
}

glm::vec3 toFloat(const glm::dvec3& p) { return glm::vec3(float(p.x), float(p.y), float(p.z)); }

glm::vec3 unit(const glm::dvec3& v) {
    const double len = std::sqrt(glm::dot(v, v));
    return len > 0.0 ? toFloat(v / len) : glm::vec3(0.0f, 1.0f, 0.0f);
}

} // namespace

// (cos, sin) of 2π·k/n, exact at quarter turns so poles and keels land on exact zeros.
glm::dvec2 circle(int k, int n) {
    k = ((k % n) + n) % n;
    if ((4 * k) % n == 0) {
        static const glm::dvec2 QUARTERS[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
        return QUARTERS[(4 * k) / n];
    }
    return cosSin(2.0 * PI * double(k) / double(n));
}


// A patch from a grid of points: cell (i, j) → triangles (i,j)(i+1,j)(i+1,j+1) and
// (i,j)(i+1,j+1)(i,j+1), so the face normal is ∂row × ∂column; `wrap` joins the last
// column to the first. Triangles with two equal corners (poles, tips) are left out.
// Normals: `normalAt` if given, else the area-weighted face normals summed per position.
void addGrid(ShapePart& part, const Grid& grid, bool wrap, const NormalAt& normalAt) {
    const size_t rows = grid.size(), cols = grid.front().size();
    const uint32_t base = uint32_t(part.positions.size());
    std::vector<glm::vec3> points;
    for (const auto& row : grid)
        for (const glm::dvec3& p : row) points.push_back(toFloat(p));
    using Key = std::array<float, 3>;
    auto key = [](const glm::vec3& p) { return Key{p.x, p.y, p.z}; };
    std::map<Key, glm::dvec3> sums;  // −0 and +0 compare equal: one key
    for (size_t i = 0; i + 1 < rows; ++i)
        for (size_t j = 0; j + 1 < cols + (wrap ? 1 : 0); ++j) {
            const size_t j1 = (j + 1) % cols;
            const size_t a = i * cols + j, b = (i + 1) * cols + j, c = (i + 1) * cols + j1, d = i * cols + j1;
            for (const std::array<size_t, 3>& t : {std::array<size_t, 3>{a, b, c}, std::array<size_t, 3>{a, c, d}}) {
                const glm::vec3 &p = points[t[0]], &q = points[t[1]], &r = points[t[2]];
                if (p == q || q == r || r == p) continue;
                const glm::dvec3 n = glm::cross(glm::dvec3(q) - glm::dvec3(p), glm::dvec3(r) - glm::dvec3(p));
                for (size_t v : t) {
                    sums[key(points[v])] += n;
                    part.indices.push_back(base + uint32_t(v));
                }
            }
        }
    for (size_t v = 0; v < points.size(); ++v) {
        part.positions.push_back(points[v]);
        part.normals.push_back(unit(normalAt ? normalAt(glm::dvec3(points[v])) : sums[key(points[v])]));
    }
}

// A flat convex quad a b c d, counter-clockwise seen from the side it faces.
void addQuad(ShapePart& part, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const uint32_t base = uint32_t(part.positions.size());
    const glm::vec3 n = unit(glm::cross(b - a, c - a));
    for (const glm::dvec3& p : {a, b, c, d}) {
        part.positions.push_back(toFloat(p));
        part.normals.push_back(n);
    }
    for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) part.indices.push_back(base + k);
}

// An axis-aligned box.
void addBox(ShapePart& part, const glm::dvec3& lo, const glm::dvec3& hi) {
    for (int k = 0; k < 3; ++k) {
        const int u = (k + 1) % 3, v = (k + 2) % 3;  // e_u × e_v = e_k
        for (int side = 0; side < 2; ++side) {
            auto corner = [&](double cu, double cv) {
                glm::dvec3 p;
                p[k] = side ? hi[k] : lo[k];
                p[u] = cu ? hi[u] : lo[u];
                p[v] = cv ? hi[v] : lo[v];
                return p;
            };
            if (side) addQuad(part, corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
            else addQuad(part, corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0));
        }
    }
}


// A surface of revolution about +z of a profile that starts and ends on the axis (r = 0),
// so the surface is closed; walking the profile with the solid on its left keeps the
// winding outward. `place` moves it into the model.
void addLathe(ShapePart& part, const std::vector<ProfilePoint>& profile, int segments, const glm::dmat4& place,
              const NormalAt& normalAt) {
    size_t start = 0;
    while (start + 1 < profile.size()) {
        size_t end = start + 1;
        while (end + 1 < profile.size() && !profile[end].crease) ++end;
        Grid grid;
        for (size_t i = start; i <= end; ++i) {
            std::vector<glm::dvec3> row;
            for (int j = 0; j < segments; ++j) {
                // The angle runs clockwise seen from +z: with rows along the profile this
                // makes ∂row × ∂column point away from the axis.
                const glm::dvec2 cs = circle(-j, segments);
                row.push_back(glm::dvec3(place * glm::dvec4(profile[i].r * cs.x, profile[i].r * cs.y, profile[i].z, 1.0)));
            }
            grid.push_back(row);
        }
        addGrid(part, grid, true, normalAt);
        start = end;
    }
}

// A closed cylinder of radius r about +z from z0 to z1.
void addCylinder(ShapePart& part, double r, double z0, double z1, int segments, const glm::dmat4& place) {
    addLathe(part, {{0.0, z0}, {r, z0, true}, {r, z1, true}, {0.0, z1}}, segments, place);
}

// A flat plate: polygon `outline` (counter-clockwise in (u, v), star-shaped about its first
// point) in the plane origin + p·u + q·v, `thickness` thick along u × v.
void addPlate(ShapePart& part, const std::vector<glm::dvec2>& outline, const glm::dvec3& origin, const glm::dvec3& u,
              const glm::dvec3& v, double thickness) {
    const glm::dvec3 w = glm::normalize(glm::cross(u, v)) * (0.5 * thickness);
    std::vector<glm::dvec3> front, back;
    for (const glm::dvec2& p : outline) {
        front.push_back(origin + p.x * u + p.y * v + w);
        back.push_back(origin + p.x * u + p.y * v - w);
    }
    const size_t n = outline.size();
    for (int side = 0; side < 2; ++side) {
        const uint32_t base = uint32_t(part.positions.size());
        const std::vector<glm::dvec3>& face = side ? back : front;
        for (const glm::dvec3& p : face) {
            part.positions.push_back(toFloat(p));
            part.normals.push_back(unit(side ? -w : w));
        }
        for (size_t k = 1; k + 1 < n; ++k) {
            part.indices.push_back(base);
            part.indices.push_back(base + uint32_t(side ? k + 1 : k));
            part.indices.push_back(base + uint32_t(side ? k : k + 1));
        }
    }
    for (size_t k = 0; k < n; ++k) {
        const size_t k1 = (k + 1) % n;
        addQuad(part, front[k], back[k], back[k1], front[k1]);
    }
}

ShapePart makePart(const char* name, glm::vec3 color, float metallic, float roughness) {
    ShapePart p;
    p.name = name;
    p.color = color;
    p.metallic = metallic;
    p.roughness = roughness;
    return p;
}

// Rigid placement: rotation taking +z to `axis` (one of ±x, +y, +z), then a translation.
glm::dmat4 placeAlong(char axis, const glm::dvec3& at) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), at);
    if (axis == 'x') return m * glm::dmat4(glm::dvec4(0, 0, -1, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, 0, 1));
    if (axis == 'y') return m * glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, -1, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 0, 1));
    return m;
}
} // namespace ob::game::shape
