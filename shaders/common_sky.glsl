// Analytic sky by the sun's height: zenith-to-horizon gradient, Mie-like glow around the sun,
// sun disk; twilight (sun below ~15°) reddens the sun and burns the horizon toward it orange,
// night (sun below about −10°) leaves a dark blue dome. Radiance in arbitrary linear units
// (1 ≈ bright horizon). With the sun above sin e = 0.25 the sky is the day sky unchanged.
#ifndef COMMON_SKY_GLSL
#define COMMON_SKY_GLSL

// Colour and strength of the sunlight reaching the sea, relative to a high sun: the longer
// path through air near the horizon scatters blue away (reddening), none below it.
vec3 sunTint(vec3 sunDir) {
    float low = 1.0 - smoothstep(0.0, 0.25, sunDir.y);
    return mix(vec3(1.0), vec3(1.0, 0.45, 0.15), low) * smoothstep(-0.05, 0.02, sunDir.y);
}

// Diffuse light by the sun's height, relative to the day: 1 from sin e = 0.1 up, a little
// moon- and starlight at night.
float daylight(vec3 sunDir) { return mix(0.06, 1.0, smoothstep(-0.18, 0.10, sunDir.y)); }

vec3 skyRadiance(vec3 dir, vec3 sunDir) {
    float up = clamp(dir.y, -1.0, 1.0);
    float day = smoothstep(-0.18, 0.10, sunDir.y);
    // Twilight weight: 0 with a high sun, strongest with the sun at the horizon, gone at night.
    float twilight = (1.0 - smoothstep(0.0, 0.25, sunDir.y)) * smoothstep(-0.18, 0.0, sunDir.y);
    vec3 zenith = mix(vec3(0.004, 0.007, 0.018), vec3(0.09, 0.26, 0.62), day);
    vec3 horizon = mix(vec3(0.010, 0.014, 0.028), vec3(0.62, 0.74, 0.88), day);
    // Toward the sun's azimuth the horizon burns orange; away from it, it stays bluish.
    float across = length(dir.xz) * length(sunDir.xz);
    float toward = across > 1e-6 ? 0.5 + 0.5 * dot(dir.xz, sunDir.xz) / across : 0.5;
    horizon = mix(horizon, vec3(1.0, 0.42, 0.12) * (0.4 + 0.6 * toward), twilight * (0.3 + 0.7 * toward));
    zenith = mix(zenith, zenith * vec3(0.55, 0.6, 0.9), twilight);
    // Rayleigh-like: the sky whitens toward the horizon (longer path through air).
    vec3 sky = mix(horizon, zenith, pow(max(up, 0.0), 0.45));
    // Below the horizon (seen only in reflections): a hazy continuation.
    sky = mix(sky, horizon * 0.75, smoothstep(0.0, -0.2, up));
    float mu = max(dot(dir, sunDir), 0.0);
    vec3 glow = mix(vec3(1.0, 0.82, 0.55), vec3(1.0, 0.38, 0.08), 1.0 - smoothstep(0.0, 0.25, sunDir.y));
    sky += glow * smoothstep(-0.12, 0.02, sunDir.y) * (0.18 * pow(mu, 6.0) + 0.6 * pow(mu, 80.0));
    return sky;
}

// The sun disk alone (0.53° wide), for direct views and sharp reflections.
vec3 sunDisk(vec3 dir, vec3 sunDir) {
    float cosAngle = dot(dir, sunDir);
    return vec3(60.0, 52.0, 40.0) * sunTint(sunDir) * smoothstep(0.99996, 0.99998, cosAngle);
}

#endif
