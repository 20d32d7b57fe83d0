// Analytic daylight sky: zenith-to-horizon gradient, Mie-like glow around the sun, sun disk.
// Radiance in arbitrary linear units (1 ≈ bright horizon).

vec3 skyRadiance(vec3 dir, vec3 sunDir) {
    float up = clamp(dir.y, -1.0, 1.0);
    vec3 zenith = vec3(0.09, 0.26, 0.62);
    vec3 horizon = vec3(0.62, 0.74, 0.88);
    // Rayleigh-like: the sky whitens toward the horizon (longer path through air).
    vec3 sky = mix(horizon, zenith, pow(max(up, 0.0), 0.45));
    // Below the horizon (seen only in reflections): a hazy continuation.
    sky = mix(sky, horizon * 0.75, smoothstep(0.0, -0.2, up));
    float mu = max(dot(dir, sunDir), 0.0);
    sky += vec3(1.0, 0.82, 0.55) * (0.18 * pow(mu, 6.0) + 0.6 * pow(mu, 80.0));
    return sky;
}

// The sun disk alone (0.53° wide), for direct views and sharp reflections.
vec3 sunDisk(vec3 dir, vec3 sunDir) {
    float cosAngle = dot(dir, sunDir);
    return vec3(60.0, 52.0, 40.0) * smoothstep(0.99996, 0.99998, cosAngle);
}
