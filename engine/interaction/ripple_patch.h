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

/// Where a patch's solver steps when not on the CPU: the GPU twins (interaction/gpu/,
/// attachGpu) implement it. The CPU field stays what queries, hashing and rendering read: the
/// offload takes the state when it changed, steps it and writes it back into the CPU field.
class RippleOffload {
public:
    virtual ~RippleOffload() = default;
    /// kang2008: one Table 2 stamp planned on the CPU, applied with the next step (ewave adds
    /// its sources to the CPU field instead: never called).
    virtual void stamp(const RippleStamp& stamp) = 0;
    /// The patch moved by whole cells (the CPU field has scrolled too).
    virtual void scroll(int dx, int dz) = 0;
    /// One step over dt (s) with eq. 2's damping DF (kang2008); `cpuChanged`: the CPU state was
    /// written since the last step (upload it first). Writes the new state into the CPU field.
    virtual void step(float dt, float damping, bool cpuChanged) = 0;
};

/// kang2008: the field runs on the CPU (RippleField) or, once an offload is set, on the GPU
/// twin (RippleFieldGpu): Table 2 still decides on the CPU, the stamps and the step run in
/// compute shaders, and Vh(t), Vh(t−1) are read back after each step into the CPU field.
/// ewave: an EWaveField (CPU, FFTW); Table 2 decides as for kang2008 (planStamp) and each stamp
/// becomes a pressure source on the vertical velocity (ewaveSource). Queries, hashing and
/// rendering read its height h and velocity v. With an offload (EWaveGpu) the sources are added
/// to the CPU field, which is uploaded whenever it changed (sources, scrolling, fieldEdited),
/// and h, v are read back after each step.
class RipplePatch {
public:
    explicit RipplePatch(const RippleDef& def);
    ~RipplePatch();
    /// Steps the field through `offload` from now on (interaction/gpu/ attachGpu).
    void setOffload(std::unique_ptr<RippleOffload> offload) { m_offload = std::move(offload); }
    /// True for the dispersive model (def().model == RippleModel::EWave).
    bool isEWave() const { return m_ewave != nullptr; }
    bool onGpu() const { return m_offload != nullptr; }

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
    /// One step of dt seconds: kang2008 the convolution of eq. 1–2 with the patch's DF (dt
    /// unused); ewave the exact per-mode step over dt, its sources added first.
    void step(float dt);

    const RippleDef& def() const { return m_def; }
    /// Changes the damping from the next step on: DF (eq. 2) in [0, 1] (kang2008); the decay
    /// time τ in s and viscosity ν in m²/s, ≥ 0, 0 = none (ewave).
    void setDamping(float damping, float decayTime, float viscosity);
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
    std::unique_ptr<RippleOffload> m_offload;
    bool m_edited = false;  // offload: the CPU field changed since the last step
};

} // namespace ob::interaction
