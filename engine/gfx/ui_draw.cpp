// The headless overlay's renderer (gfx/ui_draw.h).
#include "gfx/ui_draw.h"

#include "gfx/shader.h"

#include <cstddef>
#include <imgui.h>

namespace ob::gfx {

namespace {
constexpr GLuint VERTEX_BINDING = 0;
constexpr GLint SIZE_LOCATION = 0;   // ui_overlay.vert's u_size
constexpr GLuint ATLAS_UNIT = 0;     // ui_overlay.frag's u_atlas
} // namespace

UiDraw::UiDraw() : m_program(loadProgram("ui overlay", {"ui_overlay.vert", "ui_overlay.frag"})), m_vao(createVertexArray("ui overlay")) {
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    GLuint atlas = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &atlas);
    m_atlas = Texture(atlas);
    glObjectLabel(GL_TEXTURE, atlas, -1, "ui font atlas");
    glTextureStorage2D(atlas, 1, GL_RGBA8, w, h);
    glTextureSubImage2D(atlas, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTextureParameteri(atlas, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(atlas, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(atlas)));
    const GLuint vao = m_vao.id();
    glVertexArrayAttribFormat(vao, 0, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, pos));
    glVertexArrayAttribFormat(vao, 1, 2, GL_FLOAT, GL_FALSE, offsetof(ImDrawVert, uv));
    glVertexArrayAttribFormat(vao, 2, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(ImDrawVert, col));
    for (GLuint a = 0; a < 3; ++a) {
        glVertexArrayAttribBinding(vao, a, VERTEX_BINDING);
        glEnableVertexArrayAttrib(vao, a);
    }
}

void UiDraw::draw(const ImDrawData& data, glm::ivec2 size) {
    if (data.CmdListsCount == 0 || size.x <= 0 || size.y <= 0) return;
    glViewport(0, 0, size.x, size.y);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glUseProgram(m_program.id());
    glProgramUniform2f(m_program.id(), SIZE_LOCATION, float(size.x), float(size.y));
    glBindVertexArray(m_vao.id());
    glBindTextureUnit(ATLAS_UNIT, m_atlas.id());
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList* list = data.CmdLists[n];
        if (list->VtxBuffer.Size == 0 || list->IdxBuffer.Size == 0) continue;
        // Streamed: a buffer per list and frame (the overlay is a few thousand vertices).
        const Buffer vertices = createBuffer("ui vertices", GLsizeiptr(list->VtxBuffer.Size * sizeof(ImDrawVert)), list->VtxBuffer.Data);
        const Buffer indices = createBuffer("ui indices", GLsizeiptr(list->IdxBuffer.Size * sizeof(ImDrawIdx)), list->IdxBuffer.Data);
        glVertexArrayVertexBuffer(m_vao.id(), VERTEX_BINDING, vertices.id(), 0, sizeof(ImDrawVert));
        glVertexArrayElementBuffer(m_vao.id(), indices.id());
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) continue;
            const ImVec2 o = data.DisplayPos;
            const int x0 = int(cmd.ClipRect.x - o.x), y0 = int(cmd.ClipRect.y - o.y);
            const int x1 = int(cmd.ClipRect.z - o.x), y1 = int(cmd.ClipRect.w - o.y);
            if (x1 <= x0 || y1 <= y0) continue;
            glScissor(x0, size.y - y1, x1 - x0, y1 - y0);
            glDrawElementsBaseVertex(GL_TRIANGLES, GLsizei(cmd.ElemCount), sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                                     reinterpret_cast<const void*>(cmd.IdxOffset * sizeof(ImDrawIdx)), GLint(cmd.VtxOffset));
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
}

} // namespace ob::gfx
