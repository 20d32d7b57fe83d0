// The ripple patch in the world: a RippleField placed on a square of the water plane, moved
// in whole cells (the data scrolls with it so waves stay put), sampled by world position.
#pragma once
#include "interaction/ripple_def.h"
#include "interaction/ripple_field.h"
#include "interaction/sphere_stamp.h"

#include <glm/vec2.hpp>

namespace ob::interaction {

class RipplePatch {
public:
    explicit RipplePatch(const RippleDef& def);

    /// Moves the patch so its centre is the cell nearest `worldCenter` (scrolls the field).
    void centerOn(glm::vec2 worldCenter);
    /// Grid coordinates (column x, row z; cell centres at integers) of a world (x, z).
    glm::vec2 toGrid(glm::vec2 world) const;
    /// Vh(t) at world (x, z), bilinear between cell centres; 0 outside the patch (m).
    float heightAt(glm::vec2 world) const;
    /// (Vh(t) − Vh(t−1)) / dt at world (x, z): the layer's vertical velocity (m/s).
    float velocityAt(glm::vec2 world, float dt) const;
    /// World (x, z) of cell (0, 0)'s centre.
    glm::vec2 origin() const { return glm::vec2(m_originCell) * m_def.cell_size; }

    /// Table 2 and eq. 3–7 for one sphere this step (see stepSphere); world centre, m.
    bool stampSphere(const BoundingSphere& sphere, SphereContact& contact, const glm::vec3& centre,
                     const glm::vec3& velocity, float mass, float surfaceY);
    /// The convolution step of eq. 1–2 with the patch's DF.
    void step() { m_field.step(m_def.damping); }

    const RippleDef& def() const { return m_def; }
    RippleField& field() { return m_field; }
    const RippleField& field() const { return m_field; }

private:
    RippleDef m_def;
    RippleField m_field;
    FootprintCache m_footprints;
    glm::ivec2 m_originCell{0, 0};  // world cell index of the field's cell (0, 0)
};

} // namespace ob::interaction
