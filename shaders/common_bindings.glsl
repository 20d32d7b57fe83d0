// Every binding point, uniform location and vertex attribute that the renderer's and the
// ocean's programs share with C++, and the std140 uniform blocks: written once, read by both
// languages (GLSL 4.50 takes `const int` in layout qualifiers; engine/gfx/gpu_bindings.h
// includes this file as C++ with vec4/mat4 as glm's). tests/gl/test_gpu_bindings.cpp checks
// the numbers against the compiled programs' reflection.
#ifndef COMMON_BINDINGS_GLSL
#define COMMON_BINDINGS_GLSL

#ifdef __cplusplus
#define SHARED_CONST constexpr int
#define UNIFORM_BLOCK(Name, bindingPoint) struct Name
#define BLOCK_INSTANCE(instance)
#else
#define SHARED_CONST const int
#define UNIFORM_BLOCK(Name, bindingPoint) layout(std140, binding = bindingPoint) uniform Name
#define BLOCK_INSTANCE(instance) instance
#endif

// --- uniform blocks (GL_UNIFORM_BUFFER binding points)
SHARED_CONST FRAME_BLOCK = 0;  // FrameUniforms, one buffer per view
SHARED_CONST WATER_BLOCK = 1;  // WaterUniforms

// --- texture units of the render passes (samplers' bindings)
SHARED_CONST DISPLACEMENT_UNIT = 0;      // water: FFT (Dx, h, Dz, J), 2D array
SHARED_CONST SLOPES_UNIT = 1;            // water: FFT (dh/dx, dh/dz, J, 0), 2D array
SHARED_CONST RIPPLES_UNIT = 2;           // water: ripple heights
SHARED_CONST SKY_UNIT = 3;               // sky cube (water, sky)
SHARED_CONST REFLECTION_UNIT = 4;        // water: the reflection target's colour
SHARED_CONST REFRACTION_UNIT = 5;        // water: the refraction target's colour
SHARED_CONST DETAIL_UNIT = 6;            // water, foam bake: the detail map
SHARED_CONST REFLECTION_DEPTH_UNIT = 7;  // water: the reflection target's depth
SHARED_CONST FOAM_UNIT = 8;              // water: the persistent foam map
SHARED_CONST RIPPLE_SLOPES_UNIT = 9;     // water: ripple slopes
SHARED_CONST FOAM_PATTERN_UNIT = 10;     // water: the baked foam pattern
SHARED_CONST RIPPLE_LEVELS_UNIT = 11;    // water: the coarse ewave levels' heights, 2D array
SHARED_CONST RIPPLE_LEVEL_SLOPES_UNIT = 12;  // water: their slopes, 2D array
SHARED_CONST SCENE_DEPTH_UNIT = 13;      // water (hull clip): the opaque scene's depth before the water pass
SHARED_CONST HULL_OUTLINE_UNIT = 14;     // water (hull clip): the hulls' outlines from their models (assets::HullOutline), R32F 2D array, a layer an outline
SHARED_CONST POST_SOURCE_UNIT = 0;       // post (FXAA, upscale): the frame read

// --- uniform locations, per program
SHARED_CONST OBJECT_MODEL_LOCATION = 0;          // object_mesh*: mat4 unit mesh → world
SHARED_CONST OBJECT_TINT_LOCATION = 1;           // object_mesh*: vec3 colour factor
SHARED_CONST OBJECT_SURFACE_PLANE_LOCATION = 2;  // object_mesh (tangent plane cut): vec3 (height, slope)
SHARED_CONST SPLASH_RIGHT_LOCATION = 0;          // splash_drops*: vec3 camera right
SHARED_CONST SPLASH_UP_LOCATION = 1;             // splash_drops*: vec3 camera up
SHARED_CONST SPLASH_SPRITE_LOCATION = 2;         // splash_drops*: vec3 sprite scale, projection[1][1], least radius
SHARED_CONST SKY_FACE_LOCATION = 0;              // sky bake: mat3 cube face axes
SHARED_CONST FXAA_TEXEL_LOCATION = 0;            // post_fxaa: vec2 1 / source size
SHARED_CONST FXAA_SHARPNESS_LOCATION = 1;        // post_fxaa: float sharpening

// --- vertex attributes
SHARED_CONST MESH_POSITION_ATTRIB = 0;  // object meshes: vec3 position, normal, colour
SHARED_CONST MESH_NORMAL_ATTRIB = 1;
SHARED_CONST MESH_COLOR_ATTRIB = 2;
SHARED_CONST GRID_UV_ATTRIB = 0;        // projected grid: vec2 (u, v)
SHARED_CONST SPLASH_DROP_ATTRIB = 0;    // splash drops: vec4 (centre, radius)

// --- the ocean's compute programs (ocean_spectrum, ocean_fft, ocean_unpack)
SHARED_CONST OCEAN_MODES_BUFFER = 0;         // shader storage: per mode (h̃0(K), h̃0*(−K))
SHARED_CONST OCEAN_QUARTER_BUFFER = 1;       // shader storage: ω and 1/k per mode of a quarter
SHARED_CONST OCEAN_WAVE_NUMBERS_BUFFER = 2;  // shader storage: k per mode
SHARED_CONST OCEAN_SPECTRA_BUFFER = 3;       // shader storage: the four transforms per cascade
SHARED_CONST OCEAN_TWIDDLES_BUFFER = 4;      // shader storage: exp(+2πi·k/N)
SHARED_CONST OCEAN_DISPLACEMENT_IMAGE = 0;   // ocean_unpack: rgba32f image array
SHARED_CONST OCEAN_SLOPES_IMAGE = 1;         // ocean_unpack: rgba32f image array
SHARED_CONST OCEAN_N_LOCATION = 0;           // every ocean program: int N
SHARED_CONST OCEAN_TIME_LOCATION = 1;        // ocean_spectrum: double t (s)
SHARED_CONST OCEAN_LOG2N_LOCATION = 1;       // ocean_fft: int log2 N
SHARED_CONST OCEAN_COLUMNS_LOCATION = 2;     // ocean_fft: int 0 rows, 1 columns
SHARED_CONST OCEAN_LAMBDA_LOCATION = 1;      // ocean_unpack: float λ

// Per-view uniforms shared by every pass: the camera, the mirrored camera, the refraction
// camera. Only vec4 and mat4 members, so std140 puts them at C++'s offsets.
UNIFORM_BLOCK(FrameUniforms, FRAME_BLOCK) {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 cameraPositionTime;   // xyz eye (m), w simulated time (s)
    vec4 sunDirectionFresnel;  // xyz toward the sun (unit), w 0 Schlick / 1 exact
    vec4 waterColorExposure;   // rgb deep water colour, w exposure
    vec4 viewport;             // xy target size (px), z output: 0 display colour, 1 linear radiance + coverage (reflection), 2 display colour + luma in alpha (FXAA), 3 linear radiance + 1 / eye depth in alpha (refraction); w 1 = eye under water
    vec4 surfaceClip;          // x side s (±1; 0 keeps all), y overlap m (m), z 1 = mirror: objects keep s·(y − surface) + m >= 0, mirrored about the surface
    vec4 depthParams;          // near, far (m), water clarity (m), sky cube mip count
    vec4 shading;              // DU/DV strength, normal distortion, the sun's irradiance for the glitter, light shafts under water
    vec4 switches;             // reflections, refractions, foam (1 on, 0 off), dither of the 8-bit outputs (LSB; 0 off)
    vec4 waterline;            // xyz: height (m) of a pixel's point on the near plane above the water's tangent plane at the eye = x·ndc.x + y·ndc.y + z (< 0: the pixel is under water); w the eye's depth under the surface (m, ≥ 0)
    vec4 sky;                  // x [sky] cloud_cover, yz the clouds' drift with the wind aloft (m), w the cloud layer's height (m)
    vec4 sunLight;             // rgb [render] sun_color (linear, before sunTint), w the direct light on a surface facing the sun, × rgb (objects, foam)
    vec4 sunCloud;             // x the share of the sun's direct light the cloud layer holds back on the sun's ray this frame (0 clear; gfx::cloudBeamLoss), yzw unused
} BLOCK_INSTANCE(frame);

SHARED_CONST MAX_GERSTNER_WAVES = 32;
SHARED_CONST HULL_OUTLINE_STATIONS = 64;  // a hull outline's stations (assets::HullOutline::STATIONS)
SHARED_CONST HULL_OUTLINE_HEIGHTS = 24;   // its half-beams a station (assets::HullOutline::HEIGHTS)
SHARED_CONST MAX_HULL_CLIPS = 16;  // hulls whose inside the water skips (common_hull_clip.glsl); the nearest to the eye first
SHARED_CONST MAX_RIPPLE_LEVELS = 3;  // coarse ewave levels (ripples.levels − 1, docs/ewave.md#levels)

// The composite water surface's parameters (the water pass and whatever cuts at the surface).
UNIFORM_BLOCK(WaterUniforms, WATER_BLOCK) {
    vec4 corner[4];          // projected grid corners, homogeneous (x, 0, z, w)
    vec4 cascadeSize;        // tile side of each cascade (m); unused cascades 1
    vec4 waterParams;        // x λ (choppiness sign included), y gravity, z Gerstner wave count, w smallest w (a guard)
    vec4 gridParams;         // x grid resolution, y grid reach from the eye (m), z cascade count, w FFT resolution N
    vec4 rippleParams;       // xy world origin of cell (0, 0) (m), z cell size (m), w cells per side (0: none)
    vec4 foamParams;         // foam map: xy world origin of cell (0, 0) (m), z cell size (m), w cells per side (0: none)
    vec4 cascadeFade;        // per cascade: eye distance (m) where its fade begins
    vec4 cascadeFadeEnd;     // per cascade: eye distance (m) past which it is gone; 0: never fades
    vec4 farFade;            // x 1: Gerstner waves fade where the grid is too sparse for them (0: exact); foam (common_foam.glsl): y the whitecaps' J at density ½, z σ of J (0: a fixed ramp), w the wind's angle atan2(z, x) (rad)
    vec4 cascadeSlopeVariance;  // per cascade: mean square slope of its waves (unused cascades 0)
    vec4 glitterParams;      // x Cox–Munk mean square slope of the wind's sea, 0.003 + 5.12e-3·U10; y U10 (m/s: the foam's spume streaks)
    vec4 crest;              // x the typical crest above the mean level (m), y [render] subsurface strength (0: off), z the camera's projection[1][1]
    vec4 rippleLevels[MAX_RIPPLE_LEVELS];  // coarse level L (layer L − 1): xy world origin of cell (0, 0) (m), z cell size (m)
    vec4 rippleFade;         // x coarse levels (0: level 0 alone), y the composite's fade band (cells of each level)
    vec4 gerstner[MAX_GERSTNER_WAVES];  // (kx, kz, amplitude, phase) per wave
    vec4 hullCount;          // x hulls in hullFromWorld (≤ MAX_HULL_CLIPS)
    mat4 hullFromWorld[MAX_HULL_CLIPS];  // world → hull box unit cube [−1, 1]³ (gfx::HullClip::worldToHull)
    vec4 hullPlan[MAX_HULL_CLIPS];       // x the outline: 0 the box, k > 0 layer k − 1 of the outlines (gfx::HullClip::outline)
} BLOCK_INSTANCE(water);

#undef SHARED_CONST
#undef UNIFORM_BLOCK
#undef BLOCK_INSTANCE
#endif
