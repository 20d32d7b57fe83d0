// The hull clip's outline against the model the body draws: the ship model's section, found
// here by casting rays at its triangles (Möller–Trumbore), at 20 stations along the hull and
// heights from its keel to its deck, is where the clip's outline (assets::halfBeam, as the
// shader reads it) puts it, within 1 cm; and a model that is not a ship gets its own outline.
#include "assets/hull_outline.h"
#include "assets/model.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace ob;

namespace {

// The ship model's hull box (make-models: beam 3 m, keel to deck 1.5 m, length 10 m).
constexpr glm::vec3 SHIP_HALF{1.5f, 0.75f, 5.0f};
constexpr double TOLERANCE_M = 0.01;

// The nearest hit of the ray o + s·d (s > 0) with the model's triangles.
std::optional<double> castRay(const assets::ModelData& m, glm::dvec3 o, glm::dvec3 d) {
    std::optional<double> best;
    for (size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        const glm::dvec3 a(m.positions[m.indices[k]]), b(m.positions[m.indices[k + 1]]), c(m.positions[m.indices[k + 2]]);
        const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-15) continue;
        const glm::dvec3 t = o - a;
        const double u = glm::dot(t, p) / det;
        const glm::dvec3 q = glm::cross(t, e1);
        const double v = glm::dot(d, q) / det, s = glm::dot(e2, q) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0 || s <= 0.0) continue;
        if (!best || s < *best) best = s;
    }
    return best;
}

// The model's half-beam at height y, length z (m): a ray from far to starboard, toward −x.
double modelHalfBeam(const assets::ModelData& m, double y, double z) {
    const std::optional<double> s = castRay(m, {10.0, y, z}, {-1.0, 0.0, 0.0});
    return s ? 10.0 - *s : 0.0;
}

// The model's keel at length z (m): a ray from below on the centre line, up.
double modelKeel(const assets::ModelData& m, double z) {
    const std::optional<double> s = castRay(m, {0.0, -10.0, z}, {0.0, 1.0, 0.0});
    REQUIRE(s.has_value());
    return -10.0 + *s;
}

} // namespace

TEST_CASE("hull clip: the outline from the ship model agrees with the model at 20 stations within 1 cm", "[hull][model]") {
    const assets::ModelData ship = assets::loadGltfModel(assets::projectModel("ship"));
    const assets::HullOutline outline = assets::hullOutline(ship, -SHIP_HALF, SHIP_HALF);
    double worst = 0.0;
    for (int k = 0; k < 20; ++k) {
        const double z = -SHIP_HALF.z + 2.0 * SHIP_HALF.z * (k + 0.5) / 20.0;
        const double keel = modelKeel(ship, z), deck = SHIP_HALF.y;
        for (double f : {0.02, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99}) {
            const double y = keel + f * (deck - keel);
            const double model = modelHalfBeam(ship, y, z);
            const double clip = SHIP_HALF.x * assets::halfBeam(outline, float(z / SHIP_HALF.z), float(y / SHIP_HALF.y));
            INFO("station z = " << z << " m, height y = " << y << " m (keel " << keel << "): model " << model << " m, clip " << clip << " m");
            CHECK(std::abs(clip - model) <= TOLERANCE_M);
            worst = std::max(worst, std::abs(clip - model));
        }
        // Under the keel the clip holds nothing.
        CHECK(assets::halfBeam(outline, float(z / SHIP_HALF.z), float((keel - 0.01) / SHIP_HALF.y)) == 0.0f);
    }
    INFO("largest difference " << worst << " m");
    CHECK(worst > 0.0);  // the outline is sampled: it is not the model itself
}

TEST_CASE("hull clip: another model gets its own outline, not the ship's", "[hull][model]") {
    // The raft spans [−1, 1]³ and is a box: its outline is the whole box where the ship's tapers.
    const assets::ModelData raft = assets::loadGltfModel(assets::projectModel("raft"));
    const assets::HullOutline outline = assets::hullOutline(raft, raft.boundsMin, raft.boundsMax);
    const glm::vec3 half = 0.5f * (raft.boundsMax - raft.boundsMin);
    for (float w : {-0.9f, 0.0f, 0.9f}) {
        const double model = modelHalfBeam(raft, 0.0, double(w * half.z)) / double(half.x);
        INFO("w = " << w);
        CHECK(std::abs(assets::halfBeam(outline, w, 0.0f) - model) <= TOLERANCE_M / double(half.x));
    }
    const assets::ModelData ship = assets::loadGltfModel(assets::projectModel("ship"));
    const assets::HullOutline shipOutline = assets::hullOutline(ship, -SHIP_HALF, SHIP_HALF);
    CHECK(assets::halfBeam(shipOutline, 0.9f, 0.0f) < 0.5f * assets::halfBeam(outline, 0.9f, 0.0f));
}
