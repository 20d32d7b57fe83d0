// Draws Dear ImGui's draw data with the engine's own GL 4.5 objects: the overlay of a headless
// context (OSMesa), where ImGui's OpenGL 3 backend cannot load its functions.
#pragma once
#include "gfx/handles.h"

#include <glm/vec2.hpp>

struct ImDrawData;

namespace ob::gfx {

/// The overlay's renderer: the font atlas as a texture, the draw lists streamed each frame.
class UiDraw {
public:
    /// Uploads the current ImGui context's font atlas (call once its fonts are built).
    UiDraw();
    /// Draws `data` over the bound framebuffer of `size` px (blended, scissored, no depth).
    void draw(const ImDrawData& data, glm::ivec2 size);

private:
    Program m_program;
    Texture m_atlas;
    VertexArray m_vao;
};

} // namespace ob::gfx
