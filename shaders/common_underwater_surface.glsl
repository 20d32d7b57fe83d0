// The water surface seen from below (docs/frame.md, "Under water"): Snell's window and total
// internal reflection. Needs common_sky.glsl, common_fresnel.glsl and common_underwater.glsl;
// only the water program includes it.
#ifndef COMMON_UNDERWATER_SURFACE_GLSL
#define COMMON_UNDERWATER_SURFACE_GLSL

// The sun seen through the surface from below: the facets smaller than a pixel tilt about the
// rendered normal `n` with Gaussian slopes of variance `sigma2` (Cox & Munk, as the glitter above
// water, common_glitter.glsl); a facet whose normal is the refraction half vector
// h = −(sun + n_w·o) bends the sun's ray into the eye. The radiance per unit of the sun's
// irradiance is Walter, Marschner, Li & Torrance's (2007, eq. 21) rough-dielectric transmission
// times cos θi: |i·h||o·h| / |o·n| · n_w² (1 − F(i·h)) D(h) / (i·h + n_w o·h)², D the slope density
// over cos⁴ θh, no shadowing. `o` runs from the surface to the eye (down), `sun` toward the sun.
float sunThroughSurface(vec3 n, vec3 o, vec3 sun, float sigma2, bool exact) {
    float on = dot(o, n);
    if (on >= 0.0 || dot(sun, n) <= 0.0) return 0.0;
    vec3 h = -(sun + WATER_IOR * o);
    float len = length(h);
    if (len < 1e-6) return 0.0;
    h /= len;
    float ih = dot(sun, h), oh = dot(o, h);
    if (ih <= 0.0 || oh >= 0.0) return 0.0;
    float nh2 = max(dot(n, h), 1e-3);
    nh2 *= nh2;
    float density = exp(-(1.0 - nh2) / nh2 / sigma2) / (3.14159265 * sigma2 * nh2 * nh2);
    float denominator = ih + WATER_IOR * oh;
    return ih * -oh / -on * WATER_IOR * WATER_IOR * (1.0 - fresnel(ih, exact)) * density / (denominator * denominator);
}

// The surface seen from below along `view` (eye → surface, going up) with normal `n` (up):
// the refracted sky inside Snell's window, weighted by the transmittance (1 − Fresnel; radiance
// grows by n² entering the denser medium, which the exposure under water takes back:
// common_underwater.glsl), the sun through the surface's unresolved slopes (`sigma2`, their
// variance; `sunLight` its irradiance), the water's own light and its shafts' mean light along
// the mirrored ray from the surface point `at`, mirrored by the Fresnel reflectance and, past
// the critical angle asin(1/n) = 48.8°, totally reflected.
vec3 surfaceFromBelow(vec3 view, vec3 at, vec3 n, vec3 sun, bool exact, vec3 sunLight, float sigma2) {
    vec3 mirrored = reflect(view, -n);
    mirrored.y = min(mirrored.y, 0.0);  // a ray the waves send back up stays in the water
    vec3 inside = underwaterInscatter(mirrored) + underwaterShafts(at, normalize(mirrored - vec3(0.0, 1e-4, 0.0)), SHAFT_RANGE_M, false);
    vec3 glare = sunLight * sunThroughSurface(n, -view, sun, sigma2, exact);
    vec3 refracted = refract(view, -n, WATER_IOR);
    if (dot(refracted, refracted) == 0.0) return inside + glare;  // total internal reflection
    refracted = normalize(refracted);
    float transmitted = 1.0 - fresnel(dot(refracted, n), exact);
    return mix(inside, skyRadiance(refracted, sun) * WATER_IOR * WATER_IOR, transmitted) + glare;
}

#endif
