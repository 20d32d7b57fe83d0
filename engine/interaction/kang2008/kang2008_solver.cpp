// The kang2008 solver: RippleField and Table 2 stamping behind RippleSolver.
#include "interaction/kang2008/kang2008_solver.h"

#include "interaction/kang2008/footprint_stamp.h"
#include "interaction/ripple_arrays.h"
#include "interaction/ripple_def.h"

#include <algorithm>

namespace ob::interaction {

std::vector<RippleDefError> Kang2008Model::validate(const RippleDef& def) {
    if (def.boundary == RippleBoundary::Periodic)  // eq. 1–2 has no periodic form (ripple_field.h)
        return {{"boundary", "\"periodic\" needs ripples.model = \"ewave\" (kang2008 has \"fixed\" or \"absorbing\")"}};
    if (def.levels > 1)  // the solver's levelRefusal (docs/ewave.md#levels)
        return {{"levels", std::string("levels > 1 needs ripples.model = \"ewave\" (") + Kang2008Solver::LEVEL_REFUSAL + ")"}};
    return {};
}

void Kang2008Model::stepArrays(RippleArrays& a) {
    RippleField field(a.rows, a.cols, RippleBoundary::Fixed);
    std::copy(a.height.begin(), a.height.end(), field.current().begin());
    const std::vector<float>& previous = a.second.empty() ? a.height : a.second;
    std::copy(previous.begin(), previous.end(), field.previous().begin());
    for (int k = 0; k < a.steps; ++k) field.step(a.damping);
    std::copy(field.current().begin(), field.current().end(), a.height.begin());
}

std::unique_ptr<RippleSolver> Kang2008Model::make(const RippleDef& def) {
    return std::make_unique<Kang2008Solver>(def.resolution, def.cell_size, def, def.boundary, def.sponge_width);
}

Kang2008Solver::Kang2008Solver(int n, float cellSize, const Kang2008Def& def, RippleBoundary boundary, int spongeWidth)
    : m_field(n, n, boundary, spongeWidth), m_cellSize(cellSize), m_damping(def.damping) {}

bool Kang2008Solver::addSphere(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion) {
    if (!m_offload) return stepSphere(m_field, m_footprints, m_cellSize, sphere, contact, motion);
    RippleStamp stamp;
    if (!planSphereStamp(m_field.current(), m_field.rows(), m_field.cols(), m_cellSize, sphere, contact, motion, stamp))
        return false;
    m_offload->stamp(stamp);
    return true;
}

void Kang2008Solver::addHeight(int x, int z, double dh) {
    m_field.current()[size_t(z) * size_t(m_field.cols()) + size_t(x)] += float(dh);
    fieldEdited();
}

void Kang2008Solver::step(float /*dt*/) {
    if (m_offload) m_offload->step(m_damping, m_edited);
    else m_field.step(m_damping);
    m_edited = false;
    if (m_obstruction.empty()) return;
    // The iWave projection (docs/ewave.md#obstacles): both levels 0 inside the bodies, so the
    // next step sees still, level water there; each level's sum kept.
    obstructKeepingMean(m_field.current(), m_obstruction);
    obstructKeepingMean(m_field.previous(), m_obstruction);
    m_edited = onGpu();
}

void Kang2008Solver::scroll(glm::ivec2 shift) {
    m_field.scroll(shift.x, shift.y);
    if (m_offload) m_offload->scroll(shift);
}

void Kang2008Solver::clear() {
    m_field.clear();
    fieldEdited();
}

float Kang2008Solver::velocityAt(glm::vec2 g, float dt) const {
    const float now = bilinear(m_field.current(), m_field.rows(), m_field.cols(), g);
    const float before = bilinear(m_field.previous(), m_field.rows(), m_field.cols(), g);
    return (now - before) / dt;
}

std::vector<RippleLevel> Kang2008Solver::levels() const { return {{"Vh(t)", m_field.current()}, {"Vh(t-1)", m_field.previous()}}; }

void Kang2008Solver::hashState(StateHasher& h) const {
    h.f32s(m_field.current().data(), m_field.current().size());
    h.f32s(m_field.previous().data(), m_field.previous().size());
}

void Kang2008Solver::retune(const RippleDef& def) { m_damping = def.damping; }

} // namespace ob::interaction
