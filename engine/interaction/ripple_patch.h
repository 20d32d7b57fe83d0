// The ripple patch in the world: a ripple solver placed on a square of the water plane, moved
// in whole cells (the data scrolls with it so waves stay put), sampled by world position.
// The solver is seed 001's RippleField ("kang2008") or the dispersive EWaveField ("ewave").
#pragma once
#include "interaction/ewave_field.h"
#include "interaction/ripple_def.h"
#include "interaction/ripple_field.h"
#include "interaction/sphere_stamp.h"

#include <glm/vec2.hpp>
#include <memory>
#include <vector>

namespace ob::interaction {

class EWaveGpu;
class RippleFieldGpu;
struct RippleStamp;

/// kang2008: the field runs on the CPU (RippleField) or, once useGpu() is called on a GL
/// context, on the GPU twin (RippleFieldGpu): Table 2 still decides on the CPU, the stamps and
/// the step run in compute shaders, and Vh(t), Vh(t−1) are read back after each step into the
/// CPU field, which stays what queries, hashing and rendering read.
/// ewave: an EWaveField (CPU, FFTW); Table 2 decides as for kang2008 (planStamp) and each stamp
/// becomes a pressure source on the vertical velocity (ewaveSource). Queries, hashing and
/// rendering read its height h and velocity v. Once useGpu() is called, the GPU twin (EWaveGpu)
/// steps it: the sources are added to the CPU field, which is uploaded whenever it changed
/// (sources, scrolling, fieldEdited), and h, v are read back after each step into the CPU
/// field, which stays what queries, hashing and rendering read.
class RipplePatch {
public:
    explicit RipplePatch(const RippleDef& def);
    ~RipplePatch();
    /// Moves the field to its GPU twin (needs a current GL 4.3+ context): kang2008
    /// RippleFieldGpu, ewave EWaveGpu. Returns false, and stays on the CPU, where the twin
    /// cannot run it (ewave: N above EWaveGpu::MAX_RESOLUTION).
    bool useGpu();
    /// True for the dispersive model (def().model == "ewave").
    bool isEWave() const { return m_ewave != nullptr; }
    bool onGpu() const { return m_gpu != nullptr || m_ewaveGpu != nullptr; }

    /// Moves the patch so its centre is the cell nearest `worldCenter` (scrolls the field).
    void centerOn(glm::vec2 worldCenter);
    /// Grid coordinates (column x, row z; cell centres at integers) of a world (x, z).
    glm::vec2 toGrid(glm::vec2 world) const;
    /// Vh(t) at world (x, z), bilinear between cell centres; 0 outside the patch (m).
    float heightAt(glm::vec2 world) const;
    /// The layer's vertical velocity at world (x, z), m/s: kang2008 (Vh(t) − Vh(t−1)) / dt,
    /// ewave v (bilinear; dt unused).
    float velocityAt(glm::vec2 world, float dt) const;
    /// World (x, z) of cell (0, 0)'s centre.
    glm::vec2 origin() const { return glm::vec2(m_originCell) * m_def.cell_size; }

    /// Table 2 and eq. 3–7 for one sphere this step (see stepSphere); world centre, m.
    bool stampSphere(const BoundingSphere& sphere, SphereContact& contact, const glm::vec3& centre,
                     const glm::vec3& velocity, float mass, float surfaceY);
    /// One step of dt seconds: kang2008 the convolution of eq. 1–2 with the patch's DF (on the
    /// GPU: this step's stamps first, then the step, then the read-back; dt unused); ewave the
    /// exact per-mode step over dt (on the GPU: sources added and uploaded, the step, the
    /// read-back of h and v).
    void step(float dt);

    const RippleDef& def() const { return m_def; }
    /// Changes DF (eq. 2) from the next step on, [0, 1] (kang2008).
    void setDamping(float damping) { m_def.damping = damping; }
    /// kang2008's field (a 1×1 placeholder under ewave), writable: on the GPU, call
    /// fieldEdited() after writing it.
    RippleField& field() { return m_field; }
    /// The CPU field (either model's) was written outside stampSphere (e.g. splash drops
    /// landing): on the GPU the next step() uploads it first, so both sides hold the same
    /// state. No-op on the CPU.
    void fieldEdited() { m_edited = onGpu(); }
    const RippleField& field() const { return m_field; }
    /// The ewave field; null under kang2008. Writable: on the GPU, call fieldEdited() after
    /// writing its state.
    EWaveField* ewave() { return m_ewave.get(); }
    const EWaveField* ewave() const { return m_ewave.get(); }
    /// The current height level of either model, rows·cols row-major (z·cols + x), m: what the
    /// renderer uploads and dumps write.
    std::span<const float> height() const { return m_ewave ? m_ewave->height() : m_field.current(); }
    /// Rows (z) of the height level.
    int rows() const { return m_ewave ? m_ewave->rows() : m_field.rows(); }
    /// Columns (x) of the height level.
    int cols() const { return m_ewave ? m_ewave->cols() : m_field.cols(); }

private:
    RippleDef m_def;
    RippleField m_field;
    std::unique_ptr<EWaveField> m_ewave;
    std::vector<EWaveSource> m_sources;  // ewave: this step's stamps, applied over the step's dt in step()
    FootprintCache m_footprints;
    glm::ivec2 m_originCell{0, 0};  // world cell index of the field's cell (0, 0)
    std::unique_ptr<RippleFieldGpu> m_gpu;
    std::unique_ptr<EWaveGpu> m_ewaveGpu;
    std::vector<RippleStamp> m_pending;  // GPU: this step's stamps, in entity then sphere order
    std::vector<float> m_readback;
    bool m_edited = false;  // GPU: the CPU field changed since the last read-back
};

} // namespace ob::interaction
