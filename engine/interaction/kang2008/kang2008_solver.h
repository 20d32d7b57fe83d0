// The kang2008 ripple solver: [Kang2008]'s RippleField (eq. 1–2) stamped by bounding spheres
// (Table 2, eq. 3–7), on the CPU or through its GPU twin (kang2008/gpu/).
#pragma once
#include "interaction/kang2008/kang2008_def.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/ripple_solver.h"

#include <memory>

namespace ob::interaction {

/// RippleField behind the solver interface. Each sphere that stamps is written into Vh(t) and
/// Vh(t−1) at once (stepSphere), before the step, as the paper does.
///
/// Eq. 1–2 are a height field without a velocity law: the water's velocity it gives is the
/// vertical one (velocityAt, the difference of its levels); its horizontal velocity is the
/// interface's default, 0 (RippleSolver::horizontalVelocityAt), and velocityWavenumber 0.
///
/// On the GPU (setOffload, kang2008/gpu/): Table 2 still decides on the CPU against the field,
/// the stamps and the step run in compute shaders, and Vh(t), Vh(t−1) are read back into the
/// field after each step, so what is read (height, hash, dumps) is always the field.
class Kang2008Solver final : public RippleSolver {
public:
    /// Where the step runs when not on the CPU.
    class Offload {
    public:
        virtual ~Offload() = default;
        /// One Table 2 stamp planned on the CPU, applied with the next step.
        virtual void stamp(const RippleStamp& stamp) = 0;
        /// The field moved by `shift` cells (the CPU field has scrolled too).
        virtual void scroll(glm::ivec2 shift) = 0;
        /// One step with eq. 2's DF; `cpuChanged`: the CPU field was written since the last
        /// step (upload it first). Writes the new levels into the CPU field.
        virtual void step(float damping, bool cpuChanged) = 0;
    };

    /// An n × n field of cells `cellSize` metres, both levels 0.
    Kang2008Solver(int n, float cellSize, const Kang2008Def& def, RippleBoundary boundary, int spongeWidth);
    /// Steps through `offload` from now on (Kang2008Model::moveToGpu).
    void setOffload(std::unique_ptr<Offload> offload) { m_offload = std::move(offload); }

    /// The field, writable: on the GPU, call fieldEdited() after writing it.
    RippleField& field() { return m_field; }
    const RippleField& field() const { return m_field; }
    /// The field was written outside addSphere/addHeight: on the GPU the next step uploads it.
    void fieldEdited() { m_edited = onGpu(); }

    int rows() const override { return m_field.rows(); }
    int cols() const override { return m_field.cols(); }
    bool addSphere(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion) override;
    void addHeight(int x, int z, double dh) override;
    /// Eq. 1–2 with the Def's DF (dt unused: the paper steps per frame).
    void step(float dt) override;
    /// Applied to Vh(t) and Vh(t−1) after each step (on the GPU: on the read-back CPU field,
    /// which the next step then uploads).
    void setObstruction(std::span<const ObstructionCell> cells) override { m_obstruction.assign(cells.begin(), cells.end()); }
    /// [Kang2008]'s ship is its six bounding spheres pressing a free surface (fig. 16's hollow
    /// under the hull): a hull mask would hold that hollow at 0, so hulls do not obstruct here.
    bool obstructsHulls() const override { return false; }
    void scroll(glm::ivec2 shift) override;
    void clear() override;
    /// Vh(t).
    std::span<const float> height() const override { return m_field.current(); }
    /// (Vh(t) − Vh(t−1)) / dt, each level bilinear at g.
    float velocityAt(glm::vec2 g, float dt) const override;
    std::vector<RippleLevel> levels() const override;
    void hashState(StateHasher& h) const override;
    void retune(const RippleDef& def) override;
    bool onGpu() const override { return m_offload != nullptr; }
    const char* backendName() const override { return onGpu() ? "gpu (compute shaders)" : "cpu"; }
    /// Eq. 1–2 is a per-step scheme whose wave speed is one cell a step: a coarse level stepping
    /// 4^L frames at once would be another model (LEVEL_REFUSAL).
    const char* levelRefusal() const override { return LEVEL_REFUSAL; }

    /// Why kang2008 has no coarse levels (levelRefusal, and the Def's check of ripples.levels).
    static constexpr const char* LEVEL_REFUSAL = "kang2008 runs on one grid: levels = 1";

private:
    RippleField m_field;
    float m_cellSize;  // m
    float m_damping;   // DF of eq. 2
    FootprintCache m_footprints;
    std::unique_ptr<Offload> m_offload;
    bool m_edited = false;  // offload: the CPU field changed since the last step
    std::vector<ObstructionCell> m_obstruction;  // setObstruction's cells, applied after each step
};

} // namespace ob::interaction
