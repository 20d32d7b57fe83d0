// Built-in meshes, glTF models on first use, and the far twin's choice per view.
#include "gfx/mesh_cache.h"

#include "assets/model.h"

#include <algorithm>
#include <filesystem>
#include <glm/glm.hpp>
#include <utility>

namespace ob::gfx {

namespace {
// A model's far twin (X.lod1.gltf) is drawn where the object's bounding sphere spans fewer
// than this many pixels of radius: the default scene's fish (0.4 m) 20 m away span 12 px at
// 720 rows (whole) and 3 px at scale 0.25 (the twin, a tenth of the triangles).
constexpr float LOD_RADIUS_PX = 8.0f;
} // namespace

float boundingRadius(const ObjectDraw& o, const Mesh& mesh) {
    return mesh.radius * std::max({glm::length(glm::vec3(o.model[0])), glm::length(glm::vec3(o.model[1])), glm::length(glm::vec3(o.model[2]))});
}

MeshCache::MeshCache() : m_sphere(makeSphereMesh(16)), m_box(makeBoxMesh()), m_ring(makeRingMesh()) {}

// The model X.gltf (X.glb) and its far twin X.lod1.gltf (X.lod1.glb) beside it, if there is
// one: loaded on first use.
const MeshCache::ModelMeshes& MeshCache::meshesFor(const std::string& file) {
    auto it = m_models.find(file);
    if (it == m_models.end()) {
        ModelMeshes meshes{makeMesh(file, assets::loadGltfModel(file)), std::nullopt};
        const std::string far = assets::lodTwinPath(file);  // checked with the scene (world/scene.cpp)
        if (std::filesystem::exists(far)) meshes.far = makeMesh(far, assets::loadGltfModel(far));
        it = m_models.emplace(file, std::move(meshes)).first;
    }
    return it->second;
}

const Mesh& MeshCache::meshFor(const ObjectDraw& object, glm::vec3 eye, float pixelsPerRadian) {
    if (object.modelFile.empty())
        switch (object.mesh) {
        case MeshKind::Sphere: return m_sphere;
        case MeshKind::Box: return m_box;
        case MeshKind::Ring: return m_ring;
        }
    const ModelMeshes& meshes = meshesFor(object.modelFile);
    if (!meshes.far) return meshes.near;
    const float distance = std::max(glm::length(glm::vec3(object.model[3]) - eye), 1e-3f);
    const float pixels = boundingRadius(object, meshes.near) / distance * pixelsPerRadian;
    return pixels < LOD_RADIUS_PX ? *meshes.far : meshes.near;
}

} // namespace ob::gfx
