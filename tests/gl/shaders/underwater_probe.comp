#version 450 core
// Test probe: the under-water extinction at N distances: the transmittance, and a white object's colour seen along +y.
#include "common_frame.glsl"
#include "common_underwater.glsl"

layout(local_size_x = 16) in;
layout(std430, binding = 0) readonly buffer Distances { float g_distance[]; };  // m
layout(std430, binding = 1) writeonly buffer Result { vec4 g_result[]; };     // per distance: (T, 0), (colour, 1)
layout(location = 0) uniform int u_count;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    float d = g_distance[i];
    g_result[2 * i] = vec4(underwaterTransmittance(d), 0.0);
    g_result[2 * i + 1] = vec4(underwaterExtinction(vec3(1.0), d, vec3(0.0, 1.0, 0.0)), 1.0);
}
