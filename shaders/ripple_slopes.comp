#version 450 core
// Level 0's ripple slopes on the GPU from the heights just uploaded: the central differences
// (h(i+1) − h(i−1), h(j+1) − h(j−1)) / 2Δ with heights 0 outside the grid, on an (N + 2)² grid
// whose texel (i + 1, j + 1) is cell (i, j) (the water shader's slope in one lookup; the coarse
// levels' are made the same way by ripple_levels.comp). 1/2Δ comes from the CPU, so each texel
// is the same float the CPU's difference gave. One invocation per slope texel.
#include "ripple_levels_bindings.glsl"
layout(local_size_x = RIPPLE_LEVEL_TILE, local_size_y = RIPPLE_LEVEL_TILE) in;

layout(binding = RIPPLE_SLOPES_HEIGHT_UNIT) uniform sampler2D u_rippleHeights;
layout(binding = RIPPLE_SLOPES_IMAGE, rg32f) writeonly uniform image2D u_rippleSlopesOut;
layout(location = RIPPLE_SLOPES_GRID_LOCATION) uniform vec2 u_grid;

// The height at cell c, 0 off the grid.
float height(ivec2 c) {
    int n = int(u_grid.x);
    if (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, ivec2(n)))) return 0.0;
    return texelFetch(u_rippleHeights, c, 0).r;
}

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    int n = int(u_grid.x);
    if (any(greaterThanEqual(t, ivec2(n + 2)))) return;
    ivec2 c = t - 1;
    vec2 slope = u_grid.y * vec2(height(c + ivec2(1, 0)) - height(c - ivec2(1, 0)), height(c + ivec2(0, 1)) - height(c - ivec2(0, 1)));
    imageStore(u_rippleSlopesOut, t, vec4(slope, 0.0, 0.0));
}
