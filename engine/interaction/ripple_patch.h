// The ripple patch in the world: a RippleField placed on a square of the water plane, moved
// in whole cells (the data scrolls with it so waves stay put), sampled by world position.
#pragma once
#include "interaction/ripple_def.h"
#include "interaction/ripple_field.h"
#include "interaction/sphere_stamp.h"

#include <glm/vec2.hpp>
#include <memory>
#include <vector>

namespace ob::interaction {

class RippleFieldGpu;
struct RippleStamp;

/// The field runs on the CPU (RippleField) or, once useGpu() is called on a GL context, on the
/// GPU twin (RippleFieldGpu): Table 2 still decides on the CPU, the stamps and the step run
/// in compute shaders, and Vh(t), Vh(t−1) are read back after each step into the CPU field,
/// which stays what queries, hashing and rendering read.
class RipplePatch {
public:
    explicit RipplePatch(const RippleDef& def);
    ~RipplePatch();
    /// Moves the field to the GPU twin (needs a current GL 4.3+ context).
    void useGpu();
    bool onGpu() const { return m_gpu != nullptr; }

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
    /// The convolution step of eq. 1–2 with the patch's DF (on the GPU: this step's stamps
    /// first, then the step, then the read-back).
    void step();

    const RippleDef& def() const { return m_def; }
    /// Changes DF (eq. 2) from the next step on, [0, 1].
    void setDamping(float damping) { m_def.damping = damping; }
    /// The CPU field, writable: on the GPU, call fieldEdited() after writing it.
    RippleField& field() { return m_field; }
    /// The CPU field was written outside stampSphere (e.g. splash drops landing): on the GPU the
    /// next step() uploads it first, so both sides hold the same state. No-op on the CPU.
    void fieldEdited() { m_edited = m_gpu != nullptr; }
    const RippleField& field() const { return m_field; }

private:
    RippleDef m_def;
    RippleField m_field;
    FootprintCache m_footprints;
    glm::ivec2 m_originCell{0, 0};  // world cell index of the field's cell (0, 0)
    std::unique_ptr<RippleFieldGpu> m_gpu;
    std::vector<RippleStamp> m_pending;  // GPU: this step's stamps, in entity then sphere order
    std::vector<float> m_readback;
    bool m_edited = false;  // GPU: the CPU field changed since the last read-back
};

} // namespace ob::interaction
