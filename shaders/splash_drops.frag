#version 450 core
// A splash sprite shaded as a small sphere of spray: light scattered in it (sun, wrapped, and
// the sky's ambient), the sky mirrored at its rim by Fresnel (n = 1.33), a sun glint; round
// with a soft edge; premultiplied alpha. The water's aerial perspective as for objects.
#include "common_frame.glsl"
#include "common_sky.glsl"
#include "common_fresnel.glsl"

in vec3 v_centre;
in float v_opacity;
layout(location = SPLASH_RIGHT_LOCATION) uniform vec3 u_right;  // the camera's right and up (world, unit): the sprite's plane
layout(location = SPLASH_UP_LOCATION) uniform vec3 u_up;
out vec4 o_color;

const float OPACITY = 0.85;  // of one sprite's centre

void main() {
    vec2 corner = vec2(2.0 * gl_PointCoord.x - 1.0, 1.0 - 2.0 * gl_PointCoord.y);  // [-1, 1]², y up
    float d2 = dot(corner, corner);
    if (d2 >= 1.0) discard;
    vec3 toEye = frame.cameraPositionTime.xyz - v_centre;
    float dist = length(toEye);
    vec3 v = toEye / dist;
    vec3 n = normalize(u_right * corner.x + u_up * corner.y + v * sqrt(1.0 - d2));
    vec3 sun = frame.sunDirectionFresnel.xyz;
    vec3 ambient = 0.6 * skyRadiance(vec3(0.0, 1.0, 0.0), sun) + 0.2 * skyRadiance(vec3(n.x, abs(n.y), n.z), sun);
    vec3 scattered = 0.9 * (ambient + frame.sunLight.rgb * sunTint(sun) * 1.3 * (0.55 + 0.45 * dot(n, sun)));
    vec3 r = reflect(-v, n);
    r.y = abs(r.y);
    float F = fresnel(max(dot(n, v), 0.0), frame.sunDirectionFresnel.w > 0.5);
    vec3 color = mix(scattered, skyRadiance(r, sun) * 1.5, F) + frame.sunLight.rgb * sunTint(sun) * 2.0 * pow(max(dot(r, sun), 0.0), 60.0);
    vec3 haze = skyRadiance(normalize(vec3(-v.x, 0.0, -v.z)), sun);
    color = mix(color, haze, 1.0 - exp(-dist * 0.00025));
    float alpha = OPACITY * v_opacity * smoothstep(1.0, 0.35, d2);
    o_color = vec4(finalColor(color, gl_FragCoord.xy).rgb * alpha, alpha);
}
