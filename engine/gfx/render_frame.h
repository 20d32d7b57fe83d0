// What the passes of one frame share: the three views' uniforms, the frame's facts (set by
// the Renderer before any pass runs) and the timed, labelled span each pass runs in.
#pragma once
#include "gfx/gpu_bindings.h"
#include "gfx/gpu_timer.h"
#include "gfx/handles.h"
#include "view_data/render_def.h"
#include "view_data/sky_def.h"
#include "view_data/scene_view.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <utility>
#include <vector>

namespace ob::gfx {

/// The views a frame is drawn from: the camera; the camera seeing the objects mirrored in the
/// water surface, keeping what is above it ([KTSDE2017] eq. 1–3); the camera keeping what is below.
enum View { MAIN_VIEW, REFLECTION_VIEW, REFRACTION_VIEW, VIEW_COUNT };

/// The passes, in the order Renderer::render runs them (and their timers are reported).
enum Pass { SKY_BAKE_PASS, REFLECTION_PASS, REFRACTION_PASS, OPAQUE_PASS, WATER_PASS, SKY_PASS, SPLASH_PASS, POST_PASS, PASS_COUNT };

// Mean water level (m): the mirrored eye's. The reflection and refraction passes cut objects
// at the surface itself, each reaching this far (m) past it so the waterline leaves no seam
// between the surface the water pass shades and the one the objects were cut at.
constexpr float WATER_LEVEL = 0.0f;
constexpr float REFLECTION_OVERLAP = 0.25f;
constexpr float REFRACTION_OVERLAP = 0.25f;
// Samples a pixel of the msaa4 targets.
constexpr int MSAA_SAMPLES = 4;

/// GPU ms of each pass in the latest resolved frame (pass name → ms).
using PassTimes = std::vector<std::pair<const char*, double>>;

/// A program a pass built, by its label (for the bindings test and debug views).
using ProgramList = std::vector<std::pair<std::string, GLuint>>;

/// This frame's facts, shared by its passes.
struct FrameState {
    Antialias antialias = Antialias::Off;    ///< this frame's mode (never Auto)
    bool underwater = false;                 ///< the whole near plane is below the surface (the eye's side)
    bool waterline = false;                  ///< the surface crosses the near plane: each pixel takes its own side (pixelUnderwater)
    glm::vec4 nearPlaneHeight{0.0f};         ///< FrameUniforms::waterline: the near-plane point's height over the water, affine in ndc; w the eye's depth
    bool waterVisible = false;               ///< some water can be on screen (the projected grid's, WaterPass::prepare)
    glm::ivec2 internal{0};                  ///< the internal frame's size (px)
    glm::vec3 eye{0.0f};                     ///< the camera (m)
    float pixelsPerRadian[VIEW_COUNT] = {};  ///< per view: its target's pixels per radian of view at the centre
    glm::vec2 cloudDrift{0.0f};              ///< how far the clouds drifted with the wind aloft (m, world x, z)
    float exposureGain = 1.0f;               ///< auto exposure's factor on [render] exposure (1 when off; AutoExposure)
};

/// The FrameUniforms buffer of each view, bound at FRAME_BLOCK.
class FrameViews {
public:
    FrameViews();
    /// Fills the three views' uniforms (`skyMips`: the sky cube's mip count).
    void update(const RenderDef& def, const SkyDef& sky, const FrameState& frame, const CameraView& camera, double time, glm::ivec2 reflectionSize,
                glm::ivec2 refractionSize, int skyMips);
    /// Binds a view's uniforms for the draws that follow.
    void bind(View view) const;

private:
    Buffer m_buffers[VIEW_COUNT];
};

/// One GPU timer per pass; results arrive a few frames late.
class PassTimers {
public:
    PassTimers();
    GpuTimer& operator[](Pass pass) { return m_timers[size_t(pass)]; }
    /// GPU ms per pass of the latest frame whose queries resolved (empty until one does).
    PassTimes take();

private:
    std::vector<GpuTimer> m_timers;
};

/// What every pass of a frame reads: the settings, the frame's facts, the views, the timers.
struct FrameContext {
    explicit FrameContext(const RenderDef& d) : def(d) {}
    RenderDef def;
    SkyDef sky;
    FrameState state;
    FrameViews views;
    PassTimers timers;
};

/// A pass's span: its debug group and GPU timer, begun here and ended on destruction.
class PassScope {
public:
    PassScope(FrameContext& frame, Pass pass);
    ~PassScope();
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;

private:
    GpuTimer& m_timer;
};

/// The height (m) of each pixel's point on the near plane above the water's tangent plane at the
/// eye, as (a, b, c) of a·ndc.x + b·ndc.y + c (affine: the near plane and the tangent plane are
/// planes), and in w the eye's depth under the surface (m, ≥ 0).
glm::vec4 nearPlaneWaterHeight(const CameraView& camera);

/// Levels of a full mip chain for a square of `size` texels.
int mipLevels(int size);

} // namespace ob::gfx
