// The seed 001 Table 5 fish swarm: ballistic jump arcs, Table 2 per fish, batched stamps.
#include "fish_swarm.h"

#include "core/parallel.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

namespace ob::game {

namespace {

constexpr float GRAVITY = 9.81f;  // m/s²
// Fish per parallel chunk: below it a worker costs more than the fish it would take.
constexpr int MIN_FISH_PER_CHUNK = 4096;

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
    m_launchSpeed = std::sqrt(2.0f * GRAVITY * (m_depth + 2.0f * radius));
    const float period = 2.0f * m_launchSpeed / GRAVITY;

    const size_t n = size_t(def.count);
    for (auto* v : {&m_gx, &m_gz, &m_vx, &m_vz, &m_y, &m_vy, &m_surface}) v->resize(n);
    m_contacts.resize(n);
    m_cx.resize(n);
    m_cz.resize(n);
    m_verdict.resize(n);
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
        m_y[i] = -m_depth + m_launchSpeed * t - 0.5f * GRAVITY * t * t;
        m_vy[i] = m_launchSpeed - GRAVITY * t;
    }
}

void FishSwarm::step() {
    const int n = m_def.count;
    // --- the surface each fish sees: y = 0 plus Vh(t) at its centre cell, before any stamp
    const auto t0 = std::chrono::steady_clock::now();
    parallelFor(0, n, MIN_FISH_PER_CHUNK, [this](int b, int e) {
        for (int i = b; i < e; ++i) {
            const int cx = centreCell(m_gx[size_t(i)]), cz = centreCell(m_gz[size_t(i)]);
            const bool inside = cx >= 0 && cx < m_field.cols() && cz >= 0 && cz < m_field.rows();
            m_cx[size_t(i)] = cx;
            m_cz[size_t(i)] = cz;
            m_surface[size_t(i)] = inside ? m_field.currentAt(cx, cz) : 0.0f;
        }
    });
    // --- Table 2 and eq. 3–7, in fish order
    if (m_def.mode == StampMode::Batched) stampBatched();
    else stampSequential();
    m_timings.stamp = msSince(t0);
    // --- move along the arcs
    const auto t1 = std::chrono::steady_clock::now();
    move();
    m_timings.move = msSince(t1);
    // --- convolution
    const auto t2 = std::chrono::steady_clock::now();
    m_field.step(m_def.damping);
    m_timings.step = msSince(t2);
}

void FishSwarm::stampSequential() {
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
}

void FishSwarm::stampBatched() {
    const int n = m_def.count;
    const float radius = m_sphere.radius;
    // Table 2's verdict needs no field read (only eq. 5's base does), so every fish decides
    // at once; the base of a first contact is filled in below, in order.
    parallelFor(0, n, MIN_FISH_PER_CHUNK, [this, radius](int b, int e) {
        for (int i = b; i < e; ++i) {
            interaction::SphereContact& c = m_contacts[size_t(i)];
            const bool wasInContact = c.inContact();
            const bool stamp = interaction::updateContact(c, m_y[size_t(i)], radius, m_surface[size_t(i)], 0.0f);
            m_verdict[size_t(i)] = uint8_t(stamp) | uint8_t(stamp && !wasInContact) << 1;
        }
    });
    // Stamps in fish order; a first contact reads Vh(t) at its centre after every earlier
    // fish's stamp, as stepSphere does.
    const interaction::FootprintProfile& fp = m_cache.get(m_sphere.radius / m_def.cell_size);
    const float shr = m_sphere.heightRatio, cell = m_def.cell_size, af = m_sphere.accelerationFactor;
    const int rows = m_field.rows(), cols = m_field.cols();
    int stamps = 0;
    for (size_t i = 0; i < size_t(n); ++i) {
        const uint8_t verdict = m_verdict[i];
        if (!verdict) continue;
        const int cx = m_cx[i], cz = m_cz[i];
        interaction::SphereContact& c = m_contacts[i];
        if (verdict & 2) {
            const bool inside = cx >= 0 && cx < cols && cz >= 0 && cz < rows;
            c.baseRipple = inside ? m_batch.currentAt(m_field, cx, cz) : 0.0f;
        }
        const float sd = m_vy[i] > 0.0f ? 1.0f : -1.0f;
        m_batch.push(fp, cx, cz, c.baseRipple, sd * shr * cell, af);
        ++stamps;
    }
    m_batch.apply(m_field);
    m_lastStamps = stamps;
}

void FishSwarm::move() {
    const float dt = m_dt, depth = m_depth, launch = m_launchSpeed, edge = float(m_def.field - 1);
    parallelFor(0, m_def.count, MIN_FISH_PER_CHUNK, [&](int b, int e) {
        for (size_t i = size_t(b); i < size_t(e); ++i) {
            // Exact ballistic step; at the launch depth a falling fish turns into a new jump.
            m_y[i] += m_vy[i] * dt - 0.5f * GRAVITY * dt * dt;
            m_vy[i] -= GRAVITY * dt;
            if (m_y[i] < -depth && m_vy[i] < 0.0f) {
                m_y[i] = -2.0f * depth - m_y[i];
                m_vy[i] = launch;
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
    });
}

} // namespace ob::game
