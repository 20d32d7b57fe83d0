// glTF 2.0 loader: tinygltf parses the file; every index and byte range is checked here
// before it is read, then the default scene's triangles are flattened into one list
// (glTF 2.0 specification §3.5 scenes and nodes, §3.6 accessors, §3.7 meshes).
#include "assets/model.h"

#include "assets/gltf_library.h"
#include "core/error.h"
#include "core/file_read.h"

#include <cmath>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace ob::assets {

namespace {

// A problem with the file's content; loadGltfModel puts the path in front.
struct Corrupt : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr size_t MAX_FILE_BYTES = size_t(1) << 30;     // tinygltf takes 32-bit lengths
constexpr size_t MAX_ELEMENTS = size_t(1) << 22;       // per accessor: far beyond any model here
constexpr size_t MAX_VERTICES = size_t(1) << 26;       // in the flattened model

std::string numText(size_t v) { return std::to_string(v); }

size_t componentBytes(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

// Components per element of the vector types this loader reads; 0 for matrices and unknowns.
int vectorWidth(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
    }
}

// One component as a double; normalized integers map to [0, 1] or [-1, 1] (spec §3.11).
double component(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

// The bytes of `count` elements of `elementBytes` each, `offset` bytes into buffer view
// `viewIndex`, spaced by the view's byteStride (or packed). Every byte is checked to lie in
// the view and the view in its buffer; returns the first element and sets `stride`.
const unsigned char* viewElements(const tinygltf::Model& m, int viewIndex, size_t offset, size_t count,
                                  size_t elementBytes, bool packed, size_t& stride, const std::string& what) {
    if (viewIndex < 0 || size_t(viewIndex) >= m.bufferViews.size())
        throw Corrupt(what + ": bufferView " + std::to_string(viewIndex) + " does not exist");
    const tinygltf::BufferView& view = m.bufferViews[size_t(viewIndex)];
    const std::string viewName = "bufferView " + std::to_string(viewIndex);
    if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size())
        throw Corrupt(viewName + ": buffer " + std::to_string(view.buffer) + " does not exist");
    const std::vector<unsigned char>& data = m.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw Corrupt(viewName + ": bytes [" + numText(view.byteOffset) + ", +" + numText(view.byteLength) +
                      ") lie outside its buffer of " + numText(data.size()) + " bytes");
    stride = packed || view.byteStride == 0 ? elementBytes : view.byteStride;
    if (stride < elementBytes)
        throw Corrupt(viewName + ": byteStride " + numText(stride) + " is smaller than one element (" +
                      numText(elementBytes) + " bytes)");
    if (count == 0) return nullptr;
    const size_t length = view.byteLength;
    if (offset > length || elementBytes > length - offset || count - 1 > (length - offset - elementBytes) / stride)
        throw Corrupt(what + ": " + numText(count) + " elements of " + numText(elementBytes) + " bytes at offset " +
                      numText(offset) + " do not fit in " + viewName + " (" + numText(length) + " bytes)");
    return data.data() + view.byteOffset + offset;
}

// An accessor's elements as doubles, `width` components each, integers converted (sparse
// substitution applied; an accessor without a buffer view starts as zeros).
struct Values {
    std::vector<double> v;
    size_t count = 0;
    int width = 0;
};

Values readAccessor(const tinygltf::Model& m, int index, bool allowUint32, const std::string& what) {
    if (index < 0 || size_t(index) >= m.accessors.size())
        throw Corrupt(what + ": accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    const std::string name = what + " (accessor " + std::to_string(index) + ")";
    Values out;
    out.width = vectorWidth(a.type);
    const size_t bytes = componentBytes(a.componentType);
    if (out.width == 0) throw Corrupt(name + ": type must be SCALAR or VEC2/3/4");
    if (bytes == 0) throw Corrupt(name + ": unknown componentType " + std::to_string(a.componentType));
    if (!allowUint32 && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw Corrupt(name + ": componentType must be FLOAT or a (normalized) byte/short");
    if (a.count > MAX_ELEMENTS) throw Corrupt(name + ": count " + numText(a.count) + " is too large");
    out.count = a.count;
    const size_t w = size_t(out.width);
    size_t stride = 0;
    const unsigned char* p =
        a.bufferView >= 0 ? viewElements(m, a.bufferView, a.byteOffset, a.count, bytes * w, false, stride, name) : nullptr;
    out.v.assign(out.count * w, 0.0);  // after the check: the file backs every element read

    if (p) {
        for (size_t i = 0; i < a.count; ++i)
            for (size_t c = 0; c < w; ++c) out.v[i * w + c] = component(p + i * stride + c * bytes, a.componentType, a.normalized);
    }

    if (a.sparse.isSparse) {
        const size_t n = a.sparse.count < 0 ? 0 : size_t(a.sparse.count);
        if (n == 0 || n > a.count) throw Corrupt(name + ": sparse count must be in [1, count]");
        const int indexType = a.sparse.indices.componentType;
        const size_t indexBytes = componentBytes(indexType);
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            throw Corrupt(name + ": sparse indices must be unsigned byte, short or int");
        if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
            throw Corrupt(name + ": negative sparse byteOffset");
        const unsigned char* ip = viewElements(m, a.sparse.indices.bufferView, size_t(a.sparse.indices.byteOffset), n,
                                               indexBytes, true, stride, name + " sparse indices");
        const unsigned char* vp = viewElements(m, a.sparse.values.bufferView, size_t(a.sparse.values.byteOffset), n,
                                               bytes * w, true, stride, name + " sparse values");
        for (size_t k = 0; k < n; ++k) {
            const double target = component(ip + k * indexBytes, indexType, false);
            if (target >= double(a.count))
                throw Corrupt(name + ": sparse index " + numText(size_t(target)) + " >= count " + numText(a.count));
            for (size_t c = 0; c < w; ++c)
                out.v[size_t(target) * w + c] = component(vp + (k * w + c) * bytes, a.componentType, a.normalized);
        }
    }
    for (double x : out.v)
        if (!std::isfinite(x)) throw Corrupt(name + ": holds a value that is not a finite number");
    return out;
}

std::vector<glm::vec3> readVec3(const tinygltf::Model& m, int index, const std::string& what) {
    Values v = readAccessor(m, index, false, what);
    if (v.width != 3) throw Corrupt(what + " (accessor " + std::to_string(index) + "): type must be VEC3");
    std::vector<glm::vec3> out(v.count);
    for (size_t i = 0; i < v.count; ++i) out[i] = glm::vec3(v.v[3 * i], v.v[3 * i + 1], v.v[3 * i + 2]);
    return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& m, int index, const std::string& what) {
    if (index >= 0 && size_t(index) < m.accessors.size()) {
        const tinygltf::Accessor& a = m.accessors[size_t(index)];
        if (a.type != TINYGLTF_TYPE_SCALAR ||
            (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
             a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
             a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            throw Corrupt(what + " (accessor " + std::to_string(index) + "): must be SCALAR unsigned byte, short or int");
    }
    Values v = readAccessor(m, index, true, what);
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; ++i) out[i] = uint32_t(v.v[i]);
    return out;
}

void checkNumbers(const std::vector<double>& v, size_t sizeA, size_t sizeB, const std::string& what) {
    if (!v.empty() && v.size() != sizeA && v.size() != sizeB)
        throw Corrupt(what + ": expected " + numText(sizeA) + (sizeB != sizeA ? " or " + numText(sizeB) : "") + " numbers, got " +
                      numText(v.size()));
    for (double x : v)
        if (!std::isfinite(x)) throw Corrupt(what + ": holds a value that is not a finite number");
}

// A node's local transform: its matrix, else T · R · S (spec §3.5.3).
glm::mat4 localTransform(const tinygltf::Node& n, int index) {
    const std::string name = "node " + std::to_string(index);
    checkNumbers(n.matrix, 16, 16, name + " matrix");
    checkNumbers(n.translation, 3, 3, name + " translation");
    checkNumbers(n.rotation, 4, 4, name + " rotation");
    checkNumbers(n.scale, 3, 3, name + " scale");
    if (!n.matrix.empty()) {
        glm::dmat4 m = glm::make_mat4(n.matrix.data());  // both column-major
        return glm::mat4(m);
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!n.translation.empty()) t = glm::translate(glm::dmat4(1.0), glm::make_vec3(n.translation.data()));
    if (!n.rotation.empty()) {
        glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // glTF stores x, y, z, w
        if (glm::length(q) < 1e-9) throw Corrupt(name + " rotation: not a unit quaternion");
        r = glm::mat4_cast(glm::normalize(q));
    }
    if (!n.scale.empty()) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(n.scale.data()));
    return glm::mat4(t * r * s);
}

glm::vec3 unitOr(glm::vec3 v, glm::vec3 fallback) {
    float len = glm::length(v);
    return std::isfinite(len) && len > 1e-20f ? v / len : fallback;
}

// A primitive's attribute's accessor index, −1 where it has none.
int attributeOf(const tinygltf::Primitive& prim, const char* key) {
    auto it = prim.attributes.find(key);
    return it == prim.attributes.end() ? -1 : it->second;
}

// The n vertex colours: the material's base colour factor times COLOR_0 where it has one.
std::vector<glm::vec3> primitiveColors(const tinygltf::Model& m, const tinygltf::Primitive& prim, size_t n, const std::string& name) {
    glm::vec3 factor(1.0f);
    if (prim.material >= 0) {
        if (size_t(prim.material) >= m.materials.size())
            throw Corrupt(name + ": material " + std::to_string(prim.material) + " does not exist");
        const std::vector<double>& f = m.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorFactor;
        checkNumbers(f, 4, 4, "material " + std::to_string(prim.material) + " baseColorFactor");
        if (f.size() == 4) factor = glm::vec3(float(f[0]), float(f[1]), float(f[2]));
    }
    std::vector<glm::vec3> colors(n, factor);
    if (attributeOf(prim, "COLOR_0") >= 0) {
        Values c = readAccessor(m, attributeOf(prim, "COLOR_0"), false, name + " COLOR_0");
        if (c.width != 3 && c.width != 4) throw Corrupt(name + " COLOR_0: type must be VEC3 or VEC4");
        if (c.count != n) throw Corrupt(name + ": COLOR_0 has " + numText(c.count) + " elements, POSITION " + numText(n));
        const size_t w = size_t(c.width);
        for (size_t i = 0; i < n; ++i) colors[i] *= glm::vec3(c.v[i * w], c.v[i * w + 1], c.v[i * w + 2]);
    }
    return colors;
}

// The triangles' corners (indices into the n vertices; none given: 0 … n − 1).
std::vector<uint32_t> primitiveIndices(const tinygltf::Model& m, const tinygltf::Primitive& prim, size_t n, const std::string& name) {
    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
        indices = readIndices(m, prim.indices, name + " indices");
        for (size_t k = 0; k < indices.size(); ++k)
            if (indices[k] >= n)
                throw Corrupt(name + ": index " + std::to_string(indices[k]) + " (element " + numText(k) +
                              ") is out of range: the primitive has " + numText(n) + " vertices");
    } else {
        indices.resize(n);
        for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i);
    }
    if (indices.size() % 3 != 0)
        throw Corrupt(name + ": " + numText(indices.size()) + " vertices in TRIANGLES mode, not a multiple of 3");
    return indices;
}

// The positions moved into the model frame by `world`; a mirroring transform turns
// counter-clockwise faces clockwise, so their corners are swapped to keep them front.
void placePrimitive(const glm::mat4& world, std::vector<glm::vec3>& positions, std::vector<uint32_t>& indices, const std::string& name) {
    if (glm::determinant(glm::mat3(world)) < 0.0f)
        for (size_t k = 0; k < indices.size(); k += 3) std::swap(indices[k + 1], indices[k + 2]);
    for (glm::vec3& p : positions) p = glm::vec3(world * glm::vec4(p, 1.0f));
    for (const glm::vec3& p : positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Corrupt(name + ": a transformed position is not finite");
}

// No normals: flat shading, one vertex per corner (spec §3.7.2.1).
void appendFlat(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices, const std::vector<glm::vec3>& colors,
                ModelData& out) {
    const uint32_t base = uint32_t(out.positions.size());
    for (size_t k = 0; k < indices.size(); k += 3) {
        const glm::vec3 a = positions[indices[k]], b = positions[indices[k + 1]], c = positions[indices[k + 2]];
        const glm::vec3 face = unitOr(glm::cross(b - a, c - a), glm::vec3(0.0f, 1.0f, 0.0f));
        for (size_t j = 0; j < 3; ++j) {
            out.positions.push_back(positions[indices[k + j]]);
            out.normals.push_back(face);
            out.colors.push_back(colors[indices[k + j]]);
            out.indices.push_back(base + uint32_t(k + j));
        }
    }
}

// With normals: the vertices as given, their normals turned by `world`'s normal matrix.
void appendSmooth(const glm::mat4& world, const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                  const std::vector<uint32_t>& indices, const std::vector<glm::vec3>& colors, ModelData& out) {
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    const uint32_t base = uint32_t(out.positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        out.positions.push_back(positions[i]);
        out.normals.push_back(unitOr(normalMatrix * normals[i], glm::vec3(0.0f, 1.0f, 0.0f)));
        out.colors.push_back(colors[i]);
    }
    for (uint32_t k : indices) out.indices.push_back(base + k);
}

// Appends one TRIANGLES primitive, in the model frame given by `world`.
void appendPrimitive(const tinygltf::Model& m, const tinygltf::Primitive& prim, const glm::mat4& world,
                     const std::string& name, ModelData& out) {
    const int positionIndex = attributeOf(prim, "POSITION");
    if (positionIndex < 0) throw Corrupt(name + ": no POSITION attribute");
    std::vector<glm::vec3> positions = readVec3(m, positionIndex, name + " POSITION");
    const size_t n = positions.size();
    std::vector<glm::vec3> normals;
    if (attributeOf(prim, "NORMAL") >= 0) {
        normals = readVec3(m, attributeOf(prim, "NORMAL"), name + " NORMAL");
        if (normals.size() != n)
            throw Corrupt(name + ": NORMAL has " + numText(normals.size()) + " elements, POSITION " + numText(n));
    }
    const std::vector<glm::vec3> colors = primitiveColors(m, prim, n, name);
    std::vector<uint32_t> indices = primitiveIndices(m, prim, n, name);
    placePrimitive(world, positions, indices, name);

    const size_t added = normals.empty() ? indices.size() : n;
    if (out.positions.size() + added > MAX_VERTICES) throw Corrupt("more than " + numText(MAX_VERTICES) + " vertices");
    if (normals.empty()) appendFlat(positions, indices, colors, out);
    else appendSmooth(world, positions, normals, indices, colors, out);
}

// The roots to draw: the default scene's, else scene 0's, else every node no node parents.
std::vector<int> sceneRoots(const tinygltf::Model& m) {
    if (m.defaultScene >= 0 && size_t(m.defaultScene) >= m.scenes.size())
        throw Corrupt("scene " + std::to_string(m.defaultScene) + " (the default scene) does not exist");
    if (!m.scenes.empty()) return m.scenes[m.defaultScene >= 0 ? size_t(m.defaultScene) : 0].nodes;
    std::vector<char> isChild(m.nodes.size(), 0);
    for (const tinygltf::Node& node : m.nodes)
        for (int c : node.children)
            if (c >= 0 && size_t(c) < m.nodes.size()) isChild[size_t(c)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < m.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

ModelData flatten(const tinygltf::Model& m) {
    ModelData out;
    size_t skipped = 0;
    // Depth-first with an explicit stack: a deep chain of nodes must not exhaust the call stack.
    std::vector<char> visited(m.nodes.size(), 0);
    std::vector<std::pair<int, glm::mat4>> stack;
    std::vector<int> roots = sceneRoots(m);
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::mat4(1.0f)});
    while (!stack.empty()) {
        auto [index, parent] = stack.back();
        stack.pop_back();
        if (index < 0 || size_t(index) >= m.nodes.size()) throw Corrupt("node " + std::to_string(index) + " does not exist");
        if (visited[size_t(index)])
            throw Corrupt("node " + std::to_string(index) + " appears twice in the scene (the node hierarchy must be a tree)");
        visited[size_t(index)] = 1;
        const tinygltf::Node& node = m.nodes[size_t(index)];
        const glm::mat4 world = parent * localTransform(node, index);
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= m.meshes.size())
                throw Corrupt("node " + std::to_string(index) + ": mesh " + std::to_string(node.mesh) + " does not exist");
            const tinygltf::Mesh& mesh = m.meshes[size_t(node.mesh)];
            for (size_t p = 0; p < mesh.primitives.size(); ++p) {
                const tinygltf::Primitive& prim = mesh.primitives[p];
                if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
                    ++skipped;
                    continue;
                }
                appendPrimitive(m, prim, world, "mesh " + std::to_string(node.mesh) + " primitive " + numText(p), out);
            }
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.push_back({*c, world});
    }
    if (out.indices.empty())
        throw Corrupt("no triangles in the scene" +
                      (skipped ? " (" + numText(skipped) + " primitives of other modes than TRIANGLES skipped)" : std::string()));
    out.boundsMin = out.boundsMax = out.positions.front();
    for (const glm::vec3& p : out.positions) {
        out.boundsMin = glm::min(out.boundsMin, p);
        out.boundsMax = glm::max(out.boundsMax, p);
    }
    return out;
}

// tinygltf's messages, one line.
std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? "unknown error" : text;
}

// Images are not used: accept them without decoding (external images are never opened:
// TINYGLTF_NO_EXTERNAL_IMAGE, gltf_library.h).
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// Extensions a file may require (glTF 2.0 §3.12: a loader refuses a file that requires one
// it does not implement). None: the loader reads core glTF 2.0 only.
constexpr const char* SUPPORTED_REQUIRED_EXTENSIONS[] = {""};

// The file system as the model's external files see it: only regular files in the model's
// folder or below, after percent-decoding (tinygltf's) and symlink resolution (ours); no `~`
// or variable expansion. The first refusal is kept for the message.
struct ConfinedFiles {
    std::filesystem::path root;  // canonical folder of the model
    std::string problem;         // the first refusal, "" when none

    static bool exists(const std::string&, void*) { return true; }  // ReadWholeFile says why not
    static std::string expand(const std::string& path, void*) { return path; }
    static bool write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
        if (err) *err += "writing is not allowed";
        return false;
    }

    static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& joined, void* user) {
        auto* self = static_cast<ConfinedFiles*>(user);
        const std::string root = self->root.string();
        // tinygltf joins the folder and the decoded uri: the uri is what follows.
        const std::string uri = joined.rfind(root + "/", 0) == 0 ? joined.substr(root.size() + 1) : joined;
        std::string why;
        try {
            if (uri.find('\0') != std::string::npos) throw InputError("the uri holds a NUL character");
            namespace fs = std::filesystem;
            std::error_code ec;
            const fs::path target = fs::weakly_canonical(self->root / uri, ec);
            if (ec) throw InputError(ec.message());
            const auto [rootEnd, targetAt] = std::mismatch(self->root.begin(), self->root.end(), target.begin(), target.end());
            if (rootEnd != self->root.end() || targetAt == target.end())
                throw InputError("leads outside the model's folder " + root +
                                 " (a model reads only files in its own folder or below)");
            const std::string bytes = readRegularFile(target.string(), MAX_FILE_BYTES);
            out->assign(bytes.begin(), bytes.end());
            return true;
        } catch (const InputError& e) {
            why = e.what();
        } catch (const std::exception& e) {
            why = e.what();
        }
        if (self->problem.empty()) self->problem = "external file uri '" + uri + "': " + why;
        if (err) *err += why;
        return false;
    }
};

// The glTF version rules the parser leaves to us: the GLB container's version (2), the
// asset's version (2.x) and minVersion, and the extensions the file requires.
void checkVersions(const std::vector<unsigned char>& bytes, bool binary, const tinygltf::Model& m) {
    if (binary) {
        uint32_t version = 0;
        if (bytes.size() >= 8) std::memcpy(&version, bytes.data() + 4, 4);
        if (version != 2) throw Corrupt("GLB container version " + std::to_string(version) + " (only version 2 is read)");
    }
    if (m.asset.version.rfind("2.", 0) != 0)
        throw Corrupt("asset.version \"" + m.asset.version + "\" is not 2.x (oceanbox reads glTF 2.0)");
    if (!m.asset.minVersion.empty() && m.asset.minVersion != "2.0")
        throw Corrupt("asset.minVersion \"" + m.asset.minVersion + "\" is newer than glTF 2.0");
    for (const std::string& extension : m.extensionsRequired) {
        bool supported = false;
        for (const char* known : SUPPORTED_REQUIRED_EXTENSIONS) supported = supported || (*known && extension == known);
        if (!supported)
            throw Corrupt("requires the extension \"" + extension +
                          "\", which oceanbox does not implement (extensionsRequired: a loader must refuse the file)");
    }
}

} // namespace

std::string projectModel(const std::string& stem) {
    const std::filesystem::path file = std::filesystem::path(OCEANBOX_SOURCE_DIR) / "assets" / "models" / (stem + ".gltf");
    std::error_code ec;
    return std::filesystem::is_regular_file(file, ec) ? file.string() : "";
}

std::string lodTwinPath(const std::string& file) {
    std::filesystem::path far(file);
    far.replace_extension(".lod1" + far.extension().string());
    return far.string();
}

ModelData loadGltfModel(const std::string& path) {
    // A regular file only (a named pipe would block, a device read forever).
    const std::string text = readRegularFile(path, MAX_FILE_BYTES);
    const std::vector<unsigned char> bytes(text.begin(), text.end());
    return parseGltfModel(bytes, path, std::filesystem::path(path).parent_path().string());
}

ModelData parseGltfModel(const std::vector<unsigned char>& bytes, const std::string& path, const std::string& baseDir) {
    if (bytes.empty()) throw InputError(path + ": the file is empty");
    if (bytes.size() > MAX_FILE_BYTES) throw InputError(path + ": larger than 1 GiB");
    ConfinedFiles files;
    {
        std::error_code ec;
        files.root = std::filesystem::weakly_canonical(std::filesystem::absolute(baseDir.empty() ? "." : baseDir, ec), ec);
        if (ec) throw InputError(path + ": cannot resolve the model's folder '" + baseDir + "': " + ec.message());
    }
    tinygltf::TinyGLTF gltf;
    gltf.SetImageLoader(&ignoreImage, nullptr);
    gltf.SetFsCallbacks({&ConfinedFiles::exists, &ConfinedFiles::expand, &ConfinedFiles::read, &ConfinedFiles::write, &files});
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    bool ok = false;
    try {
        ok = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), files.root.string())
                    : gltf.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                               unsigned(bytes.size()), files.root.string());
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (!files.problem.empty()) throw InputError(path + ": " + oneLine(files.problem));
    if (!ok) throw InputError(path + ": not a valid glTF 2.0 " + (binary ? "binary (.glb)" : "file") + ": " + oneLine(err));
    try {
        checkVersions(bytes, binary, model);
        return flatten(model);
    } catch (const Corrupt& e) {
        throw InputError(path + ": " + e.what());
    } catch (const std::bad_alloc&) {
        throw InputError(path + ": too large to load");
    }
}

} // namespace ob::assets
