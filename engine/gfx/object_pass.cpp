// Objects per view: which to skip, which mesh (far twins), which cut at the surface.
#include "gfx/object_pass.h"

#include "gfx/shader.h"

namespace ob::gfx {

using namespace glsl;  // the binding points and locations (shaders/common_bindings.glsl)

namespace {
// The water's steepest slope (dh/dx) that the reflection and refraction passes assume when
// they decide that an object lies wholly on one side of the surface (steeper water breaks).
constexpr float MAX_SURFACE_SLOPE = 1.0f;
// Objects within this radius (m: fish, cannonballs) are cut at the surface's tangent plane
// under their origin, larger ones (ships) at the surface evaluated vertex by vertex.
constexpr float TANGENT_PLANE_RADIUS = 1.0f;
// A highlighted object's colour is multiplied by this (the body under the player's cursor).
constexpr glm::vec3 HIGHLIGHT_TINT{1.9f, 1.7f, 1.0f};

// Where an object's bounding sphere lies against the water: the surface within its radius
// R of the height under its origin h0 stays within h0 ± R·MAX_SURFACE_SLOPE.
enum class Side { Above, Below, Across };
Side sideOfSurface(const ObjectDraw& o, const Mesh& mesh) {
    const float reach = boundingRadius(o, mesh) * (1.0f + MAX_SURFACE_SLOPE);
    const float y = o.model[3].y;
    if (y - reach > o.waterHeight + REFLECTION_OVERLAP) return Side::Above;
    if (y + reach < o.waterHeight - REFRACTION_OVERLAP) return Side::Below;
    return Side::Across;
}
} // namespace

ObjectPass::ObjectPass()
    : m_program(loadProgram("object_mesh", {"object_mesh.vert", "object_mesh.frag"})),
      m_waterlineProgram(loadProgram("object_mesh_waterline", {"object_mesh_waterline.vert", "object_mesh.frag"})) {}

void ObjectPass::listPrograms(ProgramList& out) const {
    out.emplace_back("object_mesh", m_program.id());
    out.emplace_back("object_mesh_waterline", m_waterlineProgram.id());
}

void ObjectPass::opaquePass(FrameContext& frame, const std::vector<ObjectDraw>& objects) {
    const PassScope scope(frame, OPAQUE_PASS);
    draw(frame, objects, MAIN_VIEW);
}

void ObjectPass::draw(FrameContext& frame, const std::vector<ObjectDraw>& objects, View view) {
    if (objects.empty()) return;
    const FrameState& state = frame.state;
    frame.views.bind(view);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    if (view != MAIN_VIEW) glEnable(GL_CLIP_DISTANCE0);
    for (const ObjectDraw& o : objects) {
        const Mesh& mesh = m_meshes.meshFor(o, state.eye, state.pixelsPerRadian[view]);
        // An object wholly on one side of the surface is skipped by the pass that keeps the
        // other side, and wholly under it by the camera's view from above: the water surface,
        // drawn after it and opaque, covers it (the refraction pass shows it). Seen from under
        // water, or across the waterline, every object is drawn (with the water's extinction). The surface per
        // vertex (the cut's cost on a software rasteriser) is evaluated only for large objects
        // across it in the passes that cut; the others take its tangent plane. A hull is drawn
        // in the main view whatever the sea over it: the water is clipped out of it (HullClip).
        const Side side = sideOfSurface(o, mesh);
        if ((view == REFLECTION_VIEW && side == Side::Below) || (view == REFRACTION_VIEW && side == Side::Above) ||
            (view == MAIN_VIEW && side == Side::Below && !o.hull && !state.underwater && !state.waterline && state.waterVisible))
            continue;
        const bool perVertex = view != MAIN_VIEW && side == Side::Across && boundingRadius(o, mesh) > TANGENT_PLANE_RADIUS;
        const GLuint program = perVertex ? m_waterlineProgram.id() : m_program.id();
        const glm::vec3 plane(o.waterHeight, o.waterSlope);
        // Models carry their own colours (times a goal's state tint); a highlighted object is
        // drawn brighter and warmer.
        const glm::vec3 tint = (o.modelFile.empty() ? o.color : o.modelTint) * (o.highlight ? HIGHLIGHT_TINT : glm::vec3(1.0f));
        glUseProgram(program);
        glProgramUniformMatrix4fv(program, OBJECT_MODEL_LOCATION, 1, GL_FALSE, &o.model[0][0]);
        glProgramUniform3fv(program, OBJECT_TINT_LOCATION, 1, &tint.x);
        if (!perVertex) glProgramUniform3fv(program, OBJECT_SURFACE_PLANE_LOCATION, 1, &plane.x);
        glBindVertexArray(mesh.vao.id());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CULL_FACE);
    frame.views.bind(MAIN_VIEW);
}

} // namespace ob::gfx
