// `oceanbox make-models`: the procedural models of model_shapes.cpp written through tinygltf.
#include "tools/cmd_make_models.h"

#include "core/file_write.h"
#include "assets/gltf_library.h"
#include "core/error.h"
#include "core/log.h"
#include "tools/model_shapes.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <sstream>

namespace ob::game {

namespace {

// Appends `bytes` to the buffer at a 4-byte boundary and adds a buffer view over them.
template <class T>
int addView(tinygltf::Model& m, const std::vector<T>& values, int target) {
    std::vector<unsigned char>& data = m.buffers[0].data;
    data.resize((data.size() + 3) & ~size_t(3), 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    const size_t at = data.size();
    data.resize(at + view.byteLength);
    std::memcpy(data.data() + at, values.data(), view.byteLength);
    m.bufferViews.push_back(view);
    return int(m.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& m, int view, int componentType, int type, size_t count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    m.accessors.push_back(a);
    return int(m.accessors.size() - 1);
}

// A float factor as the nearest 4-decimal double, so the JSON reads 0.3 and not 0.30000001.
double decimal(float v) { return std::round(double(v) * 1e4) / 1e4; }

} // namespace

std::string gltfText(const ShapeModel& model) {
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = "oceanbox make-models";
    m.buffers.emplace_back();
    tinygltf::Mesh mesh;
    mesh.name = model.name;
    for (const ShapePart& part : model.parts) {
        tinygltf::Material material;
        material.name = part.name;
        material.pbrMetallicRoughness.baseColorFactor = {decimal(part.color.x), decimal(part.color.y), decimal(part.color.z), 1.0};
        material.pbrMetallicRoughness.metallicFactor = decimal(part.metallic);
        material.pbrMetallicRoughness.roughnessFactor = decimal(part.roughness);
        m.materials.push_back(material);

        tinygltf::Primitive prim;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        prim.material = int(m.materials.size() - 1);
        const size_t n = part.positions.size();
        const int position = addAccessor(m, addView(m, part.positions, TINYGLTF_TARGET_ARRAY_BUFFER),
                                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
        glm::vec3 lo = part.positions.front(), hi = lo;
        for (const glm::vec3& p : part.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        m.accessors[size_t(position)].minValues = {lo.x, lo.y, lo.z};  // required for POSITION
        m.accessors[size_t(position)].maxValues = {hi.x, hi.y, hi.z};
        prim.attributes["POSITION"] = position;
        prim.attributes["NORMAL"] = addAccessor(m, addView(m, part.normals, TINYGLTF_TARGET_ARRAY_BUFFER),
                                                TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
        if (n <= 65536) {
            std::vector<uint16_t> small(part.indices.begin(), part.indices.end());
            prim.indices = addAccessor(m, addView(m, small, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, small.size());
        } else {
            prim.indices = addAccessor(m, addView(m, part.indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, part.indices.size());
        }
        mesh.primitives.push_back(prim);
    }
    m.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = model.name;
    node.mesh = 0;
    m.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    m.scenes.push_back(scene);
    m.defaultScene = 0;

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&m, out, true, false)) throw RuntimeError(model.name + ": glTF serialisation failed");
    return out.str();
}

int makeModels(const std::string& outDir) {
    namespace fs = std::filesystem;
    // The folder itself is made, never its parents: a mistyped path fails instead of growing
    // a tree of folders somewhere.
    const fs::path parent = fs::path(outDir).parent_path().empty() ? fs::path(".") : fs::path(outDir).parent_path();
    std::error_code ec;
    if (!fs::is_directory(outDir, ec)) {
        if (!fs::is_directory(parent, ec))
            throw InputError("--out '" + outDir + "': folder '" + parent.string() +
                             "' does not exist (create it, or choose another path; make-models makes only the last folder)");
        fs::create_directory(outDir, ec);
        if (!fs::is_directory(outDir, ec))
            throw InputError("--out '" + outDir + "': cannot create the folder" + (ec ? " (" + ec.message() + ")" : std::string()));
    }
    const std::vector<ShapeModel> models = buildProjectModels();
    for (const ShapeModel& model : models) checkWritable((fs::path(outDir) / (model.name + ".gltf")).string(), "model");
    for (const ShapeModel& model : models) {
        const std::string path = (fs::path(outDir) / (model.name + ".gltf")).string();
        const std::string text = gltfText(model);
        writeTextFile(path, text, "model");
        size_t triangles = 0;
        for (const ShapePart& part : model.parts) triangles += part.indices.size() / 3;
        logInfo("%s: %zu parts, %zu triangles", path.c_str(), model.parts.size(), triangles);
    }
    return EXIT_OK;
}

} // namespace ob::game
