#version 450 core
// Test probe: the water shader's ripple composite (rippleHeight: level 0 and the coarse levels'
// array layers cross-faded) at N world points.
#include "common_water.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Points { vec2 g_point[]; };  // world (x, z), m
layout(std430, binding = 1) writeonly buffer Result { float g_height[]; };  // m
layout(location = 0) uniform int u_count;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    g_height[i] = rippleHeight(g_point[i]);
}
