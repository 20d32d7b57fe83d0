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
