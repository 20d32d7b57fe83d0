// Rendering settings, section [render].
#pragma once
#include "core/schema.h"

#include <string>

namespace ob::gfx {

/// Look of the sky and the water surface.
struct RenderDef {
    glm::vec3 sun_direction{0.35f, 0.30f, 0.88f};  ///< direction toward the sun (world, y up; normalised on use)
    glm::vec3 water_color{0.015f, 0.09f, 0.13f};   ///< deep water body colour (linear RGB, 0..1)
    std::string fresnel = "schlick";                ///< "schlick" approximation or "exact" unpolarised equations (n = 1.33)
    float exposure = 1.0f;                          ///< scene exposure multiplier before tone mapping, [0.01, 16]
    int grid_resolution = 0;                        ///< projected grid cells per side, [16, 2048]; 0 = auto (128 on a software rasteriser, 512 on a GPU)
};

template <class V> void describe(V& v, RenderDef& d) {
    v.field("sun_direction", d.sun_direction, direction(), "direction toward the sun (world, y up)");
    v.field("water_color", d.water_color, range(0, 1), "deep water body colour (linear RGB)");
    v.field("fresnel", d.fresnel, Choices{"schlick", "exact"}, "Fresnel term: Schlick or exact (n = 1.33)");
    v.field("exposure", d.exposure, range(0.01, 16), "exposure multiplier before tone mapping");
    v.field("grid_resolution", d.grid_resolution, range(0, 2048), "projected grid cells per side; 0 = auto (128 software, 512 GPU)");
}

} // namespace ob::gfx
