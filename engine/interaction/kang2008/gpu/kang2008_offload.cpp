// kang2008 on its GPU twin: Kang2008Model::moveToGpu puts a RippleFieldGpu under the solver.
#include "interaction/kang2008/gpu/ripple_gpu.h"
#include "interaction/kang2008/kang2008_solver.h"

#include <algorithm>
#include <cassert>
#include <vector>

namespace ob::interaction {

namespace {

// This step's stamps, then eq. 1–2, then Vh(t) and Vh(t−1) read back into the CPU field.
class RippleGpuOffload final : public Kang2008Solver::Offload {
public:
    explicit RippleGpuOffload(RippleField& field)
        : m_field(field), m_gpu(field.rows(), field.cols(), field.boundary(), field.spongeWidth()) {
        m_gpu.upload(field);
    }
    void stamp(const RippleStamp& stamp) override { m_pending.push_back(stamp); }
    void scroll(glm::ivec2 shift) override { m_gpu.scroll(shift.x, shift.y); }
    void step(float damping, bool cpuChanged) override {
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

} // namespace

bool Kang2008Model::moveToGpu(RippleSolver& solver) {
    auto* kang = dynamic_cast<Kang2008Solver*>(&solver);
    assert(kang && "moveToGpu takes the solver make() made");
    kang->setOffload(std::make_unique<RippleGpuOffload>(kang->field()));
    return true;
}

} // namespace ob::interaction
