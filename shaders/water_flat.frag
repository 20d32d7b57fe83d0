#version 450 core
// Water pass (flat sea): each pixel's view ray meets the plane y = 0; a few analytic
// ripples perturb the normal; the sky reflects by Fresnel over the deep water colour,
// with sun glitter.
#include "common_frame.glsl"
#include "common_sky.glsl"
#include "common_fresnel.glsl"

in vec2 v_ndc;
out vec4 o_color;

// Slope (dh/dx, dh/dz) of a small sum of travelling sine waves (deep-water dispersion).
vec2 rippleSlope(vec2 p, float t) {
    const vec3 WAVES[4] = vec3[4](vec3(0.8, 0.6, 0.012), vec3(-0.5, 0.87, 0.008),
                                  vec3(0.2, -0.98, 0.006), vec3(0.95, 0.3, 0.004));
    const float K[4] = float[4](0.35, 0.6, 1.1, 2.3);
    vec2 slope = vec2(0.0);
    for (int i = 0; i < 4; ++i) {
        vec2 k = WAVES[i].xy * K[i];
        float omega = sqrt(9.81 * K[i]);
        float a = WAVES[i].z / K[i] * 10.0;
        slope += k * a * cos(dot(k, p) - omega * t);
    }
    return slope;
}

void main() {
    vec3 eye = u_cameraPositionTime.xyz;
    vec3 dir = viewRay(v_ndc);
    // Below the horizon from above, or above it from below the surface.
    float dist = -eye.y / dir.y;
    if (dir.y == 0.0 || dist <= 0.0) discard;
    vec3 hit = eye + dist * dir;

    vec4 clip = u_viewProjection * vec4(hit, 1.0);
    gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);

    // Distant ripples average out: fade the slope with distance (no aliasing at the horizon).
    vec2 slope = rippleSlope(hit.xz, u_cameraPositionTime.w) * exp(-dist * 0.004);
    vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
    if (eye.y < 0.0) n = -n;

    vec3 v = -dir;
    vec3 sun = u_sunDirectionFresnel.xyz;
    vec3 r = reflect(dir, n);
    r.y = abs(r.y);
    float F = fresnel(dot(v, n), u_sunDirectionFresnel.w > 0.5);
    vec3 body = u_waterColorExposure.rgb * (0.35 + 0.65 * max(sun.y, 0.0));
    vec3 color = mix(body, skyRadiance(r, sun), F);
    // Sun glitter (seed 000): a sharp specular lobe around the mirrored sun.
    color += vec3(1.0, 0.9, 0.7) * 6.0 * pow(max(dot(r, sun), 0.0), 600.0) * F;
    // Aerial perspective: the far sea fades into the horizon haze.
    color = mix(color, skyRadiance(normalize(vec3(dir.x, 0.0, dir.z)), sun), 1.0 - exp(-dist * 0.00025));
    o_color = vec4(toneMap(color), 1.0);
}
