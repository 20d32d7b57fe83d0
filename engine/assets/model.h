// glTF 2.0 models as plain CPU data: the meshes objects are drawn with.
#pragma once
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ob::assets {

/// One model flattened to a single indexed triangle list in the model's frame (node
/// transforms applied, every primitive appended). Units are the file's (glTF: metres, y up).
struct ModelData {
    std::vector<glm::vec3> positions;  ///< m
    std::vector<glm::vec3> normals;    ///< unit, one per position
    std::vector<glm::vec3> colors;     ///< base colour per vertex (material baseColorFactor × vertex colour), linear RGB
    std::vector<uint32_t> indices;     ///< triangles, 3 per face, each < positions.size()
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  ///< axis-aligned bounds of the positions, m
};

/// Loads a .gltf (JSON + external or embedded buffers) or .glb file.
/// Throws ob::InputError "<path>: <what is wrong>" for a missing, unreadable or corrupt file
/// or one with no triangle mesh.
ModelData loadGltfModel(const std::string& path);

/// As loadGltfModel, from the bytes of a .gltf or .glb (told apart by the "glTF" magic);
/// `sourceName` names it in messages, external buffers are looked for in `baseDir`.
ModelData parseGltfModel(const std::vector<unsigned char>& bytes, const std::string& sourceName,
                         const std::string& baseDir = "");

} // namespace ob::assets
