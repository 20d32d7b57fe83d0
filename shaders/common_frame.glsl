// Per-view uniforms shared by every pass (mirror: gfx::FrameUniforms, std140).
layout(std140, binding = 0) uniform FrameUniforms {
    mat4 u_viewProjection;
    mat4 u_inverseViewProjection;
    vec4 u_cameraPositionTime;   // xyz eye (m), w time (s)
    vec4 u_sunDirectionFresnel;  // xyz toward the sun, w 0 Schlick / 1 exact
    vec4 u_waterColorExposure;   // rgb deep water colour, w exposure
    vec4 u_viewport;             // xy target size (px), z output: 0 display colour, 1 linear radiance, 2 display colour + luma in alpha, 3 linear radiance + 1 / eye depth in alpha; w 1 = eye under water
    vec4 u_surfaceClip;          // x side s, y overlap m (m), z 1 = mirror: objects keep s·(y − surface) + m >= 0 (s 0: all), mirrored about the surface
    vec4 u_depthParams;          // near, far (m), water clarity (m), sky cube mip count
    vec4 u_shading;              // DU/DV strength, normal distortion, glitter strength, glitter shininess
    vec4 u_switches;             // reflections, refractions, foam (1 on, 0 off)
};

// World-space view ray through a pixel (ndc in [-1, 1]²).
vec3 viewRay(vec2 ndc) {
    vec4 farPoint = u_inverseViewProjection * vec4(ndc, 1.0, 1.0);
    return normalize(farPoint.xyz / farPoint.w - u_cameraPositionTime.xyz);
}

bool eyeUnderwater() { return u_viewport.w > 0.5; }

// Water body colour lit by the sun's height (linear radiance); dark at night (the sun below
// sin e = −0.18, as common_sky.glsl's daylight()).
vec3 waterBodyColor() {
    float night = mix(0.06, 1.0, smoothstep(-0.18, 0.10, u_sunDirectionFresnel.y));
    return u_waterColorExposure.rgb * (0.35 + 0.65 * max(u_sunDirectionFresnel.y, 0.0)) * night;
}

// Light through `dist` metres of water: fades to the body colour (Beer–Lambert by clarity).
vec3 underwaterFog(vec3 color, float dist) {
    return mix(waterBodyColor(), color, exp(-dist / (4.0 * u_depthParams.z)));
}

// Exposure, filmic tone curve (Narkowicz's ACES fit) and sRGB encoding; render targets keep
// linear radiance (the water pass tone-maps what it reads from them). For the FXAA pass the
// frame's alpha carries the encoded colour's luma (Rec. 601 weights), read there in fours. In
// the refraction target the objects' shader puts 1 / their eye depth in alpha (object_mesh.frag).
vec4 finalColor(vec3 radiance) {
    if (u_viewport.z > 0.5 && (u_viewport.z < 1.5 || u_viewport.z > 2.5)) return vec4(radiance, 1.0);
    vec3 x = radiance * u_waterColorExposure.w;
    x = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    vec3 display = pow(x, vec3(1.0 / 2.2));
    return vec4(display, u_viewport.z > 1.5 ? dot(display, vec3(0.299, 0.587, 0.114)) : 1.0);
}
