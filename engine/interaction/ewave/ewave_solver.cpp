// The ewave solver: EWaveField and its pressure sources behind RippleSolver.
#include "interaction/ewave/ewave_solver.h"

#include "interaction/ripple_arrays.h"
#include "interaction/ripple_def.h"

#include <algorithm>

namespace ob::interaction {

// Every key of ewave's is checked by its range; the coarse levels (ripple_levels.h) run on the
// GPU as level 0 does, each on its own twin (attachGpu).
std::vector<RippleDefError> EWaveModel::validate(const RippleDef&) { return {}; }

void EWaveModel::stepArrays(RippleArrays& a) {
    EWaveField field(a.rows, a.cols, a.cellSize, a.boundary);
    field.setDamping(a.damping, a.viscosity);
    std::copy(a.height.begin(), a.height.end(), field.editHeight().begin());
    if (!a.second.empty()) std::copy(a.second.begin(), a.second.end(), field.editVelocity().begin());
    field.syncHeight();
    for (int k = 0; k < a.steps; ++k) field.step(a.dt);
    std::copy(field.height().begin(), field.height().end(), a.height.begin());
}

std::unique_ptr<RippleSolver> EWaveModel::make(const RippleDef& def) {
    return std::make_unique<EWaveSolver>(def.resolution, def.cell_size, def, EWaveMedium::of(def.environment, def.depth), def.boundary,
                                         def.sponge_width);
}

EWaveSolver::EWaveSolver(int n, float cellSize, const EWaveDef& def, const EWaveMedium& medium, RippleBoundary boundary,
                         int spongeWidth)
    : m_field(n, n, cellSize, boundary, spongeWidth), m_cellSize(cellSize), m_def(def), m_spongeAsked(spongeWidth) {
    m_field.setMedium(medium);
    m_field.setDamping(def.decay_time, def.viscosity);
}

bool EWaveSolver::addSphere(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion) {
    EWaveSource source;
    if (!planSource(sphere, contact, motion, source)) return false;
    m_sources.push_back(source);
    return true;
}

bool EWaveSolver::planSource(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion,
                             EWaveSource& out) const {
    RippleStamp stamp;
    const EWaveField& f = m_field;
    if (!planStamp(f.rows(), f.cols(), m_cellSize, sphere, contact, motion, [&f](int x, int z) { return f.heightAt(x, z); },
                   stamp))
        return false;
    out = ewaveSource(stamp, motion.gridX, motion.gridZ, m_cellSize, float(m_field.medium().gravity), motion.verticalVelocity);
    return true;
}

bool EWaveSolver::planLevelSource(const BoundingSphere& sphere, SphereContact& contact, const SphereMotion& motion,
                                  LevelSource& out) const {
    EWaveSource s;
    if (!planSource(sphere, contact, motion, s)) return false;
    out = {s.gx, s.gz, s.radiusCells, s.accel};
    return true;
}

std::unique_ptr<RippleSolver> EWaveSolver::makeLevel(float cellSize) const {
    auto level = std::make_unique<EWaveSolver>(m_field.rows(), cellSize, m_def, m_field.medium(), m_field.boundary(), m_spongeAsked);
    level->m_field.keepHorizontalDisplacement(true);
    return level;
}

void EWaveSolver::keepLevelState(LevelState& out) const {
    const size_t cells = m_field.height().size();
    const std::span<const float> h = m_field.height();
    out.h.assign(h.begin(), h.end());
    const std::span<const double> v = m_field.velocityState();
    double mean = 0.0;
    for (double x : v) mean += x;
    mean /= double(v.size());
    out.v.resize(cells);
    std::transform(v.begin(), v.end(), out.v.begin(), [mean](double x) { return float(x - mean); });
    const std::span<const glm::vec2> xi = m_field.horizontalDisplacement(), u = m_field.horizontalVelocity();
    for (int a = 0; a < 2; ++a) {
        out.xi[a].resize(cells);
        out.u[a].resize(cells);
        for (size_t c = 0; c < cells; ++c) out.xi[a][c] = xi[c][a], out.u[a][c] = u[c][a];
    }
}

void EWaveSolver::setObstruction(std::span<const ObstructionCell> cells) {
    m_obstruction.assign(cells.begin(), cells.end());
    m_hulls = std::any_of(cells.begin(), cells.end(), [](const ObstructionCell& c) { return c.displaces; });
}

void EWaveSolver::addHeight(int x, int z, double dh) {
    m_field.addHeight(size_t(z) * size_t(m_field.cols()) + size_t(x), dh);
    if (m_field.boundary() != RippleBoundary::Fixed) m_craterVolume += dh;
    m_changed = true;
}

void EWaveSolver::step(float dt) {
    if (m_craterVolume != 0.0) {  // the craters' water, moved not made: back as the k = 0 mode (on the CPU field, then uploaded)
        m_field.addLevel(-m_craterVolume / (double(m_field.rows()) * double(m_field.cols())));
        m_craterVolume = 0.0;
        m_changed = true;
    }
    if (!m_sources.empty()) m_changed = true;
    m_field.addSources(m_sources, dt);
    m_sources.clear();
    // Inside a floating hull's waterplane the water is the hull's, held at its hollow after the
    // step: no pressure acts on it (its own keel spheres' push is the hollow itself; pressed there
    // too, the projection would take that push out every step and the hull would pump).
    if (m_hulls) maskHullSources(m_field, m_obstruction);
    if (m_offload) m_offload->step(dt, m_changed);
    else m_field.step(dt);
    m_changed = false;
    if (!m_obstruction.empty()) obstruct();
}

// The iWave projection after the exact step (operator splitting: free evolution over dt, then
// h = its level, 0 or a hull's hollow, and v = 0 inside the bodies), each level's sum kept
// (docs/ewave.md#obstacles). On the GPU it runs on the read-back mirror, and the next step
// uploads the result.
void EWaveSolver::obstruct() {
    obstructField(m_field, m_obstruction);
    m_changed = onGpu();
}

void obstructField(EWaveField& field, std::span<const ObstructionCell> cells) {
    obstructKeepingMean(field.editHeight(), cells, true);
    obstructKeepingMean(field.editVelocity(), cells);
    for (const ObstructionCell& c : cells) field.scaleHorizontal(c.index, c.keep);
    field.syncHeight();
}

void maskHullSources(EWaveField& field, std::span<const ObstructionCell> cells) {
    for (const ObstructionCell& c : cells)
        if (c.displaces) field.scaleQueuedSources(c.index, c.keep);
}

void EWaveSolver::scroll(glm::ivec2 shift) {
    m_field.scroll(shift.x, shift.y);
    for (EWaveSource& s : m_sources) {  // queued in the old grid's coordinates
        s.gx -= float(shift.x);
        s.gz -= float(shift.y);
    }
    m_changed = true;
}

void EWaveSolver::clear() {
    m_field.clear();
    m_craterVolume = 0.0;
    m_sources.clear();
    m_changed = true;
}

float EWaveSolver::velocityAt(glm::vec2 g, float /*dt*/) const {
    return bilinear<double>(m_field.velocityState(), m_field.rows(), m_field.cols(), g);
}

// bilinear's arithmetic on the field's (x, z) pairs, per component.
glm::vec2 EWaveSolver::horizontalVelocityAt(glm::vec2 g) const {
    const int rows = m_field.rows(), cols = m_field.cols();
    const float fx = std::floor(g.x), fz = std::floor(g.y);
    const int x0 = int(fx), z0 = int(fz);
    if (x0 < 0 || z0 < 0 || x0 + 1 >= cols || z0 + 1 >= rows) return glm::vec2(0.0f);
    const float tx = g.x - fx, tz = g.y - fz;
    const glm::vec2* r0 = m_field.horizontalVelocity().data() + size_t(z0) * size_t(cols) + size_t(x0);
    const glm::vec2* r1 = r0 + cols;
    return (r0[0] * (1 - tx) + r0[1] * tx) * (1 - tz) + (r1[0] * (1 - tx) + r1[1] * tx) * tz;
}

void EWaveSolver::hashState(StateHasher& h) const {
    // The whole state of the dispersive model: h and v, in double (the horizontal velocity is
    // derived from them: not state).
    h.bytes(m_field.heightState().data(), m_field.heightState().size_bytes());
    h.bytes(m_field.velocityState().data(), m_field.velocityState().size_bytes());
    if (m_craterVolume != 0.0) h.bytes(&m_craterVolume, sizeof m_craterVolume);  // between a crater and the step
}

// The GPU twin takes the damping from the field at its next step (the medium, depth included, is set once).
void EWaveSolver::retune(const RippleDef& def) {
    m_def = def;
    m_field.setDamping(def.decay_time, def.viscosity);
}

} // namespace ob::interaction
