#version 450 core
// The coarse ripple levels between their steps (docs/ewave.md#levels): each level's height is
// the cubic Hermite in time of its last two states, weights·(h0, h1, v0, v1) per cell (the CPU's
// RippleLevels::height), and its slope the central differences of that height with 0 outside the
// grid, (h(i+1) − h(i−1), h(j+1) − h(j−1))/2Δ on an (N + 2)² grid whose texel (i + 1, j + 1) is
// cell (i, j) (as level 0's). One invocation per slope texel; the states are uploaded only when a
// level steps, so per frame the CPU sends four weights.
#include "ripple_levels_bindings.glsl"
layout(local_size_x = RIPPLE_LEVEL_TILE, local_size_y = RIPPLE_LEVEL_TILE) in;

layout(binding = RIPPLE_LEVEL_STATES_UNIT) uniform sampler2DArray u_states;
layout(binding = RIPPLE_LEVEL_HEIGHT_IMAGE, r32f) writeonly uniform image2DArray u_heights;
layout(binding = RIPPLE_LEVEL_SLOPE_IMAGE, rg32f) writeonly uniform image2DArray u_levelSlopes;
layout(location = RIPPLE_LEVEL_LOCATION) uniform int u_level;
layout(location = RIPPLE_LEVEL_WEIGHTS_LOCATION) uniform vec4 u_weights;
layout(location = RIPPLE_LEVEL_GRID_LOCATION) uniform vec2 u_grid;

// The cubic at cell c, 0 off the grid.
float height(ivec2 c) {
    int n = int(u_grid.x);
    if (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, ivec2(n)))) return 0.0;
    int base = 4 * u_level;
    return u_weights.x * texelFetch(u_states, ivec3(c, base), 0).r + u_weights.y * texelFetch(u_states, ivec3(c, base + 1), 0).r +
           u_weights.z * texelFetch(u_states, ivec3(c, base + 2), 0).r + u_weights.w * texelFetch(u_states, ivec3(c, base + 3), 0).r;
}

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    int n = int(u_grid.x);
    if (any(greaterThanEqual(t, ivec2(n + 2)))) return;
    ivec2 c = t - 1;
    if (all(greaterThanEqual(c, ivec2(0))) && all(lessThan(c, ivec2(n)))) imageStore(u_heights, ivec3(c, u_level), vec4(height(c)));
    float scale = 1.0 / (2.0 * u_grid.y);
    vec2 slope = scale * vec2(height(c + ivec2(1, 0)) - height(c - ivec2(1, 0)), height(c + ivec2(0, 1)) - height(c - ivec2(0, 1)));
    imageStore(u_levelSlopes, ivec3(t, u_level), vec4(slope, 0.0, 0.0));
}
