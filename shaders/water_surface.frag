#version 450 core
// Water surface shading: composite normal in slope form (Gerstner + FFT cascades), Fresnel
// between the sky's reflection and the water body, sun glitter (seed 000), whitecap foam
// where the FFT Jacobian folds (seed 003), aerial perspective.
#include "common_frame.glsl"
#include "common_sky.glsl"
#include "common_fresnel.glsl"
#include "common_water.glsl"

in vec3 v_world;
in vec2 v_rest;
in vec2 v_gerstnerSlope;
out vec4 o_color;

void main() {
    float t = u_cameraPositionTime.w;
    vec2 slope = v_gerstnerSlope + rippleSlope(v_world.xz);
    float jacobian = 1.0;
    int cascades = int(u_gridParams.z);
    for (int c = 0; c < cascades; ++c) {
        vec3 uv = cascadeCoord(v_rest, c);
        slope += texture(u_slopes, uv).xy;
        jacobian = min(jacobian, texture(u_displacement, uv).w);
    }
    vec3 eye = u_cameraPositionTime.xyz;
    bool fromBelow = eye.y < v_world.y - 0.0 && eye.y < 0.0;
    vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
    if (fromBelow) n = -n;

    vec3 toEye = eye - v_world;
    float dist = length(toEye);
    vec3 v = toEye / dist;
    vec3 sun = u_sunDirectionFresnel.xyz;
    float cosV = max(dot(v, n), 0.0);
    vec3 r = reflect(-v, n);
    r.y = abs(r.y);
    float F = fresnel(cosV, u_sunDirectionFresnel.w > 0.5);
    vec3 body = u_waterColorExposure.rgb * (0.35 + 0.65 * max(sun.y, 0.0));
    vec3 color = mix(body, skyRadiance(r, sun), F);
    color += vec3(1.0, 0.9, 0.7) * 6.0 * pow(max(dot(r, sun), 0.0), 600.0) * F;
    float foam = smoothstep(0.6, 0.1, jacobian);
    color = mix(color, vec3(0.9, 0.95, 1.0) * (0.4 + 0.6 * max(sun.y, 0.0)), foam * 0.8);
    if (fromBelow) {
        // Seen from below: the bright window overhead fades into the water's own colour.
        color = mix(body * 0.6, color, exp(-dist * 0.02));
    } else {
        vec3 haze = skyRadiance(normalize(vec3(-v.x, 0.0, -v.z)), sun);
        color = mix(color, haze, 1.0 - exp(-dist * 0.00025));
    }
    o_color = vec4(toneMap(color), 1.0);
}
