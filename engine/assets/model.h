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
/// Throws ob::InputError "<path>: <what is wrong>" for a missing, unreadable or corrupt file,
/// one that is not a regular file (a named pipe, device, folder), one with no triangle mesh,
/// a glTF version other than 2.x (GLB container version other than 2), a required extension
/// (`extensionsRequired`), or an external file (buffer uri) that is not a regular file in the
/// model's folder or below (after percent-decoding and symlinks).
ModelData loadGltfModel(const std::string& path);

/// As loadGltfModel, from the bytes of a .gltf or .glb (told apart by the "glTF" magic);
/// `sourceName` names it in messages, external buffers are looked for in `baseDir` (the
/// current folder when empty) and below, never elsewhere.
ModelData parseGltfModel(const std::vector<unsigned char>& bytes, const std::string& sourceName,
                         const std::string& baseDir = "");

/// One of the project's own models (`oceanbox make-models`): assets/models/<stem>.gltf of the
/// source tree, absolute; "" when it is not there (the object falls back to a built-in mesh).
std::string projectModel(const std::string& stem);

/// The far twin of a model drawn at a distance: X.lod1.gltf beside X.gltf (X.lod1.glb beside X.glb).
std::string lodTwinPath(const std::string& file);

} // namespace ob::assets
