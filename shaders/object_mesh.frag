#version 450 core
// Objects lit by the sun (Lambert + a little specular) and the sky (hemispheric ambient),
// with the water's aerial perspective above and, in pixels under the water, its extinction
// (common_underwater.glsl); under water the sunlight reaching the object is dimmed per channel
// by the water above it and focused into caustics, and the light shafts lie along the view.
#include "common_frame.glsl"
#include "common_sky.glsl"
#include "common_underwater.glsl"

in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
layout(location = OBJECT_TINT_LOCATION) uniform vec3 u_tint;
out vec4 o_color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 sun = frame.sunDirectionFresnel.xyz;
    vec3 toEye = frame.cameraPositionTime.xyz - v_world;
    float dist = length(toEye);
    vec3 v = toEye / dist;
    vec3 ambient = mix(vec3(0.10, 0.14, 0.18) * daylight(sun), skyRadiance(vec3(0.0, 1.0, 0.0), sun) * 0.45, 0.5 + 0.5 * n.y);
    bool under = pixelUnderwater(gl_FragCoord.xy);
    // Under water the sunlight comes focused by the waves (caustics); 1 above.
    float focus = under ? underwaterCaustics(v_world) : 1.0;
    vec3 light = ambient + frame.sunLight.rgb * sunTint(sun) * frame.sunLight.w * max(dot(n, sun), 0.0) * focus;
    vec3 color = u_tint * v_color * light + sunTint(sun) * 0.25 * pow(max(dot(reflect(-sun, n), v), 0.0), 40.0);
    if (under) {
        // The light reaching the object's depth under the mean level (y = 0), then the path to the
        // eye and the shafts along it.
        color *= underwaterTransmittance(-v_world.y);
        color = underwaterExtinction(color, dist, -v) + underwaterShafts(frame.cameraPositionTime.xyz, -v, dist, true);
        o_color = finalColorUnderwater(color, gl_FragCoord.xy);
    } else {
        vec3 haze = skyRadiance(normalize(vec3(-v.x, 0.0, -v.z)), sun);
        color = mix(color, haze, 1.0 - exp(-dist * 0.00025));
        o_color = finalColor(color, gl_FragCoord.xy);
    }
    // In the refraction target alpha is 1 / the eye depth (1/m; cleared to 0: nothing). Filtered,
    // it blends as window depth does (an affine function of it), and the water pass reads what
    // lies below and how deep it lies in one lookup.
    if (frame.viewport.z > 2.5) o_color.a = gl_FragCoord.w;
}
