// The props that float, mark and stand in the scenes: crate, barrel, raft, target, buoy, ball,
// the cannon's pillar and a breakwater's wall. Box-like props span [−1, 1]³ and a round prop is of radius 1, as
// the built-in box and sphere: the object's size stretches them (sim/objects.cpp).
#include "tools/model_geometry.h"

namespace ob::game {

namespace {

using namespace shape;

constexpr glm::vec3 OAK{0.50f, 0.34f, 0.18f};       // planks, linear RGB
constexpr glm::vec3 OAK_DARK{0.30f, 0.19f, 0.09f};  // battens and beams
constexpr glm::vec3 IRON{0.10f, 0.10f, 0.11f};
constexpr glm::vec3 SIGNAL_RED{0.62f, 0.05f, 0.03f};
constexpr glm::vec3 PAINT_WHITE{0.85f, 0.85f, 0.82f};

// The twelve edges of the box [−h, h]³ as battens `w` thick on both sides of the edge's line,
// set `w` inside the box's faces.
void addEdgeBattens(ShapePart& part, double h, double w) {
    for (int axis = 0; axis < 3; ++axis)
        for (double a : {-1.0, 1.0})
            for (double b : {-1.0, 1.0}) {
                glm::dvec3 lo, hi;
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                lo[axis] = -h;
                hi[axis] = h;
                lo[u] = a > 0 ? h - w : -h;
                hi[u] = a > 0 ? h : -h + w;
                lo[v] = b > 0 ? h - w : -h;
                hi[v] = b > 0 ? h : -h + w;
                addBox(part, lo, hi);
            }
}

// A wooden crate: a planked body, a batten on every edge and a plank's seam across each side.
ShapeModel buildCrate() {
    ShapePart planks = makePart("planks", OAK, 0.0f, 0.85f);
    ShapePart battens = makePart("battens", OAK_DARK, 0.0f, 0.9f);
    addBox(planks, {-0.96, -0.96, -0.96}, {0.96, 0.96, 0.96});
    addEdgeBattens(battens, 1.0, 0.16);
    for (double y : {-0.32, 0.32}) addBox(battens, {-0.98, y - 0.03, -0.98}, {0.98, y + 0.03, 0.98});
    return {"crate", {planks, battens}};
}

// A barrel standing on end (axis +y): bulged staves, flat heads, four iron hoops.
ShapeModel buildBarrel() {
    ShapePart staves = makePart("staves", OAK, 0.0f, 0.8f);
    ShapePart hoops = makePart("hoops", IRON, 0.9f, 0.5f);
    // Stave radius r(z) = 0.80 + 0.20·(1 − z²): the bilge at mid-height touches the unit box.
    std::vector<ProfilePoint> profile = {{0.0, -1.0}, {0.8, -1.0, true}};
    for (int i = 1; i < 16; ++i) {
        const double z = -1.0 + 2.0 * i / 16.0;
        profile.push_back({0.80 + 0.20 * (1.0 - z * z), z});
    }
    profile.push_back({0.8, 1.0, true});
    profile.push_back({0.0, 1.0});
    addLathe(staves, profile, 32, placeAlong('y', {0.0, 0.0, 0.0}));
    for (double z : {-0.78, -0.42, 0.42, 0.78}) {
        const double r = 0.80 + 0.20 * (1.0 - z * z) + 0.015;
        addLathe(hoops, {{0.0, z - 0.04}, {r, z - 0.04, true}, {r, z + 0.04, true}, {0.0, z + 0.04}}, 32,
                 placeAlong('y', {0.0, 0.0, 0.0}));
    }
    return {"barrel", {staves, hoops}};
}

// A raft: five planks along x on two cross-beams beneath.
ShapeModel buildRaft() {
    ShapePart planks = makePart("planks", {0.58f, 0.44f, 0.26f}, 0.0f, 0.9f);
    ShapePart beams = makePart("beams", OAK_DARK, 0.0f, 0.9f);
    for (int k = 0; k < 5; ++k) {
        const double z0 = -1.0 + 0.4 * k;
        addBox(planks, {-1.0, -0.1, z0 + 0.02}, {1.0, 1.0, z0 + 0.38});
    }
    for (double x : {-0.7, 0.7}) addBox(beams, {x - 0.12, -1.0, -0.98}, {x + 0.12, -0.1, 0.98});
    return {"raft", {planks, beams}};
}

// A floating target: a white float with a red and white bull's-eye on top (discs stacked
// 4 cm apart so each ring shows).
ShapeModel buildTarget() {
    ShapePart white = makePart("float", PAINT_WHITE, 0.0f, 0.7f);
    ShapePart red = makePart("rings", SIGNAL_RED, 0.0f, 0.6f);
    addBox(white, {-1.0, -1.0, -1.0}, {1.0, 0.2, 1.0});
    const double radii[] = {0.95, 0.72, 0.48, 0.24};
    for (int k = 0; k < 4; ++k)
        addCylinder(k % 2 ? white : red, radii[k], 0.2, 0.24 + 0.04 * k, 40, placeAlong('y', {0.0, 0.0, 0.0}));
    return {"target", {white, red}};
}

// A sphere of radius 1 cut into `gores` segments of longitude: segment k goes to part k % size.
void addSphereGores(std::vector<ShapePart*> parts, int gores, int rings, int perGore) {
    for (int k = 0; k < gores; ++k) {
        Grid grid;
        for (int i = 0; i <= rings; ++i) {
            const glm::dvec2 lat = circle(i, 2 * rings);  // south pole → north pole
            std::vector<glm::dvec3> row;
            for (int j = 0; j <= perGore; ++j) {
                const glm::dvec2 lon = circle(k * perGore + j, gores * perGore);  // eastwards: outward winding
                row.push_back({lat.y * lon.x, -lat.x, lat.y * lon.y});
            }
            grid.push_back(row);
        }
        addGrid(*parts[size_t(k) % parts.size()], grid, false, [](const glm::dvec3& p) { return p; });
    }
}

// A beach ball: six gores, red, white and blue.
ShapeModel buildBall() {
    ShapePart red = makePart("red", SIGNAL_RED, 0.0f, 0.35f);
    ShapePart white = makePart("white", PAINT_WHITE, 0.0f, 0.35f);
    ShapePart blue = makePart("blue", {0.04f, 0.12f, 0.55f}, 0.0f, 0.35f);
    addSphereGores({&red, &white, &blue}, 6, 16, 6);
    return {"ball", {red, white, blue}};
}

// A buoy: a sphere in red and white bands with a pole and a ball for a topmark above it.
ShapeModel buildBuoy() {
    ShapePart red = makePart("red", SIGNAL_RED, 0.0f, 0.5f);
    ShapePart white = makePart("white", PAINT_WHITE, 0.0f, 0.5f);
    ShapePart pole = makePart("pole", IRON, 0.8f, 0.5f);
    // Bands of latitude: rings 0–5 red (below the water line), 6–9 white, 10–16 red.
    const int RINGS = 16;
    auto band = [&](ShapePart& part, int from, int to) {
        std::vector<ProfilePoint> profile;
        for (int i = from; i <= to; ++i) {
            const glm::dvec2 t = circle(i, 2 * RINGS);
            profile.push_back({t.y, -t.x});
        }
        addLathe(part, profile, 32, placeAlong('y', {0.0, 0.0, 0.0}), [](const glm::dvec3& p) { return p; });
    };
    band(red, 0, 6);
    band(white, 6, 10);
    band(red, 10, RINGS);
    addCylinder(pole, 0.06, 0.9, 1.9, 12, placeAlong('y', {0.0, 0.0, 0.0}));
    std::vector<ProfilePoint> ball;
    for (int i = 0; i <= 8; ++i) {
        const glm::dvec2 t = circle(i, 16);
        ball.push_back({0.22 * t.y, -0.22 * t.x});
    }
    addLathe(red, ball, 16, placeAlong('y', {0.0, 2.05, 0.0}));
    return {"buoy", {red, white, pole}};
}

// The cannon's stone pillar: an octagonal shaft of dressed stone under a square cap, spanning
// [−1, 1]³ (the cannon stretches it from the sea floor to its carriage).
ShapeModel buildPillar() {
    ShapePart stone = makePart("stone", {0.30f, 0.28f, 0.25f}, 0.0f, 0.95f);
    ShapePart cap = makePart("cap", {0.40f, 0.38f, 0.34f}, 0.0f, 0.9f);
    ShapePart courses = makePart("courses", {0.20f, 0.19f, 0.17f}, 0.0f, 0.95f);
    addLathe(stone, {{0.0, -1.0}, {0.85, -1.0, true}, {0.85, 0.9, true}, {0.0, 0.9}}, 8, placeAlong('y', {0.0, 0.0, 0.0}));
    addBox(cap, {-1.0, 0.9, -1.0}, {1.0, 1.0, 1.0});
    // Mortar courses: thin rings proud of the shaft.
    for (int k = 1; k < 8; ++k) {
        const double y = -1.0 + 0.2375 * k;
        addLathe(courses, {{0.0, y - 0.01}, {0.87, y - 0.01, true}, {0.87, y + 0.01, true}, {0.0, y + 0.01}}, 8,
                 placeAlong('y', {0.0, 0.0, 0.0}));
    }
    return {"pillar", {stone, cap, courses}};
}

// A breakwater's length of wall: dressed stone under a coping that overhangs it a little, with
// mortar courses along it.
ShapeModel buildWall() {
    ShapePart stone = makePart("stone", {0.30f, 0.28f, 0.25f}, 0.0f, 0.95f);
    ShapePart coping = makePart("coping", {0.40f, 0.38f, 0.34f}, 0.0f, 0.9f);
    ShapePart courses = makePart("courses", {0.20f, 0.19f, 0.17f}, 0.0f, 0.95f);
    addBox(stone, {-1.0, -1.0, -0.92}, {1.0, 0.85, 0.92});
    addBox(coping, {-1.0, 0.85, -1.0}, {1.0, 1.0, 1.0});
    for (int k = 1; k < 6; ++k) {
        const double y = -1.0 + 0.3 * k;
        addBox(courses, {-1.0, y - 0.012, -0.93}, {1.0, y + 0.012, 0.93});
    }
    return {"wall", {stone, coping, courses}};
}

} // namespace

std::vector<ShapeModel> buildPropModels() {
    return {buildCrate(), buildBarrel(), buildRaft(), buildTarget(), buildBall(), buildBuoy(), buildPillar(), buildWall()};
}

} // namespace ob::game
