// Per-view helpers over the FrameUniforms block (common_bindings.glsl).
#include "common_bindings.glsl"
#include "common_dither.glsl"

// World-space view ray through a pixel (ndc in [-1, 1]²).
vec3 viewRay(vec2 ndc) {
    vec4 farPoint = frame.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    return normalize(farPoint.xyz / farPoint.w - frame.cameraPositionTime.xyz);
}

// Water body colour lit by the sun's height (linear radiance); dark at night (the sun below
// sin e = −0.18, as common_sky.glsl's daylight()).
vec3 waterBodyColor() {
    float night = mix(0.06, 1.0, smoothstep(-0.18, 0.10, frame.sunDirectionFresnel.y));
    // under an overcast only the diffuse light reaches into the water (about half of it by day)
    float overcast = mix(1.0, 0.55, frame.sky.x);
    return frame.waterColorExposure.rgb * (0.35 + 0.65 * max(frame.sunDirectionFresnel.y, 0.0)) * night * overcast;
}

// Exposure, filmic tone curve (Narkowicz's ACES fit) and sRGB encoding; render targets keep
// linear radiance (the water pass tone-maps what it reads from them). For the FXAA pass the
// frame's alpha carries the encoded colour's luma (Rec. 601 weights), read there in fours. In
// the refraction target the objects' shader puts 1 / their eye depth in alpha (object_mesh.frag).
// The encoded colour goes into an 8-bit target (the framebuffer or the internal frame), so it
// is dithered here, once (common_dither.glsl); `pixel` is gl_FragCoord.xy. The post pass's
// copies and blends of it keep that noise and are not dithered again (docs/frame.md).
// True where the target keeps linear radiance (the reflection and refraction targets).
bool linearTarget() { return frame.viewport.z > 0.5 && (frame.viewport.z < 1.5 || frame.viewport.z > 2.5); }

// The filmic curve alone: exposed linear radiance to display-linear 0..1.
vec3 toneCurve(vec3 x) { return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }

// A tone-mapped colour (display-linear 0..1) encoded and dithered for the 8-bit target.
vec4 encodeDisplay(vec3 toned, vec2 pixel) {
    vec3 display = dither8(pow(toned, vec3(1.0 / 2.2)), pixel, frame.switches.w);
    return vec4(display, frame.viewport.z > 1.5 ? dot(display, vec3(0.299, 0.587, 0.114)) : 1.0);
}

vec4 finalColor(vec3 radiance, vec2 pixel) {
    if (linearTarget()) return vec4(radiance, 1.0);
    return encodeDisplay(toneCurve(radiance * frame.waterColorExposure.w), pixel);
}
