// Rendering settings, section [render].
#pragma once
#include "core/schema.h"

namespace ob::gfx {

/// The Fresnel term of the water surface.
enum class Fresnel : uint8_t { Schlick, Exact };
constexpr std::array<const char*, 2> names(Fresnel) { return {"schlick", "exact"}; }

/// Edge smoothing of the frame.
enum class Antialias : uint8_t {
    Auto,   ///< Msaa4 on a GPU, Fxaa on a software rasteriser (which pays for every sample on the CPU)
    Off,
    Fxaa,   ///< one post pass
    Msaa4,  ///< 4 samples a pixel
};
constexpr std::array<const char*, 4> names(Antialias) { return {"auto", "off", "fxaa", "msaa4"}; }

/// Whether the exposure adapts to the frame (gfx/auto_exposure.h).
enum class AutoExposureMode : uint8_t {
    Auto,  ///< on in `play` with a window, off in `run` and headless runs (their pictures stay reproducible)
    On,
    Off,
};
constexpr std::array<const char*, 3> names(AutoExposureMode) { return {"auto", "on", "off"}; }

/// Look of the sky and the water surface; every switch removes its pass or term.
struct RenderDef {
    glm::vec3 sun_direction{0.35f, 0.30f, 0.88f};  ///< direction toward the sun (world, y up; normalised on use); unused when time_of_day is set
    float time_of_day = -1.0f;                      ///< local solar time, hours, [−1, 24]: the sun stands where it does at that hour (gfx/sun.h; 12 noon toward +z, rising toward +x), sky and light follow; −1 = off (sun_direction)
    float latitude_deg = 40.0f;                     ///< latitude of the sea for time_of_day, degrees, [−90, 90]
    float sun_declination_deg = 10.0f;              ///< the sun's declination for time_of_day, degrees, [−23.44, 23.44] (0 at the equinoxes, +23.44 at the June solstice)
    glm::vec3 sun_color{1.0f, 0.92f, 0.8f};        ///< the sunlight's colour at noon (linear RGB, [0, 10]; tinted by the sun's height): objects, foam, spray, light shafts
    glm::vec3 water_color{0.015f, 0.09f, 0.13f};   ///< deep water body colour (linear RGB, 0..1)
    Fresnel fresnel = Fresnel::Schlick;             ///< "schlick" approximation or "exact" unpolarised equations (n = 1.33)
    bool reflections = true;                        ///< planar reflection pass (objects above the water, mirrored); off: sky only
    bool refractions = true;                        ///< refraction pass (objects below the water, depth colour); off: body colour only
    float rtt_scale = 0.5f;                         ///< reflection/refraction target size / framebuffer size, [0.1, 1]
    float dudv_strength = 0.02f;                    ///< DU/DV distortion of the reflection/refraction lookups (fraction of the screen), [0, 0.2]
    float normal_distortion = 0.05f;                ///< offset of those lookups by the surface normal's slope ([Lee2007]), [0, 0.5]
    float water_clarity = 4.0f;                     ///< depth (m) over which refracted light fades to the water colour by 1/e, [0.05, 1000]
    bool foam = true;                               ///< whitecaps where the FFT Jacobian folds, splash rings where ripples are steep, and the persistent foam map
    bool splash_drops = true;                       ///< splash drops drawn as lit sprites (main view and reflection)
    float splash_sprite_scale = 6.0f;               ///< sprite radius / drop radius: a simulated drop stands for a cluster of spray, [1, 100]
    float glitter = 6.0f;                           ///< the sun's irradiance on the water (× sun colour, relative to the sky's radiance), [0, 100]; its glitter spreads as the sea's slopes (Cox & Munk 1954)
    float exposure = 1.0f;                          ///< scene exposure multiplier before tone mapping, [0.01, 16]
    AutoExposureMode auto_exposure = AutoExposureMode::Auto;  ///< exposure × a gain that adapts to the frame's log-average luminance (τ ≈ 1 s, gain in [1/4, 8]): "auto" (on in play, off in run), "on", "off"
    float resolution_scale = 1.0f;                  ///< internal render size / framebuffer size, [0.25, 1]; below 1 the frame is scaled up (bilinear)
    float target_fps = 30.0f;                       ///< dynamic resolution: the internal scale follows the frame time to hold this rate (play; run only when set on the command line), [0, 1000]; 0 = off (resolution_scale as set)
    Antialias antialias = Antialias::Auto;          ///< edge smoothing: "off", "fxaa" (one post pass), "msaa4" (4 samples a pixel), "auto" (msaa4 on a GPU, fxaa on a software rasteriser)
    int grid_resolution = 0;                        ///< projected grid cells per side, [16, 2048]; 0 = auto (one per 3 px of internal height on a GPU, per 12 px on a software rasteriser, within [32, 512])
    float upscale_sharpness = 0.75f;                ///< sharpening of the frame scaled up from resolution_scale < 1 (fxaa), [0, 1]; 0 = plain bilinear
    bool far_fade = true;                           ///< far field without regular patterns: FFT cascades fade out by tile_fade tiles, Gerstner waves where the grid is too sparse to sample them
    float tile_fade = 6.0f;                         ///< FFT cascade c is gone past this many of its tiles from the eye (fading from a third of it), [1, 1000]
    bool water_full_quality = false;                ///< every water term per pixel (the reference the shipped shading is tested against); slower on a software rasteriser
    bool hull_clip = true;                          ///< no water drawn inside a floating hull where the hull lies behind it (its clip volume, shaders/common_hull_clip.glsl, docs/frame.md#hulls)
    bool dither = true;                             ///< ±1 LSB triangular noise on every colour written in 8 bits (shaders/common_dither.glsl): no banding in smooth gradients; off: plain rounding
    float subsurface = 1.0f;                        ///< light through thin crests: the turquoise of a backlit crest (shaders/common_subsurface.glsl), × its strength, [0, 4]; 0 = off
    float light_shafts = 1.0f;                      ///< under water: sunlight shafts in the water and caustics on bodies (shaders/common_underwater.glsl), × their strength, [0, 4]; 0 = off
    bool interpolate = true;                        ///< bodies and the camera drawn between the last two fixed steps, at the clock's fraction of a step past the earlier (smooth at any display rate, one step behind); off: at the latest step. The simulation is untouched
};

template <class V> void describe(V& v, RenderDef& d) {
    v.field("sun_direction", d.sun_direction, direction(), "direction toward the sun (world, y up); unused when time_of_day is set", LIVE);
    v.field("time_of_day", d.time_of_day, range(-1, 24), "local solar time, hours: places the sun (12 = noon); -1 = off (sun_direction)", LIVE);
    v.field("latitude_deg", d.latitude_deg, range(-90, 90), "latitude for time_of_day, degrees", LIVE);
    v.field("sun_declination_deg", d.sun_declination_deg, range(-23.44, 23.44), "the sun's declination for time_of_day, degrees", LIVE);
    v.field("sun_color", d.sun_color, range(0, 10), "the sunlight's colour at noon, linear RGB (objects, foam, spray, light shafts)", LIVE);
    v.field("water_color", d.water_color, range(0, 1), "deep water body colour (linear RGB)", LIVE);
    v.field("fresnel", d.fresnel, "Fresnel term: Schlick or exact (n = 1.33)", LIVE);
    v.field("reflections", d.reflections, "planar reflection pass (local objects mirrored); off: sky only", LIVE);
    v.field("refractions", d.refractions, "refraction pass (objects under water, depth colour); off: body colour", LIVE);
    v.field("rtt_scale", d.rtt_scale, range(0.1, 1), "reflection/refraction target size / framebuffer size", LIVE);
    v.field("dudv_strength", d.dudv_strength, range(0, 0.2), "DU/DV distortion of reflection/refraction (screen fraction)", LIVE);
    v.field("normal_distortion", d.normal_distortion, range(0, 0.5), "lookup offset by the surface slope (screen fraction)", LIVE);
    v.field("water_clarity", d.water_clarity, range(0.05, 1000), "depth (m) over which refracted light fades to the water colour", LIVE);
    v.field("foam", d.foam, "whitecaps (FFT Jacobian), splash rings (steep ripples) and the persistent foam map", LIVE);
    v.field("splash_drops", d.splash_drops, "draw the splash drops as lit sprites", LIVE);
    v.field("splash_sprite_scale", d.splash_sprite_scale, range(1, 100), "sprite radius / drop radius (a drop stands for a cluster of spray)", LIVE);
    v.field("glitter", d.glitter, range(0, 100), "the sun's irradiance on the water (its glitter spreads as the sea's slopes)", LIVE);
    if constexpr (requires { v.refuse("", std::string()); })
        v.refuse("glitter_shininess", "removed: the glitter spreads as the sea's slopes (Cox & Munk 1954), set by ocean.wind_speed");
    v.field("exposure", d.exposure, range(0.01, 16), "exposure multiplier before tone mapping", LIVE);
    v.field("auto_exposure", d.auto_exposure, "exposure adapts to the frame's brightness (τ 1 s, gain 1/4 to 8): auto (on in play, off in run), on, off", LIVE);
    v.field("resolution_scale", d.resolution_scale, range(0.25, 1), "internal render size / framebuffer size (scaled up below 1)", LIVE);
    v.field("target_fps", d.target_fps, range(0, 1000), "dynamic resolution holds this frame rate (play); 0 = off", LIVE);
    v.field("antialias", d.antialias, "edge smoothing: off, fxaa (post pass), msaa4 (4 samples), auto (msaa4 on a GPU, fxaa in software)", LIVE);
    v.field("grid_resolution", d.grid_resolution, autoOrRange(16, 2048), "projected grid cells per side; 0 = auto (internal height / 3 on a GPU, / 12 in software)", LIVE);
    v.field("upscale_sharpness", d.upscale_sharpness, range(0, 1), "sharpening of a frame scaled up from resolution_scale < 1 (fxaa); 0 = none", LIVE);
    v.field("far_fade", d.far_fade, "FFT cascades fade out with distance, Gerstner waves where the grid cannot sample them", LIVE);
    v.field("tile_fade", d.tile_fade, range(1, 1000), "FFT cascades fade out by this many of their tiles from the eye (far_fade)", LIVE);
    v.field("water_full_quality", d.water_full_quality, "every water term per pixel (reference shading; slower in software)", LIVE);
    v.field("hull_clip", d.hull_clip, "no water drawn inside a floating hull (the sea over its deck, in an open boat)", LIVE);
    v.field("dither", d.dither, "±1 LSB noise on the 8-bit colour outputs (no banding in gradients); off: plain rounding", LIVE);
    v.field("subsurface", d.subsurface, range(0, 4), "light through thin crests: turquoise of a backlit crest, × this; 0 = off", LIVE);
    v.field("light_shafts", d.light_shafts, range(0, 4), "under water: sunlight shafts and caustics on bodies, × this; 0 = off", LIVE);
    v.field("interpolate", d.interpolate, "bodies and the camera drawn between the last two steps (smooth at any display rate); off: the latest step", LIVE);
}

} // namespace ob::gfx
