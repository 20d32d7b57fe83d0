// The weather of the sky, section [sky]: cloud cover over the sea (docs/look.md#weather).
#pragma once
#include "core/schema.h"

namespace ob::gfx {

/// Clouds: drawn in the sky and its reflection, dimming and softening the sun and greying the
/// diffuse light as they cover it (shaders/common_sky.glsl). The sea presets set cloud_cover.
struct SkyDef {
    float cloud_cover = 0.0f;    ///< share of the sky the clouds cover, [0, 1]: 0 clear, 1 overcast (no sun disc, grey diffuse light)
    float wind_aloft = 12.0f;    ///< speed the clouds drift at, downwind (the sea's wind direction), m/s, [0, 100]
    float cloud_height = 1500.0f;///< height of the cloud layer above the sea, m, [100, 10000]
};

template <class V> void describe(V& v, SkyDef& d) {
    v.field("cloud_cover", d.cloud_cover, range(0, 1), "share of the sky covered by clouds: 0 clear, 1 overcast (sun hidden, light grey and diffuse)", LIVE);
    v.field("wind_aloft", d.wind_aloft, range(0, 100), "the clouds' drift speed along the sea's wind, m/s", LIVE);
    v.field("cloud_height", d.cloud_height, range(100, 10000), "height of the cloud layer, m", LIVE);
}

} // namespace ob::gfx
