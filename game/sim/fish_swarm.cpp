// The [Kang2008] Table 5 fish swarm: ballistic jump arcs, Table 2 per fish, batched stamps.
#include "sim/fish_swarm.h"

#include "core/parallel.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

namespace ob::game {

namespace {

// Fish per chunk of the parallel passes (at most MAX_CHUNKS chunks): below it a worker costs
// more than the fish it would take.
constexpr int FISH_PER_CHUNK = 2048;
constexpr int MAX_CHUNKS = 64;

using Ms = std::chrono::duration<double, std::milli>;
double msSince(std::chrono::steady_clock::time_point t0) { return Ms(std::chrono::steady_clock::now() - t0).count(); }

// stepSphere's centre cell (round half up, clamped so that any position converts safely).
int centreCell(float g) { return int(std::clamp(std::floor(g + 0.5f), -1.0e9f, 1.0e9f)); }

} // namespace

FishSwarm::FishSwarm(const FishSwarmDef& def)
    : m_def(def), m_field(def.field, def.field, interaction::RippleBoundary::Fixed), m_batch(def.field, def.field) {
    assert(def.count >= 0 && def.field >= 3 && def.radius_cells > 0.0f && def.cell_size > 0.0f);
    const float radius = def.radius_cells * def.cell_size;
    m_sphere.radius = radius;
    m_sphere.direction = interaction::SphereDirection::Auto;
    m_sphere.heightRatio = def.height_ratio;
    m_sphere.accelerationFactor = def.acceleration_factor;
    m_dt = 1.0f / def.step_hz;
    m_depth = 2.0f * radius;                                        // launch depth = apex height = 2R
    m_launchSpeed = std::sqrt(2.0f * m_def.gravity * (m_depth + 2.0f * radius));
    const float period = 2.0f * m_launchSpeed / m_def.gravity;

    const size_t n = size_t(def.count);
    for (auto* v : {&m_gx, &m_gz, &m_vx, &m_vz, &m_y, &m_vy, &m_surface}) v->resize(n);
    m_contacts.resize(n);
    m_cx.resize(n);
    m_cz.resize(n);
    m_verdict.resize(n);
    const int chunks = std::clamp(def.count / FISH_PER_CHUNK, 1, MAX_CHUNKS);
    m_chunkStamping.resize(size_t(chunks));
    m_chunkFirst.resize(size_t(chunks));
    m_chunkFirstContacts.resize(size_t(chunks));
    for (int c = 0; c < chunks; ++c) {
        m_chunkStamping[size_t(c)].reserve(chunkBegin(c + 1) - chunkBegin(c));
        m_chunkFirstContacts[size_t(c)].reserve(chunkBegin(c + 1) - chunkBegin(c));
    }
    std::mt19937_64 rng(def.seed);
    std::uniform_real_distribution<float> across(0.0f, float(def.field - 1));
    std::uniform_real_distribution<float> heading(0.0f, 2.0f * std::numbers::pi_v<float>);
    std::uniform_real_distribution<float> speed(0.5f, 2.0f);  // m/s
    std::uniform_real_distribution<float> phase(0.0f, period);
    for (size_t i = 0; i < n; ++i) {
        m_gx[i] = across(rng);
        m_gz[i] = across(rng);
        const float a = heading(rng), s = speed(rng) / def.cell_size;
        m_vx[i] = s * std::cos(a);
        m_vz[i] = s * std::sin(a);
        const float t = phase(rng);
        m_y[i] = -m_depth + m_launchSpeed * t - 0.5f * m_def.gravity * t * t;
        m_vy[i] = m_launchSpeed - m_def.gravity * t;
    }
}

void FishSwarm::step() {
    if (m_def.mode == StampMode::Batched) {
        stepBatched();
        return;
    }
    // --- the surface each fish sees: y = 0 plus Vh(t) at its centre cell, before any stamp
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < size_t(m_def.count); ++i) {
        const int cx = centreCell(m_gx[i]), cz = centreCell(m_gz[i]);
        const bool inside = cx >= 0 && cx < m_field.cols() && cz >= 0 && cz < m_field.rows();
        m_surface[i] = inside ? m_field.currentAt(cx, cz) : 0.0f;
    }
    // --- Table 2 and eq. 3–7 per fish, in order
    int stamps = 0;
    for (size_t i = 0; i < size_t(m_def.count); ++i) {
        interaction::SphereMotion m;
        m.gridX = m_gx[i];
        m.gridZ = m_gz[i];
        m.centreY = m_y[i];
        m.verticalVelocity = m_vy[i];
        m.surfaceY = m_surface[i];
        stamps += interaction::stepSphere(m_field, m_cache, m_def.cell_size, m_sphere, m_contacts[i], m);
    }
    m_lastStamps = stamps;
    m_timings.stamp = msSince(t0);
    // --- move along the arcs
    const auto t1 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < size_t(m_def.count); ++i) moveFish(i);
    m_timings.move = msSince(t1);
    // --- convolution
    const auto t2 = std::chrono::steady_clock::now();
    m_field.step(m_def.damping);
    m_timings.step = msSince(t2);
}

void FishSwarm::stepBatched() {
    const auto t0 = std::chrono::steady_clock::now();
    const int chunks = int(m_chunkStamping.size());
    const float radius = m_sphere.radius;
    // --- per fish, in parallel: the surface it sees, Table 2's verdict, then the move. The
    // verdict needs no field read (only eq. 5's base at a first contact does: filled in below).
    parallelFor(0, chunks, 1, [this, radius](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            std::vector<uint32_t>& stamping = m_chunkStamping[size_t(c)];
            stamping.clear();
            const size_t begin = chunkBegin(c), end = chunkBegin(c + 1);
            // The field reads first, in a loop of their own: Table 2's branches hang on the
            // surface, and waiting for each read there would stall every fish.
            for (size_t i = begin; i < end; ++i) {
                const int cx = centreCell(m_gx[i]), cz = centreCell(m_gz[i]);
                const bool inside = cx >= 0 && cx < m_field.cols() && cz >= 0 && cz < m_field.rows();
                m_cx[i] = cx;
                m_cz[i] = cz;
                m_surface[i] = inside ? m_field.currentAt(cx, cz) : 0.0f;
            }
            for (size_t i = begin; i < end; ++i) {
                interaction::SphereContact& contact = m_contacts[i];
                const bool wasInContact = contact.inContact();
                const bool stamp = interaction::updateContact(contact, m_y[i], radius, m_surface[i], 0.0f);
                m_verdict[i] = uint8_t(!wasInContact) << 1 | uint8_t(m_vy[i] > 0.0f) << 2;
                if (stamp) stamping.push_back(uint32_t(i));  // capacity: the chunk's fish
                moveFish(i);
            }
        }
    });
    // --- the stamps, in fish order: chunk c's go after every earlier chunk's
    const interaction::FootprintProfile& fp = m_cache.get(m_sphere.radius / m_def.cell_size);
    size_t total = 0;
    for (int c = 0; c < chunks; ++c) {
        m_chunkFirst[size_t(c)] = total;
        total += m_chunkStamping[size_t(c)].size();
    }
    const size_t first = m_batch.grow(total);
    const float shr = m_sphere.heightRatio, cell = m_def.cell_size, af = m_sphere.accelerationFactor;
    parallelFor(0, chunks, 1, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            size_t k = first + m_chunkFirst[size_t(c)];
            std::vector<std::pair<uint32_t, uint32_t>>& firsts = m_chunkFirstContacts[size_t(c)];
            firsts.clear();
            for (const uint32_t i : m_chunkStamping[size_t(c)]) {
                const uint8_t verdict = m_verdict[i];
                if (verdict & 2) firsts.emplace_back(uint32_t(k), i);
                const float sd = verdict & 4 ? 1.0f : -1.0f;
                m_batch.set(k++, fp, m_cx[i], m_cz[i], m_contacts[i].baseRipple, sd * shr * cell, af);
            }
        }
    });
    // --- first contacts, in order: eq. 5's base is Vh(t) at the centre after every earlier
    // fish's stamp, as stepSphere reads it
    const int rows = m_field.rows(), cols = m_field.cols();
    for (int c = 0; c < chunks; ++c)
        for (const auto& [k, i] : m_chunkFirstContacts[size_t(c)]) {
            const int cx = m_cx[i], cz = m_cz[i];
            const bool inside = cx >= 0 && cx < cols && cz >= 0 && cz < rows;
            const float base = inside ? m_batch.currentAt(m_field, cx, cz, k) : 0.0f;
            m_contacts[i].baseRipple = base;
            m_batch.setBase(k, base);
        }
    m_batch.apply(m_field);
    m_lastStamps = int(total);
    m_timings.stamp = msSince(t0);
    m_timings.move = 0.0;  // inside the pass above
    // --- convolution
    const auto t2 = std::chrono::steady_clock::now();
    m_field.step(m_def.damping);
    m_timings.step = msSince(t2);
}

inline void FishSwarm::moveFish(size_t i) {
    const float dt = m_dt, edge = float(m_def.field - 1);
    // Exact ballistic step; at the launch depth a falling fish turns into a new jump.
    m_y[i] += m_vy[i] * dt - 0.5f * m_def.gravity * dt * dt;
    m_vy[i] -= m_def.gravity * dt;
    if (m_y[i] < -m_depth && m_vy[i] < 0.0f) {
        m_y[i] = -2.0f * m_depth - m_y[i];
        m_vy[i] = m_launchSpeed;
    }
    // Swim in the heading, bouncing off the field's edges.
    m_gx[i] += m_vx[i] * dt;
    m_gz[i] += m_vz[i] * dt;
    if (m_gx[i] < 0.0f || m_gx[i] > edge) {
        m_gx[i] = std::clamp(m_gx[i] < 0.0f ? -m_gx[i] : 2.0f * edge - m_gx[i], 0.0f, edge);
        m_vx[i] = -m_vx[i];
    }
    if (m_gz[i] < 0.0f || m_gz[i] > edge) {
        m_gz[i] = std::clamp(m_gz[i] < 0.0f ? -m_gz[i] : 2.0f * edge - m_gz[i], 0.0f, edge);
        m_vz[i] = -m_vz[i];
    }
}

} // namespace ob::game
