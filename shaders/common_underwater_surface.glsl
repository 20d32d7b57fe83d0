// The water surface seen from below (docs/frame.md, "Under water"): Snell's window and total
// internal reflection. Needs common_sky.glsl, common_fresnel.glsl and common_underwater.glsl;
// only the water program includes it.
#ifndef COMMON_UNDERWATER_SURFACE_GLSL
#define COMMON_UNDERWATER_SURFACE_GLSL

// The surface seen from below along `view` (eye → surface, going up) with normal `n` (up):
// the refracted sky and sun inside Snell's window, weighted by the transmittance (1 − Fresnel;
// radiance grows by n² entering the denser medium), the water's own light mirrored by the
// Fresnel reflectance and, past the critical angle asin(1/n) = 48.8°, totally reflected.
vec3 surfaceFromBelow(vec3 view, vec3 n, vec3 sun, bool exact, vec3 sunLight, float shininess) {
    vec3 mirrored = reflect(view, -n);
    vec3 inside = underwaterInscatter(vec3(mirrored.x, min(mirrored.y, 0.0), mirrored.z));  // it reads the height only
    vec3 refracted = refract(view, -n, WATER_IOR);
    if (dot(refracted, refracted) == 0.0) return inside;  // total internal reflection
    refracted = normalize(refracted);
    float transmitted = 1.0 - fresnel(dot(refracted, n), exact);
    vec3 sky = skyRadiance(refracted, sun) + sunLight * pow(max(dot(refracted, sun), 0.0), shininess);
    return mix(inside, sky * WATER_IOR * WATER_IOR, transmitted);
}

#endif
