// The GPU twins behind RipplePatch's offload interface.
#include "interaction/gpu/ripple_offload.h"

#include "interaction/gpu/ewave_gpu.h"
#include "interaction/gpu/ripple_gpu.h"
#include "interaction/ripple_patch.h"

#include <algorithm>
#include <memory>
#include <vector>

namespace ob::interaction {

namespace {

// kang2008: this step's stamps, then eq. 1–2, then Vh(t) and Vh(t−1) read back.
class RippleGpuOffload final : public RippleOffload {
public:
    explicit RippleGpuOffload(RippleField& field)
        : m_field(field), m_gpu(field.rows(), field.cols(), field.boundary(), field.spongeWidth()) {
        m_gpu.upload(field);
    }
    void stamp(const RippleStamp& stamp) override { m_pending.push_back(stamp); }
    void scroll(int dx, int dz) override { m_gpu.scroll(dx, dz); }
    void step(float /*dt*/, float damping, bool cpuChanged) override {
        if (cpuChanged) m_gpu.upload(m_field);
        m_gpu.stamp(m_pending);
        m_pending.clear();
        m_gpu.step(damping);
        m_gpu.readCurrent(m_readback);
        std::copy(m_readback.begin(), m_readback.end(), m_field.current().begin());
        m_gpu.readPrevious(m_readback);
        std::copy(m_readback.begin(), m_readback.end(), m_field.previous().begin());
    }

private:
    RippleField& m_field;
    RippleFieldGpu m_gpu;
    std::vector<RippleStamp> m_pending;  // this step's stamps, in entity then sphere order
    std::vector<float> m_readback;
};

// ewave: the sources are already in the CPU field; it is uploaded when it changed (sources,
// scrolling, edits), stepped, and h, v read back.
class EWaveGpuOffload final : public RippleOffload {
public:
    explicit EWaveGpuOffload(EWaveField& field) : m_field(field), m_gpu(field) {}
    void stamp(const RippleStamp& /*stamp*/) override {}
    void scroll(int /*dx*/, int /*dz*/) override { m_scrolled = true; }
    void step(float dt, float /*damping*/, bool cpuChanged) override {
        if (cpuChanged || m_scrolled) m_gpu.upload(m_field);
        m_scrolled = false;
        m_gpu.setDamping(m_field.decayTime(), m_field.viscosity());  // a live change of ripples.decay_time or .viscosity
        m_gpu.step(dt);
        m_gpu.download(m_field.editHeight(), m_field.editVelocity());
        m_field.syncHeight();
    }

private:
    EWaveField& m_field;
    EWaveGpu m_gpu;
    bool m_scrolled = false;
};

} // namespace

bool attachGpu(RipplePatch& patch) {
    if (EWaveField* ewave = patch.ewave()) {
        if (!EWaveGpu::supports(ewave->rows(), ewave->cols())) return false;
        patch.setOffload(std::make_unique<EWaveGpuOffload>(*ewave));
        return true;
    }
    patch.setOffload(std::make_unique<RippleGpuOffload>(patch.field()));
    return true;
}

} // namespace ob::interaction
