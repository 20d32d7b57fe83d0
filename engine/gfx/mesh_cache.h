// The meshes objects are drawn with: the built-in shapes and glTF models loaded on first use,
// each model with its far twin (X.lod1.gltf) when one lies beside it.
#pragma once
#include "gfx/mesh.h"
#include "view_data/scene_view.h"

#include <map>
#include <optional>
#include <string>

namespace ob::gfx {

/// The bounding radius of an object's mesh in the world (m): the mesh's, scaled by the largest
/// axis scale of its model matrix.
float boundingRadius(const ObjectDraw& object, const Mesh& mesh);

/// Built-in meshes and glTF models by file, kept for the renderer's life.
class MeshCache {
public:
    MeshCache();
    /// The mesh to draw `object` with in a view that spans `pixelsPerRadian` at its centre, seen
    /// from `eye` (m): a model's far twin where the object's bounding sphere spans fewer than
    /// LOD_RADIUS_PX pixels of radius.
    const Mesh& meshFor(const ObjectDraw& object, glm::vec3 eye, float pixelsPerRadian);

private:
    // A glTF model's mesh and its far twin, if one lies beside it.
    struct ModelMeshes {
        Mesh near;
        std::optional<Mesh> far;
    };
    const ModelMeshes& meshesFor(const std::string& file);

    Mesh m_sphere, m_box, m_ring;
    std::map<std::string, ModelMeshes> m_models;  // by file, loaded on first draw
};

} // namespace ob::gfx
