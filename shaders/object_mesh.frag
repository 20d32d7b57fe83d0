#version 450 core
// Opaque objects lit by the sun (Lambert + a little specular) and the sky (hemispheric
// ambient), with the same aerial perspective as the water.
#include "common_frame.glsl"
#include "common_sky.glsl"

in vec3 v_world;
in vec3 v_normal;
layout(location = 1) uniform vec3 u_color;
out vec4 o_color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 sun = u_sunDirectionFresnel.xyz;
    vec3 toEye = u_cameraPositionTime.xyz - v_world;
    float dist = length(toEye);
    vec3 v = toEye / dist;
    vec3 ambient = mix(vec3(0.10, 0.14, 0.18), skyRadiance(vec3(0.0, 1.0, 0.0), sun) * 0.45, 0.5 + 0.5 * n.y);
    vec3 light = ambient + vec3(1.0, 0.92, 0.8) * 1.4 * max(dot(n, sun), 0.0);
    vec3 color = u_color * light + 0.25 * pow(max(dot(reflect(-sun, n), v), 0.0), 40.0);
    // Below the mean water level the object is in water: tint it toward the water body.
    color = mix(color, u_waterColorExposure.rgb, clamp(-v_world.y * 0.35, 0.0, 0.85));
    vec3 haze = skyRadiance(normalize(vec3(-v.x, 0.0, -v.z)), sun);
    color = mix(color, haze, 1.0 - exp(-dist * 0.00025));
    o_color = vec4(toneMap(color), 1.0);
}
