// Analytic sky by the sun's height: zenith-to-horizon gradient, Mie-like glow around the sun,
// sun disk; twilight (sun below ~15°) reddens the sun and burns the horizon toward it orange,
// night (sun below about −10°) leaves a dark blue dome. Radiance in arbitrary linear units
// (1 ≈ bright horizon). With the sun above sin e = 0.25 the sky is the day sky unchanged.
// Clouds ([sky] cloud_cover c, frame.sky): a layer at cloud_height drifting with the wind aloft;
// the baked cube draws their pattern (skyWithClouds), every other reader the sky as the clouds
// cover it on average (skyRadiance); the sun's direct light (sunTint) dims while a cloud
// stands before the sun, to nothing under an overcast, and they grey the diffuse light
// (docs/look.md#weather).
#ifndef COMMON_SKY_GLSL
#define COMMON_SKY_GLSL
#include "common_bindings.glsl"
#include "common_clouds.glsl"

// Share of the sky the clouds cover, [0, 1].
float cloudCover() { return frame.sky.x; }

// The share of the sun's direct light the clouds let through now: none behind a cloud or under
// an overcast, nearly all of it in a gap (the layer's loss on the sun's ray, found once a frame
// from the noise the sky draws: gfx::cloudBeamLoss, common_clouds.glsl).
float sunThroughClouds() { return 1.0 - frame.sunCloud.x; }

// Colour and strength of the sunlight reaching the sea, relative to a high sun: the longer
// path through air near the horizon scatters blue away (reddening), none below it.
vec3 sunTint(vec3 sunDir) {
    float low = 1.0 - smoothstep(0.0, 0.25, sunDir.y);
    return mix(vec3(1.0), vec3(1.0, 0.45, 0.15), low) * smoothstep(-0.05, 0.02, sunDir.y) * sunThroughClouds();
}

// Diffuse light by the sun's height, relative to the day: 1 from sin e = 0.1 up, a little
// moon- and starlight at night.
float daylight(vec3 sunDir) { return mix(0.06, 1.0, smoothstep(-0.18, 0.10, sunDir.y)); }

// The cloudless sky.
vec3 clearSkyRadiance(vec3 dir, vec3 sunDir) {
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

// A cloud's radiance seen along dir: a sunlit white cumulus under a few clouds, an overcast's
// grey underside under many, brighter toward the zenith (the CIE overcast sky: L ∝ (1 + 2 sin h)/3),
// a soft bright patch round the hidden sun; reddened with the sun at twilight, dark at night.
vec3 cloudRadiance(vec3 dir, vec3 sunDir) {
    float c = cloudCover();
    float up = clamp(dir.y, -1.0, 1.0);
    vec3 lit = vec3(1.0, 0.99, 0.97);
    vec3 overcast = vec3(0.27, 0.28, 0.31) * (1.0 + 2.0 * max(up, 0.0)) / 3.0;  // a storm's dark overcast
    vec3 cloud = mix(lit, overcast, smoothstep(0.2, 1.0, c));
    float low = 1.0 - smoothstep(0.0, 0.25, sunDir.y);
    cloud *= mix(vec3(1.0), vec3(1.0, 0.6, 0.4), 0.6 * low) * daylight(sunDir);
    float mu = max(dot(dir, sunDir), 0.0);
    cloud += vec3(0.35, 0.33, 0.30) * c * pow(mu, 12.0) * smoothstep(-0.05, 0.05, sunDir.y);
    // below the horizon (reflections only): as the clear sky's hazy continuation
    return mix(cloud, cloud * 0.75, smoothstep(0.0, -0.2, up));
}

// The sky as the clouds cover it on average (no pattern): what lights and hazes the scene.
vec3 skyRadiance(vec3 dir, vec3 sunDir) {
    vec3 clear = clearSkyRadiance(dir, sunDir);
    float c = cloudCover();
    if (c <= 0.0) return clear;
    return mix(clear, cloudRadiance(dir, sunDir), c);
}

// The sky with the clouds' pattern (the cube bake): the clear sky behind them where they are thin.
vec3 skyWithClouds(vec3 dir, vec3 sunDir) {
    vec3 clear = clearSkyRadiance(dir, sunDir);
    if (cloudCover() <= 0.0) return clear;
    return mix(clear, cloudRadiance(dir, sunDir), cloudLayerOpacity(dir, cloudCover(), frame.sky.yz, frame.sky.w));
}

// The sun disk alone (0.53° wide), for direct views and sharp reflections.
vec3 sunDisk(vec3 dir, vec3 sunDir) {
    float cosAngle = dot(dir, sunDir);
    vec3 disk = vec3(60.0, 52.0, 40.0) * sunTint(sunDir) * smoothstep(0.99996, 0.99998, cosAngle);
    // (dimmed through sunTint by the cloud on the sun's ray, as the sky cube draws it there;
    // gone under an overcast)
    return disk;
}

#endif
