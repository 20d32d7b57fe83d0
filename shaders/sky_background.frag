#version 450 core
// Sky pass: the baked sky and the sun disk behind everything; in pixels under the water, the
// water's own in-scattered light (what every extinction under water fades toward) and the light
// shafts.
#include "common_frame.glsl"
#include "common_sky.glsl"
#include "common_underwater.glsl"

in vec2 v_ndc;
layout(binding = SKY_UNIT) uniform samplerCube u_sky;
out vec4 o_color;

void main() {
    vec3 dir = viewRay(v_ndc);
    vec3 sun = frame.sunDirectionFresnel.xyz;
    if (pixelUnderwater(gl_FragCoord.xy)) {
        o_color = finalColorUnderwater(underwaterInscatter(dir) + underwaterShafts(frame.cameraPositionTime.xyz, dir, SHAFT_RANGE_M, true), gl_FragCoord.xy);
        return;
    }
    o_color = finalColor(textureLod(u_sky, dir, 0.0).rgb + sunDisk(dir, sun), gl_FragCoord.xy);
}
