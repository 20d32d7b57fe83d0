// Built-in meshes.
#include "gfx/mesh.h"
#include "gfx/gpu_bindings.h"

#include "assets/model.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <utility>
#include <vector>

namespace ob::gfx {

// `interleaved` holds position, normal, colour per vertex.
static Mesh upload(const char* label, const std::vector<glm::vec3>& interleaved, const std::vector<uint32_t>& indices) {
    Mesh m;
    m.vertices = createBuffer(label, GLsizeiptr(interleaved.size() * sizeof(glm::vec3)), interleaved.data());
    m.indices = createBuffer(label, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data());
    m.indexCount = GLsizei(indices.size());
    for (size_t i = 0; i < interleaved.size(); i += 3) m.radius = std::max(m.radius, glm::length(interleaved[i]));
    m.vao = createVertexArray(label);
    GLuint vao = m.vao.id();
    glVertexArrayVertexBuffer(vao, 0, m.vertices.id(), 0, 3 * sizeof(glm::vec3));
    glVertexArrayElementBuffer(vao, m.indices.id());
    // position, normal, colour: consecutive attributes from MESH_POSITION_ATTRIB (shaders/common_bindings.glsl)
    static_assert(glsl::MESH_NORMAL_ATTRIB == glsl::MESH_POSITION_ATTRIB + 1 && glsl::MESH_COLOR_ATTRIB == glsl::MESH_POSITION_ATTRIB + 2);
    for (GLuint i = 0; i < 3; ++i) {
        const GLuint a = GLuint(glsl::MESH_POSITION_ATTRIB) + i;
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, i * sizeof(glm::vec3));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    return m;
}

Mesh makeSphereMesh(int rings) {
    const int segments = 2 * rings;
    std::vector<glm::vec3> v;
    std::vector<uint32_t> idx;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            float theta = float(M_PI) * float(r) / float(rings), phi = 2.0f * float(M_PI) * float(s) / float(segments);
            glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            v.insert(v.end(), {p, p, glm::vec3(1.0f)});
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            uint32_t a = uint32_t(r * (segments + 1) + s), b = a + 1, c = a + uint32_t(segments + 1), d = c + 1;
            idx.insert(idx.end(), {a, b, c, b, d, c});  // counter-clockwise seen from outside
        }
    return upload("sphere mesh", v, idx);
}

Mesh makeRingMesh() {
    constexpr int SEGMENTS = 64, SIDES = 8;
    constexpr float TUBE = 0.04f;
    std::vector<glm::vec3> v;
    std::vector<uint32_t> idx;
    for (int s = 0; s <= SEGMENTS; ++s)
        for (int k = 0; k <= SIDES; ++k) {
            const float a = 2.0f * float(M_PI) * float(s) / float(SEGMENTS), b = 2.0f * float(M_PI) * float(k) / float(SIDES);
            const glm::vec3 out(std::cos(a), 0.0f, std::sin(a));
            const glm::vec3 n = std::cos(b) * out + glm::vec3(0.0f, std::sin(b), 0.0f);
            v.insert(v.end(), {out + TUBE * n, n, glm::vec3(1.0f)});
        }
    for (int s = 0; s < SEGMENTS; ++s)
        for (int k = 0; k < SIDES; ++k) {
            uint32_t a = uint32_t(s * (SIDES + 1) + k), b = a + 1, c = a + uint32_t(SIDES + 1), d = c + 1;
            idx.insert(idx.end(), {a, c, b, b, c, d});  // counter-clockwise seen from outside
        }
    return upload("ring mesh", v, idx);
}

// Each face is a grid of BOX_FACE_CELLS² quads, not one: the reflection and refraction
// passes cut and mirror objects at the wavy surface vertex by vertex.
constexpr int BOX_FACE_CELLS = 4;

Mesh makeBoxMesh() {
    std::vector<glm::vec3> v;
    std::vector<uint32_t> idx;
    const int n = BOX_FACE_CELLS;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 normal(0.0f);
            normal[axis] = sign;
            glm::vec3 u(0.0f), w(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            w[(axis + 2) % 3] = 1.0f;
            if (sign < 0) std::swap(u, w);  // keep counter-clockwise seen from outside
            const uint32_t base = uint32_t(v.size() / 3);
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    const float a = 2.0f * float(i) / float(n) - 1.0f, b = 2.0f * float(j) / float(n) - 1.0f;
                    v.insert(v.end(), {normal + a * u + b * w, normal, glm::vec3(1.0f)});
                }
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const uint32_t c = base + uint32_t(j * (n + 1) + i), d = c + uint32_t(n + 1);
                    idx.insert(idx.end(), {c, c + 1, d + 1, c, d + 1, d});
                }
        }
    return upload("box mesh", v, idx);
}

Mesh makeMesh(const std::string& label, const assets::ModelData& model) {
    std::vector<glm::vec3> v;
    v.reserve(model.positions.size() * 3);
    for (size_t i = 0; i < model.positions.size(); ++i) v.insert(v.end(), {model.positions[i], model.normals[i], model.colors[i]});
    return upload(label.c_str(), v, model.indices);
}

} // namespace ob::gfx
