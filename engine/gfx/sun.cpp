// The sun's place by the hour (formulas: sun.h).
#include "gfx/sun.h"

#include <cmath>
#include <numbers>
#include <glm/geometric.hpp>

namespace ob::gfx {

glm::vec3 sunAtHour(float hour, float latitudeDeg, float declinationDeg) {
    constexpr double DEG = std::numbers::pi / 180.0;
    const double h = 15.0 * (double(hour) - 12.0) * DEG;
    const double phi = double(latitudeDeg) * DEG, delta = double(declinationDeg) * DEG;
    const double east = -std::cos(delta) * std::sin(h);
    const double north = std::sin(delta) * std::cos(phi) - std::cos(delta) * std::sin(phi) * std::cos(h);
    const double up = std::sin(delta) * std::sin(phi) + std::cos(delta) * std::cos(phi) * std::cos(h);
    return glm::normalize(glm::vec3(float(east), float(up), float(-north)));
}

glm::vec3 sunDirection(const RenderDef& def) {
    if (def.time_of_day >= 0.0f) return sunAtHour(def.time_of_day, def.latitude_deg, def.sun_declination_deg);
    return glm::normalize(def.sun_direction);
}

} // namespace ob::gfx
