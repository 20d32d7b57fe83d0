// Sun glitter after Cox & Munk (1954): the facets smaller than a pixel tilt about the
// rendered normal with Gaussian slopes of the variance the rendered layers leave out (the
// whole sea's 0.003 + 5.12e-3·U10 less what the cascades resolve); a facet whose normal is
// the half vector h of the eye and the sun mirrors the sun to the eye. The radiance is
// E·F(v·h)·p(ζ)/(4·cos θv·cos⁴ θh), p(ζ) = exp(−|ζ|²/σ²)/(π·σ²) the isotropic slope density
// and |ζ| = tan θh (Cox & Munk 1954 eq. 5; Bruneton, Neyret & Holzschuch 2010 eq. 7).
// Include after common_fresnel.glsl.

float glitterRadiance(vec3 n, vec3 v, vec3 sun, float sigma2, bool exact) {
    float nv = dot(n, v);
    if (nv <= 0.0 || dot(n, sun) <= 0.0) return 0.0;
    vec3 h = normalize(v + sun);
    float nh2 = max(dot(n, h), 1e-3);
    nh2 *= nh2;
    float tan2 = (1.0 - nh2) / nh2;
    float p = exp(-tan2 / sigma2) / (3.14159265 * sigma2);
    return fresnel(dot(v, h), exact) * p / (4.0 * nv * nh2 * nh2);
}

// Discrete glints near the eye (after Zirr & Kaplanyan 2016's idea of a pixel that sees a
// countable number of facets): where a pixel's footprint is smaller than the facets, the
// glitter is not the lobe's smooth mean but the few facets that happen to mirror the sun. The
// surface (moving with the water) is cut into square cells at the power of two times
// GLINT_CELL_M just above the pixel's footprint, up to GLINT_LEVELS − 1 doublings (ripples of a
// few decimetres, the largest the cascades leave out); each cell holds, at a time, a mirroring
// facet with probability GLINT_SHARE, drawn afresh GLINT_RATE_HZ times a second at the cell's
// own moments (the ripples re-tilt it); a facet is a paraboloid spot of radius GLINT_RADIUS
// cells, so its area is π·R²/2 of the cell. The factor on the lobe is the facet's shape over
// its mean coverage: its mean over the surface is exactly 1, so a pixel's expected brightness
// is the lobe's whatever the resolution; where the footprint covers several of the largest
// cells it fades to that mean (the band the lobe gives far away, no shimmer).
const float GLINT_CELL_M = 0.02;
const int GLINT_LEVELS = 4;
const float GLINT_SHARE = 0.25;
const float GLINT_RATE_HZ = 4.0;
const float GLINT_RADIUS = 0.45;
const float GLINT_MEAN_COVER = GLINT_SHARE * 3.14159265 * GLINT_RADIUS * GLINT_RADIUS / 2.0;

float glintHash(vec2 p) {
    vec3 q = fract(vec3(p.xyx) * vec3(0.1031, 0.1030, 0.0973));
    q += dot(q, q.yzx + 33.33);
    return fract((q.x + q.y) * q.z);
}

// The glints' factor on the glitter lobe at surface point `world` (m), time t (s), for a pixel
// whose footprint there is `footprint` m across.
float glintFactor(vec2 world, float t, float footprint) {
    float level = clamp(ceil(log2(footprint / (0.75 * GLINT_CELL_M))), 0.0, float(GLINT_LEVELS - 1));
    float size = GLINT_CELL_M * exp2(level);
    float resolved = 1.0 - smoothstep(0.5, 1.5, footprint / size);
    if (resolved <= 0.0) return 1.0;
    vec2 cellPos = world / size;
    vec2 cell = floor(cellPos) + 1013.0 * level;
    float moment = floor(t * GLINT_RATE_HZ + glintHash(cell) * 8.0);
    float on = step(glintHash(cell + vec2(17.13, 31.71) * moment), GLINT_SHARE);
    vec2 at = (fract(cellPos) - 0.5) / GLINT_RADIUS;
    float spot = max(1.0 - dot(at, at), 0.0);
    return mix(1.0, on * spot / GLINT_MEAN_COVER, resolved);
}
