// Opaque objects in a view: the camera's (the opaque pass), and the reflection's and
// refraction's, which cut them at the water surface (and mirror them about it).
#pragma once
#include "gfx/mesh_cache.h"
#include "gfx/render_frame.h"

#include <vector>

namespace ob::gfx {

/// Draws the frame's objects into the bound target, choosing per object and view what to draw.
class ObjectPass {
public:
    ObjectPass();
    /// in: camera view, objects; out: framebuffer colour, depth.
    void opaquePass(FrameContext& frame, const std::vector<ObjectDraw>& objects);
    /// The objects as one view sees them, into the bound target (depth-tested; the reflection
    /// and refraction views clip at the surface, the reflection with the winding flipped by the caller).
    void draw(FrameContext& frame, const std::vector<ObjectDraw>& objects, View view);
    void listPrograms(ProgramList& out) const;

private:
    Program m_program;           // the surface under an object taken as its tangent plane
    Program m_waterlineProgram;  // the surface evaluated per vertex (large objects across it)
    MeshCache m_meshes;
};

} // namespace ob::gfx
