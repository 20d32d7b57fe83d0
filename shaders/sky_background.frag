#version 450 core
// Sky pass: the analytic sky and the sun disk behind everything.
#include "common_frame.glsl"
#include "common_sky.glsl"

in vec2 v_ndc;
out vec4 o_color;

void main() {
    vec3 dir = viewRay(v_ndc);
    vec3 sun = u_sunDirectionFresnel.xyz;
    o_color = vec4(toneMap(skyRadiance(dir, sun) + sunDisk(dir, sun)), 1.0);
}
