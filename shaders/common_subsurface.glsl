// Light through thin crests (docs/frame.md, "Light through thin crests"): sunlight entering the back of
// a wave and leaving its thin front, seen as turquoise when the eye looks toward the sun through
// a crest. An approximation after Crest and Atlas ([Crest], [Atlas2019]), not a transport solution:
//   strength · max(0, h − h_mean) / amplitude       how thin the water is: crests, not troughs
//          · pow(saturate(dot(−view, sun)), power)  the sun behind the crest, against the eye
//          · (1 − (N·V)²)                           a grazing look through the wave, not down into it
//          · scattering colour · the sunlight       the body colour's hue, transmitted over CREST_PATH_M
//          · smoothstep(1, 3, crest in pixels)      nothing where a crest is under a pixel: far off,
//                                                   every pixel spans crests and troughs, and the
//                                                   term would draw a line along the horizon
// Needs common_frame.glsl (the body colour) and common_sky.glsl (the sunlight).
#ifndef COMMON_SUBSURFACE_GLSL
#define COMMON_SUBSURFACE_GLSL
#include "common_underwater.glsl"

const float CREST_POWER = 4.0;   // falloff away from the sun (Crest's default "sun fall-off")
const float CREST_GAIN = 0.6;    // at strength 1: a crest at full height, backlit, grazing: 0.6 × the sunlight
const float CREST_PATH_M = 1.0;  // path through the crest whose Jerlov I absorption colours the light (m)

// The radiance (linear) a crest at `height` m above the mean level adds, seen along `toEye`
// (surface → eye, unit) with normal `n` from `distance` m away, the sun toward `sun`; `amplitude`
// (m) the typical crest, `strength` the [render] subsurface factor, `pixelAngle` the angle a
// pixel spans (rad). A crest `amplitude` high spans amplitude / (distance · pixelAngle) pixels
// up the screen (its height is what a grazing look sees of it).
vec3 crestSubsurface(float height, float amplitude, float strength, vec3 toEye, vec3 n, vec3 sun, float distance,
                     float pixelAngle) {
    float resolved = smoothstep(1.0, 3.0, amplitude / max(distance * pixelAngle, 1e-6));
    if (resolved <= 0.0) return vec3(0.0);
    float thin = clamp(height / max(amplitude, 1e-3), 0.0, 1.0) * resolved;
    float backlit = pow(clamp(dot(-toEye, sun), 0.0, 1.0), CREST_POWER);
    float cosV = clamp(dot(toEye, n), 0.0, 1.0);
    // The hue of the water's scattering: the body colour scaled to a brightest channel of 1,
    // less what the path through the crest absorbs.
    vec3 body = frame.waterColorExposure.rgb;
    vec3 hue = body / max(max(body.r, body.g), max(body.b, 1e-4)) * underwaterTransmittance(CREST_PATH_M);
    return (strength * CREST_GAIN * thin * backlit * (1.0 - cosV * cosV)) * hue * sunTint(sun);
}

#endif
