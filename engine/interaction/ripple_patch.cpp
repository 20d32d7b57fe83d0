// Ripple patch placement, world sampling and per-sphere stamping.
#include "interaction/ripple_patch.h"

#include <algorithm>

#include <cmath>
#include <glm/geometric.hpp>

namespace ob::interaction {

RipplePatch::RipplePatch(const RippleDef& def)
    : m_def(def),
      m_field(def.model == RippleModel::EWave ? 1 : def.resolution, def.model == RippleModel::EWave ? 1 : def.resolution,
              def.boundary, def.sponge_width) {
    if (def.model == RippleModel::EWave) {
        m_ewave = std::make_unique<EWaveField>(def.resolution, def.resolution, def.cell_size, def.boundary,
                                               def.sponge_width);
        m_ewave->setDamping(def.decay_time, def.viscosity);
    }
    m_originCell = glm::ivec2(int(std::lround(def.center.x / def.cell_size)), int(std::lround(def.center.y / def.cell_size))) -
                   glm::ivec2(def.resolution / 2);
}

RipplePatch::~RipplePatch() = default;

void RipplePatch::setDamping(float damping, float decayTime, float viscosity) {
    m_def.damping = damping;
    m_def.decay_time = decayTime;
    m_def.viscosity = viscosity;
    if (m_ewave) m_ewave->setDamping(decayTime, viscosity);  // the GPU twin takes it from the field at its next step
}

void RipplePatch::step(float dt) {
    if (m_ewave) {
        const bool sources = !m_sources.empty();
        m_ewave->addSources(m_sources, dt);
        m_sources.clear();
        if (m_offload) m_offload->step(dt, m_def.damping, m_edited || sources);
        else m_ewave->step(dt);
    } else {
        if (m_offload) m_offload->step(dt, m_def.damping, m_edited);
        else m_field.step(m_def.damping);
    }
    m_edited = false;
}

void RipplePatch::centerOn(glm::vec2 worldCenter) {
    glm::ivec2 target = glm::ivec2(int(std::lround(worldCenter.x / m_def.cell_size)), int(std::lround(worldCenter.y / m_def.cell_size))) -
                        glm::ivec2(m_def.resolution / 2);
    glm::ivec2 shift = target - m_originCell;
    if (shift == glm::ivec2(0)) return;
    if (m_ewave) {
        m_ewave->scroll(shift.x, shift.y);
        // Queued sources are in grid coordinates of the old origin.
        for (EWaveSource& s : m_sources) {
            s.gx -= float(shift.x);
            s.gz -= float(shift.y);
        }
    }
    m_field.scroll(shift.x, shift.y);
    if (m_offload) m_offload->scroll(shift.x, shift.y);
    m_originCell = target;
}

glm::vec2 RipplePatch::toGrid(glm::vec2 world) const { return world / m_def.cell_size - glm::vec2(m_originCell); }

// Bilinear sample of a row-major N×M level (float or double) at grid position g (0 outside).
template <class T>
static float bilinear(std::span<const T> level, int rows, int cols, glm::vec2 g) {
    float fx = std::floor(g.x), fz = std::floor(g.y);
    int x0 = int(fx), z0 = int(fz);
    if (x0 < 0 || z0 < 0 || x0 + 1 >= cols || z0 + 1 >= rows) return 0.0f;
    float tx = g.x - fx, tz = g.y - fz;
    const T* r0 = &level[size_t(z0) * size_t(cols) + size_t(x0)];
    const T* r1 = r0 + cols;
    return float((r0[0] * T(1 - tx) + r0[1] * T(tx)) * T(1 - tz) + (r1[0] * T(1 - tx) + r1[1] * T(tx)) * T(tz));
}

float RipplePatch::heightAt(glm::vec2 world) const {
    return bilinear(height(), rows(), cols(), toGrid(world));  // ewave: its float copy of h
}

float RipplePatch::velocityAt(glm::vec2 world, float dt) const {
    glm::vec2 g = toGrid(world);
    if (m_ewave) return bilinear<double>(m_ewave->velocityState(), rows(), cols(), g);
    float now = bilinear(m_field.current(), m_field.rows(), m_field.cols(), g);
    float before = bilinear(m_field.previous(), m_field.rows(), m_field.cols(), g);
    return (now - before) / dt;
}

bool RipplePatch::stampSphere(const BoundingSphere& sphere, SphereContact& contact, const glm::vec3& centre,
                              const glm::vec3& velocity, float mass, float surfaceY) {
    glm::vec2 g = toGrid(glm::vec2(centre.x, centre.z));
    SphereMotion motion;
    motion.gridX = g.x;
    motion.gridZ = g.y;
    motion.centreY = centre.y;
    motion.verticalVelocity = velocity.y;
    motion.speed = glm::length(velocity);
    motion.mass = mass;
    motion.surfaceY = surfaceY;
    if (m_ewave) {
        RippleStamp stamp;
        const EWaveField& f = *m_ewave;
        if (!planStamp(f.rows(), f.cols(), m_def.cell_size, sphere, contact, motion,
                       [&f](int x, int z) { return f.heightAt(x, z); }, stamp))
            return false;
        m_sources.push_back(ewaveSource(stamp, g.x, g.y, m_def.cell_size, velocity.y));
        return true;
    }
    if (!m_offload) return stepSphere(m_field, m_footprints, m_def.cell_size, sphere, contact, motion);
    RippleStamp stamp;
    if (!planSphereStamp(m_field.current(), m_field.rows(), m_field.cols(), m_def.cell_size, sphere, contact, motion, stamp))
        return false;
    m_offload->stamp(stamp);
    return true;
}

} // namespace ob::interaction
