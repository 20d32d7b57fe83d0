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
// surface (moving with the water) is cut into square cells GLINT_CELL_M wide within
// GLINT_NEAR_M of the eye, twice as wide at each doubling of the distance (GLINT_LEVELS sizes):
// the same cells at any resolution, so a picture's glints are the same facets whatever its
// size. Between two sizes each cell of the coarser chooses, with the probability the distance
// gives, to be one cell or its four finer ones, so the sizes mix without a seam. Each cell
// holds, at a time, a mirroring facet with probability GLINT_SHARE, drawn afresh GLINT_RATE_HZ
// times a second at the cell's own moments (the ripples re-tilt it); a facet is a paraboloid
// spot of radius GLINT_RADIUS cells, so its area is π·R²/2 of the cell. The factor on the lobe
// is the facet's shape over its mean coverage: its mean over the surface is exactly 1, so a
// pixel's expected brightness is the lobe's; where the pixel's footprint covers a cell it fades
// to that mean (the band the lobe gives far away or in a small picture, no shimmer).
const float GLINT_CELL_M = 0.01;
const float GLINT_NEAR_M = 4.0;
const int GLINT_LEVELS = 5;
const float GLINT_SHARE = 0.5;
const float GLINT_RATE_HZ = 4.0;
const float GLINT_RADIUS = 0.45;
const float GLINT_MEAN_COVER = GLINT_SHARE * 3.14159265 * GLINT_RADIUS * GLINT_RADIUS / 2.0;
const float GLINT_DRAW_RANGE = 65536.0;  // a draw is 16 bits of the hash

// Three uniform 32-bit draws per integer cell and moment (Jarzynski & Olano 2020's pcg3d,
// unbiased: a float hash's share of draws under GLINT_SHARE strays by several percent).
uvec3 glintHash(ivec2 cell, int moment) {
    uvec3 v = uvec3(ivec3(cell, moment)) * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// The glints' factor on the glitter lobe at surface point `world` (m), `dist` m from the eye,
// time t (s), for a pixel whose footprint there is `footprint` m across. One hash a pixel: the
// coarser cell's draws decide its size (16 bits of x), its own facet (the other 16) and its
// four finer cells' facets (16 bits each of y and z).
float glintFactor(vec2 world, float dist, float t, float footprint) {
    float level = clamp(log2(dist / GLINT_NEAR_M), 0.0, float(GLINT_LEVELS - 1));
    float finer = min(floor(level), float(GLINT_LEVELS - 2));
    float coarse = GLINT_CELL_M * exp2(finer + 1.0);
    vec2 cellPos = world / coarse;
    vec2 cell = floor(cellPos);
    vec2 within = cellPos - cell;
    // the cell's own moments: a cheap phase (its bias does not matter), the draws unbiased
    float phase = fract(dot(cell, vec2(0.0671, 0.5831)) + 0.13 * finer);
    uvec3 h = glintHash(ivec2(cell), int(finer) * 65536 + int(floor(t * GLINT_RATE_HZ + 8.0 * phase)));
    bool whole = float(h.x >> 16u) < (level - finer) * GLINT_DRAW_RANGE;
    bvec2 upper = greaterThanEqual(within, vec2(0.5));
    uint quarter = (upper.x ? h.z : h.y) >> (upper.y ? 16u : 0u);
    float draw = float((whole ? h.x : quarter) & 0xffffu);
    float size = whole ? coarse : 0.5 * coarse;
    vec2 at = ((whole ? within : fract(2.0 * within)) - 0.5) / GLINT_RADIUS;
    float spot = draw < GLINT_SHARE * GLINT_DRAW_RANGE ? max(1.0 - dot(at, at), 0.0) / GLINT_MEAN_COVER : 0.0;
    float resolved = 1.0 - smoothstep(0.5, 1.5, footprint / size);
    return mix(1.0, spot, resolved);
}
