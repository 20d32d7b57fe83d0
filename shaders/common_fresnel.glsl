// Fresnel reflectance of water (n = 1.33) for unpolarised light: Schlick or exact.
#ifndef COMMON_FRESNEL_GLSL
#define COMMON_FRESNEL_GLSL
const float WATER_IOR = 1.33;

float fresnelSchlick(float cosTheta) {
    float r0 = (WATER_IOR - 1.0) / (WATER_IOR + 1.0);
    r0 *= r0;
    return r0 + (1.0 - r0) * pow(1.0 - clamp(cosTheta, 0.0, 1.0), 5.0);
}

// Exact: mean of the s- and p-polarised reflectances, from air into water.
float fresnelExact(float cosTheta) {
    float ci = clamp(cosTheta, 0.0, 1.0);
    float si2 = 1.0 - ci * ci;
    float ct = sqrt(max(1.0 - si2 / (WATER_IOR * WATER_IOR), 0.0));
    float rs = (ci - WATER_IOR * ct) / (ci + WATER_IOR * ct);
    float rp = (WATER_IOR * ci - ct) / (WATER_IOR * ci + ct);
    return 0.5 * (rs * rs + rp * rp);
}

float fresnel(float cosTheta, bool exact) {
    return exact ? fresnelExact(cosTheta) : fresnelSchlick(cosTheta);
}

#endif
