#version 450 core
// Water surface shading (docs/references.md#water-rendering): composite normal in slope form (Gerstner + FFT cascades
// + ripples); reflection = sky cube with the mirrored local objects blended over it by their
// coverage; refraction = what lies below, faded to the water colour by its depth ([KTSDE2017]
// eq. 7); both looked up at the pixel offset by the normal ([Lee2007]) and a DU/DV map
// scrolled in time ([KTSDE2017] eq. 4–5); mixed by Fresnel (n = 1.33); plus sun glitter
// (Cox & Munk 1954: the slopes no layer draws, common_glitter.glsl) and foam (common_foam.glsl)
// where the FFT Jacobian folds or the ripples are steep, and where the persistent foam map
// holds coverage.
// Each FFT cascade's slopes fade out with distance ([render] far_fade) as its displacement does.
// Light through thin crests: common_subsurface.glsl. From below: common_underwater*.glsl.
// Not inside a floating hull where the hull lies behind (WATER_HULL_CLIP, WATER_HULL_DEPTH_SAMPLES):
// common_hull_clip.glsl.
// Compiled per gfx::WaterVariant: the cascade count and the switches (WATER_REFLECTIONS,
// WATER_REFRACTIONS, WATER_FOAM, WATER_FOAM_MAP, WATER_RIPPLES), the eye's side
// (WATER_UNDERWATER; WATER_WATERLINE: the surface crosses the near plane, each pixel takes its
// own), the hulls' clip (WATER_HULL_CLIP), the Fresnel law (WATER_EXACT_FRESNEL) and whether the
// sky has clouds (WATER_CLOUDS) are constants here. With
// WATER_FULL_QUALITY ([render] water_full_quality): every term per pixel, the reference the
// shipped shading is tested against (the ripple slope from four height lookups, the haze from
// the sky and the cascades' weights per pixel instead of per vertex).
#include "common_frame.glsl"
#include "common_sky.glsl"
#include "common_fresnel.glsl"
#include "common_glitter.glsl"
#include "common_water.glsl"
#include "common_detail.glsl"
#include "common_underwater.glsl"
#include "common_underwater_surface.glsl"
#include "common_subsurface.glsl"
#include "common_foam.glsl"
#include "common_hull_clip.glsl"

in vec3 v_world;
in vec2 v_rest;
in vec2 v_gerstnerSlope;
in vec3 v_haze;
in vec4 v_cascadeWeight;
layout(binding = SKY_UNIT) uniform samplerCube u_sky;
layout(binding = REFLECTION_UNIT) uniform sampler2D u_reflection;       // rgb linear radiance, a coverage
layout(binding = REFRACTION_UNIT) uniform sampler2D u_refraction;       // rgb linear radiance, a 1 / eye depth (1/m) of what lies below (0: nothing)
layout(binding = REFLECTION_DEPTH_UNIT) uniform sampler2D u_reflectionDepth;  // window depth of the mirrored objects
out vec4 o_color;

const float DETAIL_TILE = 24.0;            // m per repeat of the detail map
const vec2 DETAIL_DRIFT = vec2(0.031, 0.017);  // detail map scroll (repeats per s)
const vec3 SUN_COLOR = vec3(1.0, 0.9, 0.7);
const float MIN_GLITTER_SLOPE_VARIANCE = 0.001;
const float GLINT_VISIBLE = 0.002;  // glitter radiance of about one level of 255 over the water's own colour: fainter, no glints (their mean is the lobe's anyway)
// A tilted surface shifts an image by an angle, so the shift grows with the distance of the
// reflected or refracted object behind the surface: none where it touches it (a hull at the
// waterline), the full offset from this many metres behind. Without the ramp the offset tears
// the contact line into a zig-zag of object and sky (reflection) or body colour (refraction).
const float DISTORTION_RAMP_M = 2.0;

// Eye distance of a window depth (perspective projection, near/far in frame.depthParams).
float eyeDepth(float windowZ) {
    float n = frame.depthParams.x, f = frame.depthParams.y;
    float ndc = 2.0 * windowZ - 1.0;
    return 2.0 * n * f / (f + n - ndc * (f - n));
}

void main() {
    // Inside a hull there is no sea to draw, from above or below: what the hull holds shows.
    if (WATER_HULL_CLIP && hullClipped(v_world)) discard;
    float t = frame.cameraPositionTime.w;
    vec2 ripple = rippleSlope(v_world.xz);
    vec2 slope = v_gerstnerSlope + ripple;
    float jacobian = 1.0;
    float resolvedSlopes = 0.0;  // mean square slope the cascades draw here (faded ones less)
    float filteredOut = 0.0;     // of it, what the maps' mip filtering averaged away within the pixel
    for (int c = 0; c < WATER_CASCADES; ++c) {
        vec3 uv = cascadeCoord(v_rest, c);
        // (dh/dx, dh/dz, J), faded out with distance as the vertex shader fades the displacement
        vec4 s = texture(u_slopes, uv);
#ifdef WATER_FULL_QUALITY
        float weight = cascadeWeight(v_rest, c);
#else
        float weight = v_cascadeWeight[c];
#endif
        slope += weight * s.xy;
        resolvedSlopes += weight * weight * water.cascadeSlopeVariance[c];
        filteredOut += weight * weight * max(s.w - dot(s.xy, s.xy), 0.0);
        jacobian += weight * (s.z - 1.0);  // J − 1 adds over the cascades (first order)
    }
    vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
    vec3 eye = frame.cameraPositionTime.xyz;
    vec3 toEye = eye - v_world;
    float dist = length(toEye);
    vec3 v = toEye / dist;
    vec3 sun = frame.sunDirectionFresnel.xyz;
    const bool exact = WATER_EXACT_FRESNEL;
    vec3 body = waterBodyColor();
    vec3 r = reflect(-v, n);
    r.y = abs(r.y);
    // The slopes no layer draws: the sea's whole variance less the cascades' (at least that
    // of capillary ripples on a glassy sea, so the sun never shrinks to a point).
    // With them the slopes the pixel's footprint averages away (Bruneton, Neyret & Holzschuch
    // 2010 §4: the filtered |∇h|² less the filtered slope's square), so a pixel's mean
    // brightness does not depend on the resolution.
    float unresolved = max(water.glitterParams.x - resolvedSlopes, MIN_GLITTER_SLOPE_VARIANCE) + filteredOut;

    // The sky is the analytic one the cube is baked from: on llvmpipe a cube lookup costs more
    // than the formula. Seen from below (the eye under water, or this pixel under the
    // waterline): Snell's window and total internal reflection, faded over the path to the eye.
    if (WATER_UNDERWATER || (WATER_WATERLINE && pixelUnderwater(gl_FragCoord.xy))) {
        vec3 below = surfaceFromBelow(-v, v_world, n, sun, exact, SUN_COLOR * sunTint(sun) * frame.shading.z, unresolved);
        vec3 seen = underwaterExtinction(below, dist, -v) + underwaterShafts(eye, -v, dist, true);
        o_color = finalColorUnderwater(seen, gl_FragCoord.xy);
        return;
    }
    // Under clouds the baked cube holds their pattern (the formula only their mean); a clear sky
    // is the formula alone. The variant's constant, so the program holds one of the two (a
    // software rasteriser runs both sides of a branch, even on a uniform).
    vec3 sky;
    if (WATER_CLOUDS) sky = textureLod(u_sky, r, 0.0).rgb;
    else sky = clearSkyRadiance(normalize(r), sun);

    // --- lookups into the targets, offset by the normal and the scrolling DU/DV map
    vec2 screen = gl_FragCoord.xy / frame.viewport.xy;
    vec3 detail = decodeDetail(texture(u_detail, v_world.xz / DETAIL_TILE + DETAIL_DRIFT * t));
    vec2 offset = frame.shading.x * detail.xy + frame.shading.y * n.xz;
    float surfaceDepth = eyeDepth(gl_FragCoord.z);

    float cosV = max(dot(v, n), 0.0);
    vec3 reflection = sky;
    if (WATER_REFLECTIONS) {
        // The mirrored camera has the camera's projection: its depth less the surface's is
        // the path from the surface to the mirrored object.
        float behind = eyeDepth(texture(u_reflectionDepth, screen).r) - surfaceDepth;
        vec2 uv = clamp(screen + offset * smoothstep(0.0, DISTORTION_RAMP_M, behind), 0.0, 1.0);
        // Premultiplied by coverage (objects' partial samples resolved over transparent black,
        // splash sprites blended): the sky shows through by 1 − coverage.
        vec4 local = texture(u_reflection, uv);
        reflection = reflection * (1.0 - local.a) + local.rgb;
    }
    vec3 refraction = body;
    if (WATER_REFRACTIONS) {
        vec4 below = texture(u_refraction, screen);
        float behind = 1.0 / max(below.a, 1e-6) - surfaceDepth;
        vec2 uv = clamp(screen + offset * smoothstep(0.0, DISTORTION_RAMP_M, behind), 0.0, 1.0);
        vec4 shifted = texture(u_refraction, uv);
        float depth = 1.0 / max(shifted.a, 1e-6) - surfaceDepth;
        // What the offset lookup found, unless it is an object in front of the surface (the part
        // of a hull above the waterline, kept by the plane's overlap): then what lies straight behind.
        if (depth >= 0.0) below = shifted;
        else depth = behind;
        refraction = mix(body, below.rgb, exp(-max(depth, 0.0) / frame.depthParams.z));
    }

    float F = fresnel(cosV, exact);
    vec3 color = mix(refraction, reflection, F);
    // Near the eye the lobe breaks into single glints (a pixel's footprint: its angle over the
    // distance, stretched by the grazing view).
    float pixelAngle = 2.0 / (water.crest.z * frame.viewport.y);
    float footprint = dist * pixelAngle / sqrt(max(abs(v.y), 0.05));
    // (only where the lobe shows at all: the glints cost, and far from the sun's path there are none)
    float glitter = frame.shading.z * glitterRadiance(n, v, sun, unresolved, exact);
    if (glitter > GLINT_VISIBLE) glitter *= glintFactor(v_world.xz, dist, t, footprint);
    color += SUN_COLOR * sunTint(sun) * glitter;
    // the mean level is y = 0; a pixel spans 2 / (projection[1][1] · viewport height) radians
    color += crestSubsurface(v_world.y, water.crest.x, water.crest.y, v, n, sun, dist, 2.0 / (water.crest.z * frame.viewport.y));

    if (WATER_FOAM) color = shadeFoam(color, v_world.xz, n, sun, jacobian, length(ripple), detail);
#ifdef WATER_FULL_QUALITY
    vec3 haze = textureLod(u_sky, normalize(vec3(-v.x, 0.0, -v.z)), 0.0).rgb;
#else
    vec3 haze = v_haze;
#endif
    color = mix(color, haze, 1.0 - exp(-dist * 0.00025));
    o_color = finalColor(color, gl_FragCoord.xy);
}
