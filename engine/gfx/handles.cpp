// Labelled GL object creation (DSA).
#include "gfx/handles.h"

namespace ob::gfx {

Buffer createBuffer(const char* label, GLsizeiptr size, const void* data) {
    GLuint id;
    glCreateBuffers(1, &id);
    glNamedBufferStorage(id, size, data, GL_DYNAMIC_STORAGE_BIT);
    glObjectLabel(GL_BUFFER, id, -1, label);
    return Buffer(id);
}

VertexArray createVertexArray(const char* label) {
    GLuint id;
    glCreateVertexArrays(1, &id);
    glObjectLabel(GL_VERTEX_ARRAY, id, -1, label);
    return VertexArray(id);
}

} // namespace ob::gfx
