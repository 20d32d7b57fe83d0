// The renderer: a short list of passes over the default framebuffer.
//   sky   → background: analytic daylight sky and sun disk
//   water → the sea surface (flat, lightly animated until the ocean layers land)
#pragma once
#include "gfx/gpu_timer.h"
#include "gfx/handles.h"
#include "gfx/render_def.h"

#include <glm/mat4x4.hpp>
#include <string>

namespace ob::gfx {

/// What the camera sees from where: the render phase fills this from the camera entity.
struct CameraView {
    glm::vec3 position{0.0f};   ///< eye (world m)
    glm::mat4 view{1.0f};       ///< world → eye
    glm::mat4 projection{1.0f}; ///< eye → clip
};

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
    void render(const CameraView& camera, double time, glm::ivec2 size);
    /// GPU ms of the latest resolved frame (negative until one resolves).
    double takeGpuMs() { return m_gpuTimer.takeResultMs(); }
    RenderDef& def() { return m_def; }

private:
    void skyPass();    // in: frame uniforms; out: colour, depth = far
    void waterPass();  // in: frame uniforms; out: colour, depth of the sea plane

    RenderDef m_def;
    Program m_skyProgram;
    Program m_waterProgram;
    VertexArray m_emptyVao;
    Buffer m_frameUniforms;
    GpuTimer m_gpuTimer{"render"};
};

/// Reads the default framebuffer (size px) and writes it as an RGB PNG, top row first.
/// Writes to a temporary file and renames it, so a failed write leaves nothing behind.
/// Throws ob::InputError when the path cannot be written.
void writeScreenshot(const std::string& path, glm::ivec2 size);

} // namespace ob::gfx
