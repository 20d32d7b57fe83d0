#version 450 core
// Sky pass: the baked sky and the sun disk behind everything; under water, the water's fog.
#include "common_frame.glsl"
#include "common_sky.glsl"

in vec2 v_ndc;
layout(binding = SKY_UNIT) uniform samplerCube u_sky;
out vec4 o_color;

void main() {
    vec3 dir = viewRay(v_ndc);
    vec3 sun = frame.sunDirectionFresnel.xyz;
    if (eyeUnderwater()) {
        // Brighter toward the surface, darker toward the deep.
        o_color = finalColor(waterBodyColor() * (0.6 + 0.5 * dir.y), gl_FragCoord.xy);
        return;
    }
    o_color = finalColor(textureLod(u_sky, dir, 0.0).rgb + sunDisk(dir, sun), gl_FragCoord.xy);
}
