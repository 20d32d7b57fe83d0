// Meshes as labelled GL buffers: the built-in unit sphere and box, and glTF models.
#pragma once
#include "gfx/handles.h"

#include <string>

namespace ob::assets {
struct ModelData;
}

namespace ob::gfx {

/// An indexed triangle mesh; attributes 0 position, 1 normal, 2 base colour (vec3 each, interleaved).
struct Mesh {
    VertexArray vao;
    Buffer vertices, indices;
    GLsizei indexCount = 0;
    float radius = 0.0f;  ///< bounding radius about the mesh's origin (mesh units)
};

/// A sphere of radius 1 (latitude/longitude, `rings` × 2·`rings` quads).
Mesh makeSphereMesh(int rings);
/// A ring in the xz plane: a torus of radius 1 about +y whose tube is 0.04 thick.
Mesh makeRingMesh();
/// A box from −1 to 1 on each axis (flat-shaded faces).
Mesh makeBoxMesh();
/// A model's triangles (labelled with its file name).
Mesh makeMesh(const std::string& label, const assets::ModelData& model);

} // namespace ob::gfx
