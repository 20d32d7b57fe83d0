// Procedural models: lofted hull, lathed barrels and spheres, extruded fins, boxes. Every
// surface is closed and wound counter-clockwise seen from outside; smooth normals are the
// area-weighted face normals of one surface patch, creases come from separate patches.
#include "tools/model_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

namespace ob::game {

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

// (cos, sin) of 2π·k/n, exact at quarter turns so poles and keels land on exact zeros.
glm::dvec2 circle(int k, int n) {
    k = ((k % n) + n) % n;
    if ((4 * k) % n == 0) {
        static const glm::dvec2 QUARTERS[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
        return QUARTERS[(4 * k) / n];
    }
    return cosSin(2.0 * PI * double(k) / double(n));
}

glm::vec3 toFloat(const glm::dvec3& p) { return glm::vec3(float(p.x), float(p.y), float(p.z)); }

glm::vec3 unit(const glm::dvec3& v) {
    const double len = std::sqrt(glm::dot(v, v));
    return len > 0.0 ? toFloat(v / len) : glm::vec3(0.0f, 1.0f, 0.0f);
}

using Grid = std::vector<std::vector<glm::dvec3>>;  // [row][column] points
using NormalAt = std::function<glm::dvec3(const glm::dvec3&)>;

// A patch from a grid of points: cell (i, j) → triangles (i,j)(i+1,j)(i+1,j+1) and
// (i,j)(i+1,j+1)(i,j+1), so the face normal is ∂row × ∂column; `wrap` joins the last
// column to the first. Triangles with two equal corners (poles, tips) are left out.
// Normals: `normalAt` if given, else the area-weighted face normals summed per position.
void addGrid(ShapePart& part, const Grid& grid, bool wrap, const NormalAt& normalAt = nullptr) {
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

// One point of a lathe profile: radius r and height z on the axis; a crease ends one
// smooth run of the profile and starts the next (a hard edge).
struct ProfilePoint {
    double r, z;
    bool crease = false;
};

// A surface of revolution about +z of a profile that starts and ends on the axis (r = 0),
// so the surface is closed; walking the profile with the solid on its left keeps the
// winding outward. `place` moves it into the model.
void addLathe(ShapePart& part, const std::vector<ProfilePoint>& profile, int segments, const glm::dmat4& place,
              const NormalAt& normalAt = nullptr) {
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

// --- ship -------------------------------------------------------------------------------

// One hull station at z: the half-beam of the deck outline (pointed bow: a parabola, zero
// at z = 5; straight waist; round stern: a quarter ellipse, zero at z = −5) and the keel
// height (−0.75 along the waist, rising towards both ends: the forefoot and the run).
struct Station {
    double z, halfBeam, keel;
};

std::vector<Station> hullStations() {
    std::vector<Station> s;
    const int STERN = 8, WAIST = 8, BOW = 14;
    for (int k = 0; k <= STERN; ++k) {
        const glm::dvec2 cs = circle(k, 4 * STERN);  // quarter turn in STERN steps
        s.push_back({-3.0 - 2.0 * cs.x, 1.5 * cs.y, -0.75 + 0.25 * cs.x * cs.x});
    }
    for (int k = 1; k <= WAIST; ++k) s.push_back({-3.0 + 4.0 * k / WAIST, 1.5, -0.75});
    for (int k = 1; k <= BOW; ++k) {
        const double t = double(k) / BOW;
        s.push_back({1.0 + 4.0 * t, 1.5 * (1.0 - t * t), -0.75 + 0.5 * t * t * t});
    }
    return s;
}

// A point of the hull's section at station `st`: m = 0 at the deck edge to m = QUARTER at
// the keel, on the starboard (+x) or port side. y = 0.75 − depth·g(sin φ), g(s) = s(2 − s):
// vertical sides under the deck edge, a flat run at the keel.
glm::dvec3 hullPoint(const Station& st, int m, bool starboard) {
    constexpr int QUARTER = 16;
    const glm::dvec2 cs = circle(m, 4 * QUARTER);
    const double x = st.halfBeam * cs.x;
    return {starboard ? x : -x, 0.75 - (0.75 - st.keel) * cs.y * (2.0 - cs.y), st.z};
}

ShapeModel buildShip() {
    constexpr int QUARTER = 16;
    const std::vector<Station> stations = hullStations();
    ShapePart hull = makePart("hull", {0.30f, 0.17f, 0.08f}, 0.0f, 0.85f);
    ShapePart wale = makePart("hull_stripe", {0.50f, 0.07f, 0.05f}, 0.0f, 0.8f);
    ShapePart deck = makePart("deck", {0.62f, 0.45f, 0.27f}, 0.0f, 0.9f);
    ShapePart cabin = makePart("cabin", {0.46f, 0.30f, 0.16f}, 0.0f, 0.85f);
    ShapePart spars = makePart("mast", {0.36f, 0.23f, 0.12f}, 0.0f, 0.8f);
    ShapePart sail = makePart("sail", {0.90f, 0.88f, 0.80f}, 0.0f, 0.95f);
    ShapePart pennant = makePart("pennant", {0.60f, 0.06f, 0.04f}, 0.0f, 0.9f);

    // Hull: rows are stations stern → bow, columns run starboard deck edge → keel → port
    // deck edge, so ∂row × ∂column points out of the hull. Each side is its own patch: at
    // the bow and stern tips the sides meet in a sharp stem, whose normals must not blend
    // (at the flat keel both sides' normals are −y anyway). The top band is the stripe.
    Grid starboardLower, portLower, starboardBand, portBand, deckGrid;
    for (const Station& st : stations) {
        starboardLower.emplace_back();
        portLower.emplace_back();
        for (int m = 1; m <= QUARTER; ++m) starboardLower.back().push_back(hullPoint(st, m, true));
        for (int m = QUARTER; m >= 1; --m) portLower.back().push_back(hullPoint(st, m, false));
        starboardBand.push_back({hullPoint(st, 0, true), hullPoint(st, 1, true)});
        portBand.push_back({hullPoint(st, 1, false), hullPoint(st, 0, false)});
        deckGrid.push_back({hullPoint(st, 0, false), hullPoint(st, 0, true)});
    }
    addGrid(hull, starboardLower, false);
    addGrid(hull, portLower, false);
    addGrid(wale, starboardBand, false);
    addGrid(wale, portBand, false);
    addGrid(deck, deckGrid, false, [](const glm::dvec3&) { return glm::dvec3(0.0, 1.0, 0.0); });

    // Cabin at the stern with an overhanging roof.
    addBox(cabin, {-0.9, 0.75, -4.0}, {0.9, 1.6, -2.4});
    addBox(cabin, {-1.0, 1.6, -4.1}, {1.0, 1.7, -2.3});

    // Mast (foot inside the hull), yard across it near the top.
    const double MAST_Z = 0.6;
    addLathe(spars, {{0.0, 0.7}, {0.13, 0.7, true}, {0.09, 7.0, true}, {0.0, 7.0}}, 20, placeAlong('y', {0.0, 0.0, MAST_Z}));
    addCylinder(spars, 0.07, -1.4, 1.4, 16, placeAlong('x', {0.0, 6.4, MAST_Z + 0.15}));

    // Square sail under the yard, bellied forward (+z): a 4 cm thick sheet, front, back and rim.
    const int KU = 16, KV = 16;
    const double T = 0.04;
    auto mid = [&](int k, int l) {
        const double u = -1.3 + 2.6 * k / KU;
        const double belly = 0.3 * (1.0 - (u / 1.3) * (u / 1.3)) * circle(l, 2 * KV).y;
        return glm::dvec3(u, 2.4 + 3.9 * l / KV, MAST_Z + 0.26 + belly);
    };
    const glm::dvec3 half(0.0, 0.0, 0.5 * T);
    Grid front, back;
    for (int k = 0; k <= KU; ++k) {
        front.emplace_back();
        for (int l = 0; l <= KV; ++l) front.back().push_back(mid(k, l) + half);
    }
    for (int l = 0; l <= KV; ++l) {
        back.emplace_back();
        for (int k = 0; k <= KU; ++k) back.back().push_back(mid(k, l) - half);
    }
    addGrid(sail, front, false);
    addGrid(sail, back, false);
    // Rim: the outline counter-clockwise seen from +z, columns back → front.
    std::vector<std::array<int, 2>> loops[4];
    for (int k = 0; k <= KU; ++k) loops[0].push_back({k, 0});
    for (int l = 0; l <= KV; ++l) loops[1].push_back({KU, l});
    for (int k = KU; k >= 0; --k) loops[2].push_back({k, KV});
    for (int l = KV; l >= 0; --l) loops[3].push_back({0, l});
    for (const auto& loop : loops) {
        Grid rim;
        for (const auto& [k, l] : loop) rim.push_back({mid(k, l) - half, mid(k, l) + half});
        addGrid(sail, rim, false);
    }
    // Pennant at the masthead, streaming aft: a plate in the y–z plane, outline as (z, y).
    addPlate(pennant, {{MAST_Z, 6.7}, {MAST_Z, 6.95}, {MAST_Z - 0.8, 6.82}}, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0.01);
    return {"ship", {hull, wale, deck, cabin, spars, sail, pennant}};
}

// --- fish -------------------------------------------------------------------------------

// `coarse`: the far twin (fish.lod1), drawn where a fish covers a few pixels: an 8 × 8 body,
// the same fins, no eyes (a tenth of the triangles).
ShapeModel buildFish(bool coarse) {
    ShapePart body = makePart("body", {0.55f, 0.66f, 0.78f}, 0.3f, 0.35f);
    ShapePart fins = makePart("fins", {0.28f, 0.40f, 0.58f}, 0.1f, 0.5f);
    ShapePart eyes = makePart("eyes", {0.02f, 0.02f, 0.025f}, 0.0f, 0.2f);

    // Body: elliptic sections (half-width 0.07, half-height 0.13 at most) along z from the
    // tail end −0.32 to the nose 0.5; the profile sin θ·(1 − 0.3 cos θ) is fuller forward.
    const int ALONG = coarse ? 8 : 24, AROUND = coarse ? 8 : 24;
    const double A = 0.07, C = 0.13, ZC = 0.09, HALF_LENGTH = 0.41;
    Grid grid;
    for (int i = 0; i <= ALONG; ++i) {
        const glm::dvec2 t = circle(i, 2 * ALONG);  // θ from 0 (tail) to π (nose)
        const double f = t.y * (1.0 - 0.3 * t.x);
        std::vector<glm::dvec3> row;
        for (int j = 0; j < AROUND; ++j) {
            const glm::dvec2 cs = circle(-j, AROUND);
            row.push_back({A * f * cs.x, C * f * cs.y, ZC - HALF_LENGTH * t.x});
        }
        grid.push_back(row);
    }
    addGrid(body, grid, true);

    // Fins: plates in the y–z plane (u = +z, v = +y), outlines as (z, y).
    const glm::dvec3 Z(0, 0, 1), Y(0, 1, 0);
    addPlate(fins, {{-0.28, 0.0}, {-0.5, 0.17}, {-0.44, 0.0}, {-0.5, -0.17}}, {0, 0, 0}, Z, Y, 0.012);  // forked tail
    addPlate(fins, {{0.14, 0.09}, {0.02, 0.21}, {-0.10, 0.17}, {-0.12, 0.08}}, {0, 0, 0}, Z, Y, 0.010); // dorsal

    std::vector<ProfilePoint> ball;
    for (int i = 0; i <= 8; ++i) {
        const glm::dvec2 t = circle(i, 16);
        ball.push_back({0.018 * t.y, -0.018 * t.x});
    }
    if (coarse) return {"fish.lod1", {body, fins}};
    for (double side : {-1.0, 1.0}) addLathe(eyes, ball, 12, placeAlong('z', {side * 0.05, 0.035, 0.40}));
    return {"fish", {body, fins, eyes}};
}

// --- cannonball -------------------------------------------------------------------------

// `coarse`: the far twin (cannonball.lod1): 8 rings of 16 (a sixteenth of the triangles).
ShapeModel buildCannonball(bool coarse) {
    ShapePart iron = makePart("iron", {0.09f, 0.09f, 0.10f}, 1.0f, 0.5f);
    std::vector<ProfilePoint> half;
    const int RINGS = coarse ? 8 : 32;
    for (int i = 0; i <= RINGS; ++i) {
        const glm::dvec2 t = circle(i, 2 * RINGS);  // south pole → north pole
        half.push_back({t.y, -t.x});
    }
    addLathe(iron, half, 2 * RINGS, glm::dmat4(1.0), [](const glm::dvec3& p) { return p; });
    return {coarse ? "cannonball.lod1" : "cannonball", {iron}};
}

// --- cannon -----------------------------------------------------------------------------

ShapeModel buildCannon() {
    ShapePart barrel = makePart("barrel", {0.08f, 0.08f, 0.09f}, 1.0f, 0.45f);
    ShapePart wood = makePart("carriage", {0.42f, 0.26f, 0.13f}, 0.0f, 0.85f);
    ShapePart wheels = makePart("wheels", {0.27f, 0.16f, 0.08f}, 0.0f, 0.9f);

    // Barrel profile (r, z), breech knob → breech → reinforce ring → chase → muzzle → bore.
    std::vector<ProfilePoint> p;
    for (int i = 0; i <= 5; ++i) {
        const glm::dvec2 t = circle(i, 16);  // knob: 0.08 m ball at z = −1.0
        p.push_back({0.08 * t.y, -1.0 - 0.08 * t.x});
    }
    const std::vector<ProfilePoint> rest = {
        {0.035, -0.93, true}, {0.035, -0.90, true},          // neck
        {0.17, -0.90}, {0.215, -0.87}, {0.235, -0.82, true}, // rounded breech
        {0.25, -0.80, true}, {0.25, -0.62, true},            // reinforce ring
        {0.225, -0.62, true}, {0.18, 1.30, true},            // tapered chase
        {0.20, 1.34, true}, {0.20, 1.50, true},              // muzzle swell
        {0.085, 1.50, true}, {0.085, 0.20, true},            // bore
        {0.0, 0.20}};
    p.insert(p.end(), rest.begin(), rest.end());
    addLathe(barrel, p, 32, glm::dmat4(1.0));
    addCylinder(barrel, 0.07, -0.36, 0.36, 16, placeAlong('x', {0.0, 0.0, 0.0}));  // trunnions

    // Carriage: two cheeks holding the trunnions, a bed, two axles.
    for (double side : {-1.0, 1.0}) {
        const double inner = 0.26 * side, outer = 0.34 * side;
        addBox(wood, {std::min(inner, outer), -0.62, -0.95}, {std::max(inner, outer), 0.08, 0.55});
    }
    addBox(wood, {-0.34, -0.62, -0.95}, {0.34, -0.48, 0.55});
    for (double z : {0.35, -0.75}) {
        addCylinder(barrel, 0.05, -0.48, 0.48, 12, placeAlong('x', {0.0, -0.65, z}));  // iron axle
        for (double side : {-1.0, 1.0})
            addCylinder(wheels, 0.25, side > 0 ? 0.36 : -0.44, side > 0 ? 0.44 : -0.36, 24, placeAlong('x', {0.0, -0.65, z}));
    }
    return {"cannon", {barrel, wood, wheels}};
}

} // namespace

std::vector<ShapeModel> buildProjectModels() {
    return {buildShip(), buildFish(false), buildFish(true), buildCannonball(false), buildCannonball(true), buildCannon()};
}

} // namespace ob::game
