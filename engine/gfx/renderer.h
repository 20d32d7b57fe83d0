// The renderer: a short list of passes, each an object that owns its targets and programs;
// Renderer::render runs them in this order.
//   sky bake   → the analytic daylight sky into a cube map, when the sun moves      (SkyPass)
//   reflection → objects above the water surface, mirrored about it (per vertex) → colour + depth target (SurfacePasses)
//   refraction → objects below the water surface from the camera → colour target (1 / eye depth in alpha) (SurfacePasses)
//   opaque     → objects from the camera into the framebuffer                        (ObjectPass, MeshCache)
//   water      → the composite surface on a projected grid, shaded from the targets and sky (WaterPass)
//   sky        → the cube map (or underwater fog) where nothing else was drawn       (SkyPass)
//   splash     → splash drops as lit, soft sprites over the frame (depth-tested, blended; the
//                reflection pass draws them too, mirrored)                           (SplashPass)
//   post       → the internal frame to the framebuffer: MSAA resolve, FXAA, upscale (when
//                resolution_scale < 1); skipped when the frame was drawn into it directly (PostPass)
//   exposure   → with auto exposure: the finished frame read back small, the next frame's
//                exposure gain adapted to it                                          (AutoExposure)
// Bindings, locations and the uniform blocks: shaders/common_bindings.glsl (gfx/gpu_bindings.h).
#pragma once
#include "gfx/auto_exposure.h"
#include "gfx/object_pass.h"
#include "gfx/post_pass.h"
#include "gfx/render_frame.h"
#include "gfx/sky_pass.h"
#include "gfx/splash_pass.h"
#include "gfx/surface_passes.h"
#include "gfx/water_pass.h"

#include <span>
#include <string>
#include <vector>

namespace ob::gfx {

/// The mode a `RenderDef::antialias` key selects (never Auto: that is Msaa4 on a GPU and Fxaa
/// on a software rasteriser).
Antialias antialiasMode(Antialias key, bool softwareRenderer);

/// Orders the passes of a frame; the passes own the programs, targets and buffers.
class Renderer {
public:
    explicit Renderer(const RenderDef& def);
    /// Draws one frame of the scene into the default framebuffer of `size`; `drops`: the live
    /// splash drops (drawn unless [render] splash_drops is off).
    void render(const CameraView& camera, const WaterView& water, const std::vector<ObjectDraw>& objects, double time,
                glm::ivec2 size, std::span<const SplashDrop> drops = {});
    /// GPU ms per pass of the latest frame whose timer queries resolved (empty until one does).
    PassTimes takePassTimes() { return m_frame.timers.take(); }
    RenderDef& def() { return m_frame.def; }
    /// The sky's weather ([sky]).
    SkyDef& sky() { return m_frame.sky; }
    /// Whether render.auto_exposure's "auto" means on (play with a window) or off (run).
    void setAutoExposureDefault(bool on) { m_autoExposureDefault = on; }
    /// The exposure gain the next frame is drawn with (1 without auto exposure).
    float exposureGain() const { return m_frame.state.exposureGain; }
    /// The reflection and refraction targets of the latest frame (for tests and debug views).
    const RenderTarget& reflectionTarget() const { return m_surfaces.reflection(); }
    const RenderTarget& refractionTarget() const { return m_surfaces.refraction(); }
    /// The detail map and the foam pattern baked from it (RGBA8, for tests).
    const Texture& detailMap() const { return m_water.detail().detailMap(); }
    const Texture& foamPatternMap() const { return m_water.detail().foamPattern(); }
    /// Every program the passes have built so far, by label (the water's variants as met).
    ProgramList programs() const;

private:
    void beginFrame(const CameraView& camera, double time, glm::ivec2 size, float windAngle);
    bool autoExposureOn() const;

    FrameContext m_frame;
    SkyPass m_sky;
    WaterPass m_water;
    ObjectPass m_objects;
    SurfacePasses m_surfaces;
    SplashPass m_splash;
    PostPass m_post;
    AutoExposure m_exposure;
    bool m_autoExposureDefault = false;
};

/// Reads the default framebuffer (size px) and writes it as an RGB PNG, top row first.
/// Writes to a temporary file and renames it, so a failed write leaves nothing behind.
/// Throws ob::InputError when the path cannot be written.
void writeScreenshot(const std::string& path, glm::ivec2 size);

} // namespace ob::gfx
