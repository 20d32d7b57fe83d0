// The renderer: a short list of passes over the default framebuffer.
//   opaque → objects (built-in meshes) lit by the sun and sky
//   water → the composite sea surface on a projected grid (Gerstner + FFT cascades + ripples)
//   sky   → background where nothing was drawn: analytic daylight sky and sun disk
#pragma once
#include "gfx/gpu_timer.h"
#include "gfx/handles.h"
#include "gfx/mesh.h"
#include "gfx/render_def.h"

#include <array>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

namespace ob::gfx {

/// What the camera sees from where: the render phase fills this from the camera entity.
struct CameraView {
    glm::vec3 position{0.0f};   ///< eye (world m)
    glm::mat4 view{1.0f};       ///< world → eye
    glm::mat4 projection{1.0f}; ///< eye → clip
    float farM = 20000.0f;      ///< far clip distance (m)
};

/// The water layers the surface pass draws (everything optional: absent layers are flat).
struct WaterView {
    const Texture* displacement = nullptr;  ///< 2D array, layer per cascade: (Dx, h, Dz, J)
    const Texture* slopes = nullptr;        ///< 2D array, layer per cascade: (dh/dx, dh/dz, 0, 0)
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
};

/// The built-in shapes an object can be drawn as.
enum class MeshKind : uint8_t { Sphere, Box };

/// One opaque object to draw this frame.
struct ObjectDraw {
    MeshKind mesh = MeshKind::Sphere;
    glm::mat4 model{1.0f};          ///< unit mesh → world (scale, rotation, position)
    glm::vec3 color{0.8f};          ///< base colour (linear RGB)
    std::string modelFile;          ///< glTF file drawn instead of `mesh` ("" = built-in)
};

/// std140 mirror of `WaterUniforms` in shaders/common_water.glsl.
struct WaterUniforms {
    glm::vec4 corner[4];
    glm::vec4 cascadeSize;
    glm::vec4 waterParams;   ///< λ, gravity, Gerstner wave count, minimum |w|
    glm::vec4 gridParams;    ///< grid resolution, max distance (m), cascades, FFT N
    glm::vec4 rippleParams;  ///< origin x, origin z (m), cell size (m), cells per side (0: none)
    glm::vec4 gerstner[32];
};
static_assert(sizeof(WaterUniforms) == 16 * (4 + 4 + 32), "WaterUniforms must match std140 layout");
constexpr int MAX_GERSTNER_WAVES = 32;

/// std140 mirror of `FrameUniforms` in shaders/common_frame.glsl.
struct FrameUniforms {
    glm::mat4 viewProjection;
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraPositionTime;   ///< xyz eye (m), w simulated time (s)
    glm::vec4 sunDirectionFresnel;  ///< xyz toward the sun (unit), w 0 = Schlick, 1 = exact
    glm::vec4 waterColorExposure;   ///< rgb deep water colour, w exposure
    glm::vec4 viewport;             ///< xy framebuffer size (px)
};
static_assert(sizeof(FrameUniforms) == 2 * 64 + 4 * 16, "FrameUniforms must match std140 layout");

/// Owns the programs and buffers of every pass.
class Renderer {
public:
    explicit Renderer(const RenderDef& def);
    /// Draws one frame of the scene into the default framebuffer of `size`.
    void render(const CameraView& camera, const WaterView& water, const std::vector<ObjectDraw>& objects, double time,
                glm::ivec2 size);
    /// GPU ms of the latest resolved frame (negative until one resolves).
    double takeGpuMs() { return m_gpuTimer.takeResultMs(); }
    RenderDef& def() { return m_def; }

private:
    void skyPass();    // in: frame uniforms, depth; out: colour where nothing was drawn
    void opaquePass(const std::vector<ObjectDraw>& objects);  // in: frame uniforms, objects; out: colour, depth
    void waterPass(const CameraView& camera, const WaterView& water);  // in: frame uniforms, water layers; out: colour, depth
    void buildGrid(int resolution);

    RenderDef m_def;
    Program m_skyProgram;
    Program m_waterProgram;
    Program m_objectProgram;
    Mesh m_sphereMesh, m_boxMesh;
    VertexArray m_emptyVao;
    Buffer m_frameUniforms;
    Buffer m_waterUniforms;
    VertexArray m_gridVao;
    Buffer m_gridVertices, m_gridIndices;
    int m_gridResolution = 0;
    GLsizei m_gridIndexCount = 0;
    Texture m_flatMaps;  // 1×1 layer: no displacement, J = 1, zero slope
    Texture m_rippleTexture;  // R32F heights of the ripple patch, re-uploaded every frame
    int m_rippleCells = 0;
    GpuTimer m_gpuTimer{"render"};
};

/// Reads the default framebuffer (size px) and writes it as an RGB PNG, top row first.
/// Writes to a temporary file and renames it, so a failed write leaves nothing behind.
/// Throws ob::InputError when the path cannot be written.
void writeScreenshot(const std::string& path, glm::ivec2 size);

} // namespace ob::gfx
