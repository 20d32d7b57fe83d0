// The renderer: a short list of passes (Renderer::render runs them in this order).
//   sky bake   → the analytic daylight sky into a cube map, when the sun moves
//   reflection → objects above the water surface, mirrored about it (per vertex) → colour + depth target
//   refraction → objects below the water surface from the camera → colour target (1 / eye depth in alpha)
//   opaque     → objects from the camera into the framebuffer
//   water      → the composite surface on a projected grid, shaded from the targets and sky
//   sky        → the cube map (or underwater fog) where nothing else was drawn
//   splash     → splash drops as lit, soft sprites over the frame (depth-tested, blended; the
//                reflection pass draws them too, mirrored)
//   post       → the internal frame to the framebuffer: MSAA resolve, FXAA, upscale (when
//                resolution_scale < 1); skipped when the frame was drawn into it directly
// Bindings, locations and the uniform blocks: shaders/common_bindings.glsl (gfx/gpu_bindings.h).
#pragma once
#include "gfx/gpu_bindings.h"
#include "gfx/gpu_timer.h"
#include "gfx/handles.h"
#include "gfx/mesh.h"
#include "view_data/render_def.h"
#include "gfx/render_target.h"
#include "view_data/scene_view.h"
#include "gfx/projected_grid.h"

#include <array>
#include <glm/mat4x4.hpp>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ob::gfx {

/// The mode a `RenderDef::antialias` key selects (never Auto: that is Msaa4 on a GPU and Fxaa
/// on a software rasteriser).
Antialias antialiasMode(Antialias key, bool softwareRenderer);

/// The water layers the surface pass draws (everything optional: absent layers are flat).
struct WaterView {
    const Texture* displacement = nullptr;  ///< 2D array, layer per cascade: (Dx, h, Dz, J)
    const Texture* slopes = nullptr;        ///< 2D array, layer per cascade: (dh/dx, dh/dz, J, 0)
    int cascades = 0;                       ///< FFT cascades in the textures, [0, 4]
    int resolution = 1;                     ///< FFT N
    std::array<float, 4> cascadeSize{};     ///< tile side per cascade (m)
    float lambda = 0.0f;                    ///< choppy displacement factor λ (X + λ·D)
    float gravity = 9.81f;                  ///< m/s², Gerstner dispersion
    std::vector<glm::vec4> gerstner;        ///< (kx, kz, amplitude, phase) per wave, at most 32
    const float* ripples = nullptr;         ///< ripple heights Vh(t), rippleCells² row-major (z rows), m
    int rippleCells = 0;                    ///< ripple patch cells per side (0: no ripple layer)
    glm::vec2 rippleOrigin{0.0f};           ///< world (x, z) of cell (0, 0)'s centre, m
    float rippleCellSize = 1.0f;            ///< m per cell
    const float* foam = nullptr;            ///< persistent foam coverage [0, 1], foamCells² row-major (z rows)
    int foamCells = 0;                      ///< foam map cells per side (0: no foam map)
    glm::vec2 foamOrigin{0.0f};             ///< world (x, z) of foam cell (0, 0)'s centre, m
    float foamCellSize = 1.0f;              ///< m per foam cell
    /// How far the FFT cascades together move a rest point (m; λ included): the projected
    /// grid reaches this far past the view. Gerstner and ripple bounds the renderer derives.
    SurfaceBounds fftBounds;
};

/// What the water program is compiled for (`#define`s of shaders/water_surface.frag): each a
/// constant in its code, so the compiler drops the terms that are off and unrolls the cascades'
/// loop. A software rasteriser runs both sides of a branch on a uniform, and a loop over a
/// uniform count cost it a sixth of the water pass. One program per variant met, kept.
struct WaterVariant {
    int cascades = 0;          ///< FFT cascades sampled (0: no layers)
    bool ripples = false;      ///< a ripple patch is uploaded
    bool foamMap = false;      ///< a persistent foam map is uploaded
    bool underwater = false;   ///< the eye is below the surface
    bool exactFresnel = false; ///< [render] fresnel = "exact" (else Schlick)
    bool reflections = true, refractions = true, foam = true;  ///< [render] switches
    bool fullQuality = false;  ///< [render] water_full_quality: every term per pixel, the reference
    /// The lines put after the shaders' #version line.
    std::string defines() const;
};

/// GPU ms of each pass in the latest resolved frame (pass name → ms).
using PassTimes = std::vector<std::pair<const char*, double>>;

/// Owns the programs, targets and buffers of every pass.
class Renderer {
public:
    explicit Renderer(const RenderDef& def);
    /// Draws one frame of the scene into the default framebuffer of `size`; `drops`: the live
    /// splash drops (drawn unless [render] splash_drops is off).
    void render(const CameraView& camera, const WaterView& water, const std::vector<ObjectDraw>& objects, double time,
                glm::ivec2 size, std::span<const SplashDrop> drops = {});
    /// GPU ms per pass of the latest frame whose timer queries resolved (empty until one does).
    PassTimes takePassTimes();
    RenderDef& def() { return m_def; }
    /// The reflection and refraction targets of the latest frame (for tests and debug views).
    const RenderTarget& reflectionTarget() const { return m_reflection; }
    const RenderTarget& refractionTarget() const { return m_refraction; }
    /// The detail map and the foam pattern baked from it (RGBA8, for tests).
    const Texture& detailMap() const { return m_detailMap; }
    const Texture& foamPatternMap() const { return m_foamPattern; }

private:
    enum View { MAIN_VIEW, REFLECTION_VIEW, REFRACTION_VIEW, VIEW_COUNT };
    enum Pass { SKY_BAKE_PASS, REFLECTION_PASS, REFRACTION_PASS, OPAQUE_PASS, WATER_PASS, SKY_PASS, SPLASH_PASS, POST_PASS, PASS_COUNT };

    void skyBakePass();  // in: sun direction; out: m_skyCube (linear radiance, mipmapped)
    void reflectionPass(const std::vector<ObjectDraw>& objects);  // in: mirrored view, objects; out: m_reflection colour + depth
    void refractionPass(const std::vector<ObjectDraw>& objects);  // in: camera view, objects; out: m_refraction colour, 1 / eye depth in alpha
    void opaquePass(const std::vector<ObjectDraw>& objects);      // in: camera view, objects; out: framebuffer colour, depth
    void prepareWater(const CameraView& camera, const WaterView& water, int internalHeight);  // out: grid, water uniforms, layer textures bound
    void waterPass(const CameraView& camera);  // in: water layers, targets, sky; out: framebuffer
    void skyPass();  // in: sky cube, depth; out: colour where nothing was drawn
    void splashPass();  // in: camera view, uploaded drops, depth; out: framebuffer colour (blended)
    void postPass(glm::ivec2 size);  // in: m_multisampled or m_internal; out: framebuffer of `size`

    // Splash drops and foam (renderer_effects.cpp).
    void uploadSplashDrops(std::span<const SplashDrop> drops, const CameraView& camera);  // out: m_splashBuffer, sprite uniforms
    void drawSplashDrops(View view);  // the uploaded drops as sprites into the bound target (MAIN_VIEW or REFLECTION_VIEW)
    void uploadFoam(const WaterView& water, WaterUniforms& u);  // out: m_foamTexture, u.foamParams

    void drawObjects(const std::vector<ObjectDraw>& objects, View view);
    // A glTF model's mesh and its far twin, if one lies beside it.
    struct ModelMeshes {
        Mesh near;
        std::optional<Mesh> far;
    };
    const ModelMeshes& meshesFor(const std::string& file);
    const Mesh& meshFor(const ObjectDraw& object, View view);
    glm::vec3 m_eye{0.0f};                   // this frame's camera (m)
    float m_pixelsPerRadian[VIEW_COUNT] = {};  // per view: its target's pixels per radian of view at the centre
    void updateFrameUniforms(const CameraView& camera, double time, glm::ivec2 size);
    void resizeTargets(glm::ivec2 internal);
    void uploadWaterUniforms(const CameraView& camera, const WaterView& water, const GridCorners& grid);
    GridCorners m_grid;  // this frame's projected grid (prepareWater)
    void buildGrid(int resolution);

    RenderDef m_def;
    Program m_skyBakeProgram, m_skyProgram, m_objectProgram, m_objectWaterlineProgram, m_upscaleProgram;
    Program m_fxaaPrograms[2];  // post_fxaa.frag off the edges, then on them
    Mesh m_sphereMesh, m_boxMesh, m_ringMesh;
    std::map<std::string, ModelMeshes> m_models;  // glTF meshes by file, loaded on first draw
    VertexArray m_emptyVao;
    Buffer m_frameUniforms[VIEW_COUNT];
    Buffer m_waterUniforms;
    VertexArray m_gridVao;
    Buffer m_gridVertices, m_gridIndices;
    int m_gridResolution = 0;
    GLsizei m_gridIndexCount = 0;
    Texture m_flatDisplacement, m_flatSlopes;  // 1×1 layers: no displacement, zero slope, J = 1
    Texture m_rippleTexture;  // R32F heights of the ripple patch, re-uploaded every frame
    Texture m_rippleSlopeTexture;  // RG32F central differences of the heights, one cell of margin, every frame
    std::vector<glm::vec2> m_rippleSlopes;  // their texels, (cells + 2)² row-major
    int m_rippleCells = 0;
    WaterVariant m_waterVariant;  // this frame's (uploadWaterUniforms)
    std::map<std::string, Program> m_waterPrograms;  // by WaterVariant::defines(), compiled on first use
    Texture m_skyCube;        // RGBA16F cube map of the sky's radiance
    Framebuffer m_skyBakeFramebuffer;
    glm::vec3 m_bakedSun{0.0f};
    Texture m_detailMap;      // DU/DV (rg, as 0.5 + 0.5·x) and foam streaks (b), RGBA8, tileable, mipmapped
    Texture m_foamPattern;    // the persistent foam's bubble pattern over its repeat, baked from the detail map
    Sampler m_nearestMipSampler;  // bilinear in the nearest mip, repeated: the slopes, detail map and foam pattern on a software rasteriser
    void bakeDetailMaps();    // out: m_detailMap, m_foamPattern
    Texture m_foamTexture;    // R32F foam coverage of the foam map, re-uploaded every frame
    int m_foamCells = 0;
    Program m_splashProgram, m_splashMirrorProgram;
    VertexArray m_splashVao;
    Buffer m_splashBuffer;    // this frame's drops, (centre, radius) per instance
    size_t m_splashCapacity = 0;  // drops the buffer holds
    GLsizei m_splashCount = 0;    // drops uploaded this frame
    RenderTarget m_reflection, m_refraction;
    RenderTarget m_internal;      // the frame (RGBA8, display-encoded) when it is not drawn into the framebuffer directly
    RenderTarget m_multisampled;  // msaa4: the frame's 4 samples a pixel, resolved into m_internal
    RenderTarget m_antialiased;   // fxaa below scale 1 (or a framebuffer without depth): the frame anti-aliased, then scaled up (or copied)
    RenderTarget m_rttMultisampled;  // msaa4: reflection, then refraction, resolved into each
    bool m_underwater = false;
    Antialias m_antialias = Antialias::Off;  // this frame's mode
    bool m_msaaSupported = false;           // the driver multisamples float colour and depth textures 4×
    bool m_framebufferDepth = false;        // the default framebuffer has a depth buffer (FXAA draws into it at full size)
    std::vector<GpuTimer> m_passTimers;
};

/// Reads the default framebuffer (size px) and writes it as an RGB PNG, top row first.
/// Writes to a temporary file and renames it, so a failed write leaves nothing behind.
/// Throws ob::InputError when the path cannot be written.
void writeScreenshot(const std::string& path, glm::ivec2 size);

} // namespace ob::gfx
