// Per-frame uniforms shared by every pass (mirror: gfx::FrameUniforms, std140).
layout(std140, binding = 0) uniform FrameUniforms {
    mat4 u_viewProjection;
    mat4 u_inverseViewProjection;
    vec4 u_cameraPositionTime;   // xyz eye (m), w time (s)
    vec4 u_sunDirectionFresnel;  // xyz toward the sun, w 0 Schlick / 1 exact
    vec4 u_waterColorExposure;   // rgb deep water colour, w exposure
    vec4 u_viewport;             // xy framebuffer size (px)
};

// World-space view ray through a pixel (ndc in [-1, 1]²).
vec3 viewRay(vec2 ndc) {
    vec4 farPoint = u_inverseViewProjection * vec4(ndc, 1.0, 1.0);
    return normalize(farPoint.xyz / farPoint.w - u_cameraPositionTime.xyz);
}

// Exposure, filmic tone curve (Narkowicz's ACES fit) and sRGB encoding.
vec3 toneMap(vec3 radiance) {
    vec3 x = radiance * u_waterColorExposure.w;
    x = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    return pow(x, vec3(1.0 / 2.2));
}
