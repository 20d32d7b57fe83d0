// WaterQuery's default batch path and the flat-water stub.
#include "water/water_query.h"

#include <cassert>

namespace ob::water {

void WaterQuery::sampleBatch(std::span<const glm::vec2> points, std::span<WaterSample> out) const {
    assert(points.size() == out.size());
    for (size_t i = 0; i < points.size(); ++i) out[i] = sample(points[i].x, points[i].y);
}

WaterSample FlatWater::sample(float, float, WaterLayers) const {
    WaterSample s;
    s.height = m_height;
    return s;
}

void FlatWater::sampleBatch(std::span<const glm::vec2> points, std::span<WaterSample> out) const {
    assert(points.size() == out.size());
    for (size_t i = 0; i < points.size(); ++i) out[i] = sample(points[i].x, points[i].y);
}

} // namespace ob::water
