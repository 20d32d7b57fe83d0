// The project's vessels and creatures: lofted hull, lathed barrels and spheres, extruded fins,
// boxes (model_geometry.h); the props (crate, barrel, buoy, ...) are in model_props.cpp.
#include "tools/model_geometry.h"

#include <algorithm>
#include <array>

namespace ob::game {

namespace {

using namespace shape;

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
    std::vector<ShapeModel> models = {buildShip(),           buildFish(false),      buildFish(true),
                                      buildCannonball(false), buildCannonball(true), buildCannon()};
    for (ShapeModel& prop : buildPropModels()) models.push_back(std::move(prop));
    return models;
}

} // namespace ob::game

