#version 450 core
// Test probe: the water shader's Fresnel terms at N angles of incidence in [0°, 90°].
#include "common_fresnel.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Result { vec2 g_result[]; };  // (Schlick, exact)
layout(location = 0) uniform int u_count;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= u_count) return;
    float theta = radians(90.0) * float(i) / float(u_count - 1);
    float c = cos(theta);
    g_result[i] = vec2(fresnel(c, false), fresnel(c, true));
}
