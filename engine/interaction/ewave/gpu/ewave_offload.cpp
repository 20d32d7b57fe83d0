// ewave on its GPU twin: EWaveModel::moveToGpu puts an EWaveGpu under the solver.
#include "core/log.h"
#include "interaction/ewave/ewave_solver.h"
#include "interaction/ewave/gpu/ewave_gpu.h"

#include <cassert>

namespace ob::interaction {

namespace {

// The sources are already in the CPU field; it is uploaded when it changed (sources,
// scrolling, edits), stepped, and h, v read back. The horizontal velocity (and
// velocityWavenumber) is then derived on the CPU from the read-back state
// (EWaveField::deriveHorizontal: one forward and two inverse FFTW transforms), not by the
// compute shaders: the same law as the CPU step, after the GPU's boundary instead of before.
class EWaveGpuOffload final : public EWaveSolver::Offload {
public:
    explicit EWaveGpuOffload(EWaveField& field) : m_field(field), m_gpu(field) {}
    void step(float dt, bool cpuChanged) override {
        if (cpuChanged) m_gpu.upload(m_field);
        m_gpu.setDamping(m_field.decayTime(), m_field.viscosity());  // a live change of ripples.decay_time or .viscosity
        m_gpu.step(dt);
        m_gpu.download(m_field.editHeight(), m_field.editVelocity());
        m_field.syncHeight();
        m_field.deriveHorizontal();
    }

private:
    EWaveField& m_field;
    EWaveGpu m_gpu;
};

} // namespace

bool EWaveModel::moveToGpu(RippleSolver& solver) {
    auto* ewave = dynamic_cast<EWaveSolver*>(&solver);
    assert(ewave && "moveToGpu takes the solver make() made");
    if (!EWaveGpu::supports(ewave->rows(), ewave->cols())) {
        logWarn("ripples: the ewave GPU field runs up to %d² cells; %d² runs on the CPU (FFTW)", EWaveGpu::MAX_RESOLUTION,
                ewave->rows());
        return false;
    }
    ewave->setOffload(std::make_unique<EWaveGpuOffload>(ewave->field()));
    return true;
}

} // namespace ob::interaction
