// Built-in meshes (unit sphere, unit box) as labelled GL buffers: position + normal.
#pragma once
#include "gfx/handles.h"

namespace ob::gfx {

/// An indexed triangle mesh; attribute 0 position, 1 normal (vec3 each, interleaved).
struct Mesh {
    VertexArray vao;
    Buffer vertices, indices;
    GLsizei indexCount = 0;
};

/// A sphere of radius 1 (latitude/longitude, `rings` × 2·`rings` quads).
Mesh makeSphereMesh(int rings);
/// A box from −1 to 1 on each axis (flat-shaded faces).
Mesh makeBoxMesh();

} // namespace ob::gfx
