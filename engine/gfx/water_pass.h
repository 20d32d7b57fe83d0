// The water surface: the composite surface (Gerstner + FFT cascades + ripples) on a projected
// grid, shaded from the reflection and refraction targets, the sky and the detail maps, with
// its program compiled per configuration (WaterVariant).
#pragma once
#include "assets/hull_outline.h"
#include "environment/environment_def.h"
#include "gfx/projected_grid.h"
#include "gfx/render_frame.h"
#include "gfx/water_detail.h"
#include "gfx/water_layers.h"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ob::gfx {

class SkyPass;
class SurfacePasses;

/// The water layers the surface pass draws (everything optional: absent layers are flat).
struct WaterView {
    const Texture* displacement = nullptr;  ///< 2D array, layer per cascade: (Dx, h, Dz, J)
    const Texture* slopes = nullptr;        ///< 2D array, layer per cascade: (dh/dx, dh/dz, J, 0)
    int cascades = 0;                       ///< FFT cascades in the textures, [0, 4]
    int resolution = 1;                     ///< FFT N
    std::array<float, 4> cascadeSize{};     ///< tile side per cascade (m)
    std::array<float, 4> cascadeSlopeVariance{};  ///< mean square slope of each cascade's waves (ocean::cascadeSlopeVariance)
    float seaSlopeVariance = 0.0f;          ///< the whole sea's mean square slope (ocean::coxMunkSlopeVariance): the glitter's spread
    float lambda = 0.0f;                    ///< choppy displacement factor λ (X + λ·D)
    float gravity = environment::STANDARD_ENVIRONMENT.gravity;  ///< m/s², Gerstner dispersion (OceanDef::gravity)
    std::vector<glm::vec4> gerstner;        ///< (kx, kz, amplitude, phase) per wave, at most 32
    const float* ripples = nullptr;         ///< ripple heights Vh(t), rippleCells² row-major (z rows), m
    int rippleCells = 0;                    ///< ripple patch cells per side (0: no ripple layer)
    glm::vec2 rippleOrigin{0.0f};           ///< world (x, z) of cell (0, 0)'s centre, m
    float rippleCellSize = 1.0f;            ///< m per cell
    /// A coarse ewave level (docs/ewave.md#levels): rippleCells² heights like `ripples`, placed by its own origin and cell.
    /// Its height is evaluated on the GPU (shaders/ripple_levels.comp): the cubic in time of its
    /// last two states, uploaded only when `version` changes, with this frame's weights.
    struct RippleLevel {
        std::array<const float*, 4> states{};  ///< h0, h1 (m), v0, v1 (m/s), each rippleCells² row-major (z rows)
        uint64_t version = 0;               ///< changes whenever the states do
        glm::vec4 weights{0.0f};            ///< height = weights · (h0, h1, v0, v1) this frame
        std::array<glm::vec2, 4> extremes{};  ///< (min, max) of each state: the grid's reach without reading them
        glm::vec2 origin{0.0f};             ///< world (x, z) of cell (0, 0)'s centre, m
        float cellSize = 1.0f;              ///< m per cell
    };
    std::vector<RippleLevel> rippleLevels;  ///< levels 1.. of the patch, at most MAX_RIPPLE_LEVELS (none: one grid)
    int rippleFadeCells = 0;                ///< the composite's fade band, cells of each level (RippleLevels::sponge)
    const float* foam = nullptr;            ///< persistent foam coverage [0, 1], foamCells² row-major (z rows)
    int foamCells = 0;                      ///< foam map cells per side (0: no foam map)
    glm::vec2 foamOrigin{0.0f};             ///< world (x, z) of foam cell (0, 0)'s centre, m
    float foamCellSize = 1.0f;              ///< m per foam cell
    /// Whitecaps drawn from the per-pixel Jacobian J (shaders/common_foam.glsl): density ½ at
    /// whitecapJacobian, ramping over whitecapSigma either side (foam::WhitecapLaw's viewJacobian,
    /// sigma); whitecapSigma 0: the fixed ramp from J = 0.6 to 0.1.
    float whitecapJacobian = 0.0f;
    float whitecapSigma = 0.0f;
    float windAngle = 0.0f;                 ///< direction the wind blows toward, atan2(z, x), rad: the foam's streaks lie along it
    float windSpeed = 0.0f;                 ///< U10 (m/s): from a gale up the foam's lace is drawn out into spume streaks along the wind
    /// How far the FFT cascades together move a rest point (m; λ included): the projected
    /// grid reaches this far past the view. Gerstner and ripple bounds the renderer derives.
    SurfaceBounds fftBounds;
    std::vector<HullClip> hulls;            ///< floating hulls: no water is drawn inside them ([render] hull_clip)
};

/// What the water program is compiled for (`#define`s of shaders/water_surface.frag): each a
/// constant in its code, so the compiler drops the terms that are off and unrolls the cascades'
/// loop. A software rasteriser runs both sides of a branch on a uniform, and a loop over a
/// uniform count cost it a sixth of the water pass. One program per variant met, kept.
struct WaterVariant {
    int cascades = 0;          ///< FFT cascades sampled (0: no layers)
    bool ripples = false;      ///< a ripple patch is uploaded
    bool foamMap = false;      ///< a persistent foam map is uploaded
    bool underwater = false;   ///< the whole near plane is below the surface: the surface seen from below
    bool waterline = false;    ///< the surface crosses the near plane: each pixel takes its side (both shadings compiled)
    bool exactFresnel = false; ///< [render] fresnel = "exact" (else Schlick)
    bool clouds = false;       ///< [sky] cloud_cover > 0: the sky reflected from the baked cube (its clouds), else the clear sky's formula
    bool reflections = true, refractions = true, foam = true;  ///< [render] switches
    bool fullQuality = false;  ///< [render] water_full_quality: every term per pixel, the reference
    bool hullClip = false;     ///< hulls are clipped out of the water ([render] hull_clip and at least one hull)
    int hullDepthSamples = 1;  ///< samples a pixel of the frame's depth the clip reads (4 in msaa4)
    /// The lines put after the shaders' #version line.
    std::string defines() const;
};

class WaterPass {
public:
    WaterPass();
    /// Before the object passes, which clip against (and mirror about) the surface: the grid for
    /// the camera, the water uniforms, the layers' textures bound; sets frame.state.waterVisible.
    void prepare(FrameContext& frame, const CameraView& camera, const WaterView& water);
    /// in: water layers, reflection and refraction targets, sky, and the frame's framebuffer
    /// `frameFramebuffer` (0: the default one), bound, holding the opaque scene; out: the water in it.
    void waterPass(FrameContext& frame, const SkyPass& sky, const SurfacePasses& surfaces, GLuint frameFramebuffer);
    const WaterDetail& detail() const { return m_detail; }
    void listPrograms(ProgramList& out) const;

private:
    void buildGrid(int resolution);
    int uploadHullClips(const WaterView& water, const CameraView& camera, WaterUniforms& u);
    int hullOutlineLayer(const std::shared_ptr<const assets::HullOutline>& outline);
    void uploadHullOutlines();
    void uploadUniforms(FrameContext& frame, const CameraView& camera, const WaterView& water);
    void copySceneDepth(const FrameContext& frame, GLuint frameFramebuffer);

    WaterDetail m_detail;
    WaterLayers m_layers;
    Buffer m_uniforms;
    VertexArray m_gridVao;
    Buffer m_gridVertices, m_gridIndices;
    int m_gridResolution = 0;
    GLsizei m_gridIndexCount = 0;
    GridCorners m_grid;           // this frame's projected grid
    WaterVariant m_variant;       // this frame's
    float m_crestBound = 0.0f;    // this frame's tallest crest above the mean level (m)
    std::map<std::string, Program> m_programs;  // by WaterVariant::defines(), compiled on first use
    // The hull clip's copy of the opaque scene's depth, made before the water is drawn
    // (DEPTH_COMPONENT32F, the frame's size and samples), and the framebuffer that holds it.
    Texture m_sceneDepth;
    // The outlines of the hulls drawn this frame, a layer each (HULL_OUTLINE_UNIT), and which.
    Texture m_hullOutlines;
    std::vector<std::shared_ptr<const assets::HullOutline>> m_hullOutlineLayers;
    Framebuffer m_sceneDepthFramebuffer;
    glm::ivec2 m_sceneDepthSize{0};
    int m_sceneDepthSamples = 0;
};

} // namespace ob::gfx
