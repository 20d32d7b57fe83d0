// Persistent foam map: the storage and the order of its parts (foam_map.h).
#include "foam/foam_map.h"

#include "core/hash.h"
#include "interaction/ripple_patch.h"

#include <cmath>

namespace ob::foam {

namespace {

// Coverage of a row-major n×n map at sample (i, j), 0 outside.
inline float mapCellOr0(const float* f, int n, int i, int j) {
    return (i < 0 || j < 0 || i >= n || j >= n) ? 0.0f : f[size_t(j) * size_t(n) + size_t(i)];
}

} // namespace

FoamMap::FoamMap(const FoamDef& def, float extent, glm::vec2 centre)
    : m_def(def), m_grid(ScrollingGrid::centredOn(centre, extent / float(def.resolution), def.resolution)),
      m_f(size_t(def.resolution) * size_t(def.resolution), 0.0f), m_flow(m_grid, def.flow_resolution) {
    m_transport.chooseThreads(m_grid, def.flow_resolution, m_f);
}

void FoamMap::setDef(const FoamDef& def) {
    m_def = def;
    m_def.resolution = m_grid.n;
    m_flow.setResolution(def.flow_resolution);
}

void FoamMap::centerOn(glm::vec2 worldCentre) {
    const glm::ivec2 shift = m_grid.centreOn(worldCentre);
    if (shift == glm::ivec2(0)) return;
    scrollCells(m_f.data(), m_grid.n, m_grid.n, shift, 0.0f);
    m_flow.follow(m_grid);
}

float FoamMap::sample(float x, float z) const {
    const int n = m_grid.n;
    const glm::vec2 g = m_grid.toGrid(glm::vec2(x, z));
    const float fx = std::floor(g.x), fz = std::floor(g.y);
    const int i = int(fx), j = int(fz);
    if (i < -1 || j < -1 || i >= n || j >= n) return 0.0f;
    const float tx = g.x - fx, tz = g.y - fz;
    const float* f = m_f.data();
    return (mapCellOr0(f, n, i, j) * (1 - tx) + mapCellOr0(f, n, i + 1, j) * tx) * (1 - tz) +
           (mapCellOr0(f, n, i, j + 1) * (1 - tx) + mapCellOr0(f, n, i + 1, j + 1) * tx) * tz;
}

double FoamMap::mean() const {
    double sum = 0.0;
    for (float v : m_f) sum += v;
    return sum / double(m_f.size());
}

void FoamMap::addSources(const FoamInputs& in, float dt) {
    const RowSources sources(m_def, m_grid, in, dt);
    m_whitecaps = sources.whitecaps();
    sources.addTo(m_f);
}

void FoamMap::step(float dt) { m_transport.step(m_f, m_grid, m_flow, m_def.decay_s, dt); }

WindFlow FoamMap::windFlow(float windSpeed, glm::vec2 direction, glm::vec2 stokes) const {
    WindFlow w;
    w.direction = glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec2(1.0f, 0.0f);
    w.drift = m_def.wind_drift * windSpeed * w.direction + stokes;
    w.streakSpeed = m_def.streak_speed * windSpeed;
    w.streakSpacing = m_def.streak_spacing_m;
    return w;
}

void FoamMap::update(const FoamInputs& in, float dt) {
    prepare(in, dt, false);
    sweep();
}

void FoamMap::prepare(const FoamInputs& given, float dt, bool copyInputs) {
    FoamInputs in = given;
    if (copyInputs) {
        m_jacobianCopy.assign(in.jacobian.begin(), in.jacobian.end());
        in.jacobian = m_jacobianCopy;
        if (in.ripples) {
            const std::span<const float> h = in.rippleHeight.empty() ? in.ripples->height() : in.rippleHeight;
            m_rippleCopy.assign(h.begin(), h.end());
            in.rippleHeight = m_rippleCopy;
        }
    }
    // --- the velocity at the water's time
    if (in.water) m_flow.refresh(*in.water, m_def.flow_refresh_steps);
    m_flow.setWind(windFlow(in.windSpeed, in.windDirection, in.stokesDrift));
    m_flow.setWindTime(m_time);
    m_time += double(dt);
    m_sources.emplace(m_def, m_grid, in, dt);
    m_whitecaps = m_sources->whitecaps();
    m_sweepDt = dt;
}

void FoamMap::sweep() {
    if (!m_sources) return;
    // --- sources and step: one sweep when the flow is from the nodes and within a sample a step
    const float dt = m_sweepDt;
    if (m_transport.sweepFits(m_grid, m_flow, dt)) {
        m_transport.sweep(m_f, m_grid, m_flow, &*m_sources, m_def.decay_s, dt);
    } else {
        m_sources->addTo(m_f);
        step(dt);
    }
    m_sources.reset();
}

void FoamMap::hash(StateHasher& h) const {
    h.u64(uint64_t(uint32_t(m_grid.originCell.x)) | (uint64_t(uint32_t(m_grid.originCell.y)) << 32));
    h.f32(m_grid.cell);
    h.f32s(m_f.data(), m_f.size());
}

} // namespace ob::foam
