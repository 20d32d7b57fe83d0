// The water's detail map (gfx::makeDetailMap, RGBA8: a software rasteriser filters 8-bit
// texels on its fast path) and the persistent foam's bubble pattern made from it.
#include "common_bindings.glsl"

layout(binding = DETAIL_UNIT) uniform sampler2D u_detail;  // rg DU/DV stored as 0.5 + 0.5·(du, dv), b foam streaks

// (du, dv) ∈ [−1, 1]² and the foam streaks ∈ [0, 1] of a detail map lookup.
vec3 decodeDetail(vec4 texel) { return vec3(texel.xy * 2.0 - 1.0, texel.b); }

const float FOAM_PATTERN_LOW = 0.47;   // pow(ridges, 0.4) at 5% of the detail map's foam streaks
const float FOAM_PATTERN_HIGH = 0.88;  // ...and at 95%
// The pattern repeats every this many foam tiles: its octaves are 8/3 and 22/3 of the first.
const float FOAM_PATTERN_REPEAT = 3.0;
// The foam's bubbles: the pattern again this many times finer (an integer, so they repeat with it),
// baked into the map's alpha.
const float FOAM_BUBBLE_SCALE = 5.0;
const float FOAM_BUBBLE_OFFSET = 0.41;  // foam tiles, so the bubbles do not line up with the lace

#ifdef FOAM_PATTERN_BAKE
#define FOAM_DETAIL(uv) textureLod(u_detail, uv, 0.0)  // baked at full detail: the baked map's mips minify
#else
#define FOAM_DETAIL(uv) texture(u_detail, uv)
#endif

// At fuv (foam tiles): the DU/DV that frays the foam's edges, and the bubble pattern, three
// octaves of the detail map's streaks (periods 1, 3/8 and 3/22 of a tile) sharpened and
// spread over [0, 1]: pow(ridges, 0.4) lies between FOAM_PATTERN_LOW and _HIGH at 5% and 95%
// of the program's detail map, nearly uniform between, so a threshold at 1 − x covers about x
// of the surface. The water shader reads it baked (foam_pattern_bake.frag), or per pixel at
// full quality.
vec3 foamPattern(vec2 fuv) {
    vec3 fine = decodeDetail(FOAM_DETAIL(fuv));
    float ridges = 0.5 * fine.z + 0.3 * FOAM_DETAIL(fuv * (8.0 / 3.0) + 0.37).b + 0.2 * FOAM_DETAIL(fuv * (22.0 / 3.0) + 0.71).b;
    float pattern = clamp((pow(ridges, 0.4) - FOAM_PATTERN_LOW) / (FOAM_PATTERN_HIGH - FOAM_PATTERN_LOW), 0.0, 1.0);
    return vec3(fine.xy, pattern);
}
