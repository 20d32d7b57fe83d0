// A hull's clip outline sliced from its model's triangles (hull_outline.h).
#include "assets/hull_outline.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

namespace ob::assets {

namespace {

using Outline = HullOutline;

float stationW(int i) { return -float(std::cos(std::numbers::pi * double(i) / double(Outline::STATIONS - 1))); }

// The fraction t of a height y above keel k at a station: y = k + (1 − k)·t⁴.
float heightT(float y, float k) { return std::sqrt(std::sqrt(std::clamp((y - k) / std::max(1.0f - k, 1e-6f), 0.0f, 1.0f))); }

// Where the line {y, z} (unit cube) crosses triangle abc (projected on the y–z plane): its |x|,
// or −1 where it misses.
float crossing(glm::vec3 a, glm::vec3 b, glm::vec3 c, float y, float z) {
    const float det = (b.y - a.y) * (c.z - a.z) - (c.y - a.y) * (b.z - a.z);
    if (std::abs(det) < 1e-12f) return -1.0f;
    const float u = ((y - a.y) * (c.z - a.z) - (c.y - a.y) * (z - a.z)) / det;
    const float v = ((b.y - a.y) * (z - a.z) - (y - a.y) * (b.z - a.z)) / det;
    constexpr float EDGE = -1e-5f;  // a line along an edge shared by two triangles hits both
    if (u < EDGE || v < EDGE || u + v > 1.0f - EDGE) return -1.0f;
    return std::abs(a.x + u * (b.x - a.x) + v * (c.x - a.x));
}

// The triangles in the unit cube that reach station w (z within their span).
struct Slice {
    std::vector<glm::vec3> corners;  // 3 a triangle
};

Slice sliceAt(const std::vector<glm::vec3>& unit, const std::vector<uint32_t>& indices, float w) {
    Slice s;
    for (size_t k = 0; k + 2 < indices.size(); k += 3) {
        const glm::vec3 a = unit[indices[k]], b = unit[indices[k + 1]], c = unit[indices[k + 2]];
        if (std::min({a.z, b.z, c.z}) > w || std::max({a.z, b.z, c.z}) < w) continue;
        s.corners.insert(s.corners.end(), {a, b, c});
    }
    return s;
}

// The largest |x| of the slice at height y (−1: none).
float widthAt(const Slice& s, float y, float w) {
    float x = -1.0f;
    for (size_t k = 0; k < s.corners.size(); k += 3) x = std::max(x, crossing(s.corners[k], s.corners[k + 1], s.corners[k + 2], y, w));
    return x;
}

// The lowest y of the slice's crossings of station w within the box (1: none).
float keelOf(const Slice& s, float w) {
    float keel = 1.0f;
    for (size_t k = 0; k < s.corners.size(); k += 3) {
        const glm::vec3 p[3] = {s.corners[k], s.corners[k + 1], s.corners[k + 2]};
        for (int e = 0; e < 3; ++e) {  // each edge's crossing of the plane z = w
            const glm::vec3 a = p[e], b = p[(e + 1) % 3];
            if ((a.z - w) * (b.z - w) > 0.0f || a.z == b.z) {
                if (a.z == w) keel = std::min(keel, a.y);
                continue;
            }
            const float y = a.y + (w - a.z) / (b.z - a.z) * (b.y - a.y);
            keel = std::min(keel, y);
        }
    }
    return std::max(keel, -1.0f);
}

} // namespace

HullOutline hullOutline(const ModelData& model, glm::vec3 boxMin, glm::vec3 boxMax) {
    const glm::vec3 centre = 0.5f * (boxMin + boxMax), half = 0.5f * (boxMax - boxMin);
    std::vector<glm::vec3> unit(model.positions.size());
    for (size_t i = 0; i < unit.size(); ++i) unit[i] = (model.positions[i] - centre) / half;
    HullOutline out;
    out.table.assign(size_t(Outline::STATIONS) * Outline::ROW, 0.0f);
    for (int i = 0; i < Outline::STATIONS; ++i) {
        // The end stations lie on the box's faces; their sections are the hull's end points.
        const float w = std::clamp(stationW(i), -1.0f + 1e-4f, 1.0f - 1e-4f);
        const Slice slice = sliceAt(unit, model.indices, w);
        float* row = out.table.data() + size_t(i) * Outline::ROW;
        const float keel = keelOf(slice, w);
        row[0] = keel;
        for (int j = 0; j < Outline::HEIGHTS && keel < 1.0f; ++j) {
            const float t = float(j) / float(Outline::HEIGHTS - 1), t2 = t * t;
            // Just above the keel and just under the top: a line along a flat bottom or a deck
            // touches it edge-on.
            const float y = std::clamp(keel + (1.0f - keel) * t2 * t2, keel + 1e-4f, 1.0f - 1e-4f);
            row[1 + j] = std::max(widthAt(slice, y, w), 0.0f);
        }
    }
    return out;
}

float halfBeam(const HullOutline& outline, float w, float y) {
    const float s = std::acos(std::clamp(-w, -1.0f, 1.0f)) / float(std::numbers::pi) * float(Outline::STATIONS - 1);
    const int i = std::clamp(int(s), 0, Outline::STATIONS - 2);
    const float f = std::clamp(s - float(i), 0.0f, 1.0f);
    const float* a = outline.table.data() + size_t(i) * Outline::ROW;
    const float* b = a + Outline::ROW;
    const float keel = glm::mix(a[0], b[0], f);
    if (y <= keel || keel >= 1.0f) return 0.0f;
    // The same share of the depth at both stations (as the hull is lofted), t from it.
    const float t = heightT(std::min(y, 1.0f), keel) * float(Outline::HEIGHTS - 1);
    const int j = std::min(int(t), Outline::HEIGHTS - 2);
    const float u = t - float(j);
    return glm::mix(glm::mix(a[1 + j], a[2 + j], u), glm::mix(b[1 + j], b[2 + j], u), f);
}

} // namespace ob::assets
