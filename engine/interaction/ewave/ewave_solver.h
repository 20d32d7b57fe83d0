// The ewave ripple solver: the dispersive EWaveField (docs/references.md#dispersive-ripples) whose sources are the
// bounding spheres' Table 2 stamps as pressure (ewaveSource), on the CPU (FFTW) or through its
// GPU twin (ewave/gpu/).
#pragma once
#include "interaction/ewave/ewave_def.h"
#include "interaction/ewave/ewave_field.h"
#include "interaction/ripple_solver.h"

#include <memory>
#include <vector>

namespace ob::interaction {

/// EWaveField behind the solver interface. Table 2 decides as for kang2008 (planStamp) and
/// each stamp becomes a source on v, queued in grid coordinates and added over the next
/// step's dt. Queries, hashing and rendering read h and v.
///
/// On the GPU (setOffload, ewave/gpu/): the sources are still added to the CPU field, which is
/// uploaded whenever it changed (sources, scrolling, addHeight, fieldEdited), stepped there,
/// and h, v are read back after each step.
class EWaveSolver final : public RippleSolver {
public:
    /// Where the step runs when not on the CPU.
    class Offload {
    public:
        virtual ~Offload() = default;
        /// One step of dt seconds; `cpuChanged`: the CPU field was written since the last step
        /// (upload it first). Writes h and v back into the CPU field.
        virtual void step(float dt, bool cpuChanged) = 0;
    };

    /// An n × n field of cells `cellSize` metres in `medium` (g, σ/ρ, depth, ν), h = v = 0, with the Def's extra damping.
    EWaveSolver(int n, float cellSize, const EWaveDef& def, const EWaveMedium& medium, RippleBoundary boundary, int spongeWidth);
    /// Steps through `offload` from now on (EWaveModel::moveToGpu).
    void setOffload(std::unique_ptr<Offload> offload) { m_offload = std::move(offload); }

    /// The field, writable: on the GPU, call fieldEdited() after writing its state.
    EWaveField& field() { return m_field; }
    const EWaveField& field() const { return m_field; }
    /// The field was written outside the interface: on the GPU the next step uploads it.
    void fieldEdited() { m_changed = true; }

    int rows() const override { return m_field.rows(); }
    int cols() const override { return m_field.cols(); }
    bool addSphere(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion) override;
    /// addSphere's decision and source, not queued: true and `out` set when the sphere stamps.
    bool planSource(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion, EWaveSource& out) const;
    /// h += dh at cell (x, z) now; with a Periodic or Absorbing border the next step first takes
    /// that volume back as a uniform shift, so a crater moves water and makes none: the mean
    /// level, the k = 0 mode, is kept (its waves, every k > 0, are the crater's).
    void addHeight(int x, int z, double dh) override;
    /// Queues a source (grid coordinates) for the next step, as addSphere does.
    void addSource(const EWaveSource& source) { m_sources.push_back(source); }
    /// The sources queued for the next step, in order (the last one addSphere's newest).
    std::span<const EWaveSource> queuedSources() const { return m_sources; }
    /// The queued sources over dt (none inside a floating hull's waterplane: the hull holds that
    /// water at its hollow, docs/ewave.md#hulls), then the exact per-mode step over dt.
    void step(float dt) override;
    /// Applied after the CPU step, or after the GPU step's read-back on the CPU mirror (which
    /// the next step then uploads). A hull's cells hold h at its hollow (ObstructionCell::level).
    void setObstruction(std::span<const ObstructionCell> cells) override;
    void scroll(glm::ivec2 shift) override;
    void clear() override;
    /// h, its float copy.
    std::span<const float> height() const override { return m_field.height(); }
    /// v, bilinear at g in double (dt unused).
    float velocityAt(glm::vec2 g, float dt) const override;
    /// The field's horizontal velocity (EWaveField::horizontalVelocity, exact per mode), bilinear
    /// at g; 0 inside the bodies the obstruction masks (scaled by their keep factor as v is).
    glm::vec2 horizontalVelocityAt(glm::vec2 g) const override;
    /// EWaveField::velocityWavenumber.
    float velocityWavenumber() const override { return float(m_field.velocityWavenumber()); }
    std::vector<RippleLevel> levels() const override { return {{"h", m_field.height()}}; }
    void hashState(StateHasher& h) const override;
    void retune(const RippleDef& def) override;
    bool onGpu() const override { return m_offload != nullptr; }
    const char* backendName() const override { return onGpu() ? "gpu (compute shaders, float FFT)" : "cpu (FFTW)"; }

    // --- a coarse level of the stack (interaction/ripple_levels.h)
    const char* levelRefusal() const override { return nullptr; }
    /// The same medium, damping, border and sponge on cells of `cellSize` m; it keeps the
    /// horizontal displacement too (the stack's cubic in time of u reads ξ).
    std::unique_ptr<RippleSolver> makeLevel(float cellSize) const override;
    int spongeCells() const override { return m_field.spongeWidth(); }
    bool planLevelSource(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion,
                         LevelSource& out) const override;
    void addLevelSource(const LevelSource& s) override { m_sources.push_back({s.gx, s.gz, s.radiusCells, s.accel}); }
    /// h's float copy, v less its mean (the sponge and a scroll leave some there: no motion, but
    /// in the cubic's S·v terms it would move the level's mean between two states), ξ and u.
    void keepLevelState(LevelState& out) const override;

private:
    void obstruct();

    EWaveField m_field;
    float m_cellSize;                    // m
    EWaveDef m_def;                      // the damping keys as last retuned (a coarse level's)
    int m_spongeAsked;                   // the sponge width asked for, cells (a coarse level's)
    std::vector<EWaveSource> m_sources;  // this step's stamps, grid coordinates, applied over the step's dt
    std::unique_ptr<Offload> m_offload;
    double m_craterVolume = 0.0;         // Σ dh of addHeight since the last step, m (times the cell area), taken back by it
    bool m_changed = false;              // the CPU state was written since the last step (the offload uploads it)
    std::vector<ObstructionCell> m_obstruction;  // setObstruction's cells, applied after each step
    bool m_hulls = false;                        // some of them are a displacing hull's
};

/// The iWave projection on an ewave field (docs/ewave.md#obstacles): h drawn towards each cell's
/// level (0, or a hull's hollow) and v towards 0 by the cells' keep factors, each level's sum
/// kept (obstructKeepingMean), the float copy rebuilt; the derived horizontal velocity (and
/// displacement) scaled by the keep factors too, towards 0 (no sum kept: it has no volume).
/// EWaveSolver runs it after each step; tests run it on fields of any shape.
void obstructField(EWaveField& field, std::span<const ObstructionCell> cells);

/// The sources queued on `field` since its last step, scaled in each displacing hull's cell by
/// its keep factor: no pressure acts on the water a hull holds (EWaveSolver::step runs it
/// before each step; docs/ewave.md#hulls).
void maskHullSources(EWaveField& field, std::span<const ObstructionCell> cells);

} // namespace ob::interaction
