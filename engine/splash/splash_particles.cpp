// Splash particles: emission laws, the exact linear-drag flight, landings (laws in the header).
#include "splash/splash_particles.h"

#include "core/hash.h"
#include "core/parallel.h"
#include "core/random.h"
#include "core/simd.h"
#include "interaction/ripple_patch.h"
#include "water/water_query.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <glm/geometric.hpp>

namespace ob::splash {

namespace {

constexpr float DEG = std::numbers::pi_v<float> / 180.0f;
// Drops per parallelFor chunk: a chunk's flight is ~10 µs, enough to pay for a hand-off.
constexpr int FLIGHT_CHUNK = 16384;

// One step of the exact linear-drag flight for drops [begin, end): v ← a·v − g·b·ŷ,
// x ← x + b·v − g·c·ŷ (old v), age += dt. Element-wise, so any split gives the same bits.
OB_VECTOR_KERNEL void flyKernel(float* __restrict x, float* __restrict y, float* __restrict z, float* __restrict vx,
                                float* __restrict vy, float* __restrict vz, float* __restrict age, int begin, int end,
                                float a, float b, float gb, float gc, float dt) {
    for (int i = begin; i < end; ++i) {
        const float ux = vx[i], uy = vy[i], uz = vz[i];
        x[i] += b * ux;
        y[i] += b * uy - gc;
        z[i] += b * uz;
        vx[i] = a * ux;
        vy[i] = a * uy - gb;
        vz[i] = a * uz;
        age[i] += dt;
    }
}

} // namespace

Crossing SurfaceCrossing::update(float centreY, float radius, float surfaceY) {
    const bool below = centreY - radius <= surfaceY;
    const bool known = m_known;
    const bool wasBelow = m_below;
    m_known = true;
    m_below = below;
    if (!known || below == wasBelow) return Crossing::None;
    return below ? Crossing::Entry : Crossing::Exit;
}

float impactNormalSpeed(const Impact& impact) {
    const glm::vec3 relative = impact.velocity - glm::vec3(0.0f, impact.surfaceVelocity, 0.0f);
    return std::abs(glm::dot(relative, impact.surfaceNormal));
}

int impactDropCount(const Impact& impact, const SplashDef& def) {
    const double vn = impactNormalSpeed(impact);
    if (vn < def.min_speed || vn <= 0.0 || impact.mass <= 0.0f) return 0;
    const double energy = 0.5 * double(impact.mass) * vn * vn;  // J
    const double n = std::floor(double(def.emission_scale) * DROPS_PER_SQRT_JOULE * std::sqrt(energy));
    return int(std::min(n, 1e9));
}

float crownHeight(const Impact& impact, float gravity) {
    // H = R·sqrt(Fr) with Fr = v_n²/(g·R), i.e. v_n·sqrt(R/g).
    return impactNormalSpeed(impact) * std::sqrt(std::max(impact.radius, 0.0f) / gravity);
}

float crownSpeed(const Impact& impact, float gravity) { return std::sqrt(2.0f * gravity * crownHeight(impact, gravity)); }

SplashParticles::SplashParticles(const SplashDef& def, uint64_t seed) : m_def(def), m_rng(seed) {}

float SplashParticles::uniform() { return uniform01f(m_rng); }

bool SplashParticles::push(const glm::vec3& p, const glm::vec3& v, float r, bool spray) {
    if (size() >= m_def.max_particles) return false;
    m_x.push_back(p.x);
    m_y.push_back(p.y);
    m_z.push_back(p.z);
    m_vx.push_back(v.x);
    m_vy.push_back(v.y);
    m_vz.push_back(v.z);
    m_age.push_back(0.0f);
    m_radius.push_back(r);
    m_spray.push_back(uint8_t(spray));
    ++m_stats.emitted;
    m_stats.spray += uint64_t(spray);
    return true;
}

int SplashParticles::emitImpact(const Impact& impact) {
    const int n = impactDropCount(impact, m_def);
    if (n <= 0) return 0;
    const float uc = crownSpeed(impact, m_def.environment.gravity);
    const bool exit = impact.kind == Crossing::Exit;
    const float elevationLo = (exit ? 75.0f : 60.0f) * DEG, elevationSpan = (exit ? 14.0f : 20.0f) * DEG;
    const glm::vec3 carry = TANGENT_CARRY * glm::vec3(impact.velocity.x, 0.0f, impact.velocity.z);
    // Draws in a fixed order per drop (azimuth jitter, speed, elevation, radius): separate
    // statements, since the order of a call's arguments is unspecified.
    for (int k = 0; k < n; ++k) {
        const float phi = 2.0f * std::numbers::pi_v<float> * (float(k) + uniform()) / float(n);
        const float speed = uc * (0.5f + 0.5f * uniform());
        const float elevation = elevationLo + elevationSpan * uniform();
        const float r = m_def.drop_size * (0.5f + uniform());
        const float c = std::cos(phi), s = std::sin(phi);
        const float out = speed * std::cos(elevation), up = speed * std::sin(elevation);
        const glm::vec3 p(impact.centre.x + impact.radius * c, impact.surfaceHeight, impact.centre.z + impact.radius * s);
        if (!push(p, glm::vec3(out * c, up, out * s) + carry, r)) {
            m_stats.dropped += uint64_t(n - k);
            return k;
        }
    }
    return n;
}

int SplashParticles::emitBowSpray(const glm::vec3& centre, const glm::vec3& velocity, float radius, float dt) {
    const glm::vec3 horizontal(velocity.x, 0.0f, velocity.z);
    const float u = glm::length(horizontal);
    if (u <= m_def.bow_speed || dt <= 0.0f) return 0;
    const float rate = m_def.emission_scale * BOW_DROPS_PER_SECOND * radius * radius * (u / m_def.bow_speed - 1.0f);
    const int n = int(std::floor(rate * dt + uniform()));  // stochastic rounding: the mean is rate·dt
    const glm::vec3 heading = horizontal / u;
    const glm::vec3 side(-heading.z, 0.0f, heading.x);
    const glm::vec3 front = centre + radius * heading;
    for (int k = 0; k < n; ++k) {
        const float sign = uniform() < 0.5f ? -1.0f : 1.0f;
        const float elevation = (30.0f + 30.0f * uniform()) * DEG;
        const float speed = 0.6f * u * (0.5f + 0.5f * uniform());
        const float r = m_def.drop_size * (0.5f + uniform());
        // Thrown half forward, mostly sideways (60° off the heading), plus half the hull's velocity.
        const glm::vec3 across = 0.5f * heading + 0.8660254f * sign * side;
        const glm::vec3 v = across * (speed * std::cos(elevation)) + glm::vec3(0.0f, speed * std::sin(elevation), 0.0f) +
                            0.5f * horizontal;
        if (!push(front, v, r)) {
            m_stats.dropped += uint64_t(n - k);
            return k;
        }
    }
    return n;
}

int SplashParticles::emitWindSpray(std::span<const glm::vec2> crests, float crestArea, glm::vec2 wind, float dt,
                                   const water::WaterQuery& water) {
    const float u = glm::length(wind);
    if (u <= m_def.spray_wind || crests.empty() || dt <= 0.0f) return 0;
    m_air = SPRAY_AIR_FRACTION * wind;
    const float area = crestArea * float(crests.size());
    const float rate = m_def.emission_scale * SPRAY_DROPS_PER_M2_SECOND * area * (u / m_def.spray_wind - 1.0f);
    const float wanted = std::floor(rate * dt + uniform());  // stochastic rounding: the mean is rate·dt
    const int n = int(std::min(wanted, float(m_def.spray_per_step)));
    const glm::vec2 downwind = wind / u;
    const float half = 0.5f * std::sqrt(crestArea);
    for (int k = 0; k < n; ++k) {
        // Draws in a fixed order per drop: crest, offset in its cell (x, z), azimuth, speed, rise, radius.
        const size_t c = std::min(size_t(uniform() * float(crests.size())), crests.size() - 1);
        const float ox = half * (2.0f * uniform() - 1.0f);
        const float oz = half * (2.0f * uniform() - 1.0f);
        const float turn = 20.0f * DEG * (2.0f * uniform() - 1.0f);
        const float speed = u * (0.2f + 0.3f * uniform());
        const float rise = 1.0f + 2.0f * uniform();
        const float r = m_def.drop_size * (0.5f + uniform());
        const glm::vec2 at = crests[c] + glm::vec2(ox, oz);
        const float ct = std::cos(turn), st = std::sin(turn);
        const glm::vec2 dir(ct * downwind.x - st * downwind.y, st * downwind.x + ct * downwind.y);
        const glm::vec3 p(at.x, water.sample(at.x, at.y).height, at.y);
        if (!push(p, glm::vec3(speed * dir.x, rise, speed * dir.y), r, true)) {
            m_stats.dropped += uint64_t(n - k);
            return k;
        }
    }
    return n;
}

// The wind's share of the spray drops' flight: by linearity of dv/dt = −g·ŷ − k·(v − w), the
// still-air step plus (1 − a)·w to v and (Δt − b)·w to x (the other drops keep their bits).
void SplashParticles::blowSpray(float dt, float a, float b) {
    if (m_stats.spray == 0) return;
    const float dv = 1.0f - a, dx = dt - b;
    for (size_t i = 0; i < m_spray.size(); ++i) {
        if (!m_spray[i]) continue;
        m_vx[i] += dv * m_air.x;
        m_vz[i] += dv * m_air.y;
        m_x[i] += dx * m_air.x;
        m_z[i] += dx * m_air.y;
    }
}

void SplashParticles::step(float dt, const water::WaterQuery& water, float ceiling) {
    m_landings.clear();
    const int n = size();
    if (n == 0) return;

    // --- flight: the exact solution of dv/dt = −g·ŷ − k·v over dt (coefficients in double)
    const double k = m_def.drag, t = dt, kt = k * t, g = m_def.environment.gravity;
    double a, b, c;
    if (kt < 1e-4) {  // series: (1 − e^(−kt))/k and (t − b)/k lose every digit as k → 0
        a = std::exp(-kt);
        b = t * (1.0 - kt / 2.0 + kt * kt / 6.0);
        c = t * t * (0.5 - kt / 6.0 + kt * kt / 24.0);
    } else {
        a = std::exp(-kt);
        b = -std::expm1(-kt) / k;
        c = (t - b) / k;
    }
    const float fa = float(a), fb = float(b), gb = float(g * b), gc = float(g * c);
    float *x = m_x.data(), *y = m_y.data(), *z = m_z.data(), *vx = m_vx.data(), *vy = m_vy.data(), *vz = m_vz.data(),
          *age = m_age.data();
    parallelFor(0, n, FLIGHT_CHUNK,
                [&](int lo, int hi) { flyKernel(x, y, z, vx, vy, vz, age, lo, hi, fa, fb, gb, gc, dt); });
    blowSpray(dt, fa, fb);

    // --- landing candidates: descending drops below the ceiling
    m_dead.assign(size_t(n), 0);
    m_candidates.clear();
    m_candidateXZ.clear();
    for (int i = 0; i < n; ++i) {
        if (vy[i] < 0.0f && y[i] < ceiling) {
            m_candidates.push_back(i);
            m_candidateXZ.emplace_back(x[i], z[i]);
        }
    }

    // --- landings: at or below the water; the crossing point found back along the velocity
    if (!m_candidates.empty()) {
        m_samples.resize(m_candidates.size());
        water.sampleBatch(m_candidateXZ, m_samples);
        for (size_t c2 = 0; c2 < m_candidates.size(); ++c2) {
            const int i = m_candidates[c2];
            const float h = m_samples[c2].height;
            if (y[i] > h) continue;
            const float back = std::max((h - y[i]) / vy[i], -dt);  // s ≤ 0: time since it crossed
            Landing l;
            l.position = glm::vec3(x[i] + vx[i] * back, h, z[i] + vz[i] * back);
            l.velocity = glm::vec3(vx[i], vy[i], vz[i]);
            l.radius = m_radius[size_t(i)];
            l.mass = m_def.environment.water_density * (4.0f / 3.0f) * std::numbers::pi_v<float> * l.radius * l.radius * l.radius;
            m_landings.push_back(l);
            m_dead[size_t(i)] = 1;
        }
        m_stats.landed += m_landings.size();
    }

    // --- expiry: still airborne after max_life
    const float maxLife = m_def.max_life;
    for (int i = 0; i < n; ++i) {
        if (!m_dead[size_t(i)] && age[i] >= maxLife) {
            m_dead[size_t(i)] = 2;
            ++m_stats.expired;
        }
    }
    removeDead();
}

void SplashParticles::removeDead() {
    const size_t n = m_x.size();
    size_t first = 0;
    while (first < n && !m_dead[first]) ++first;
    if (first == n) return;
    // Stable compaction: drop order (and so the hash and the landings' order) is emission order.
    std::vector<float>* arrays[] = {&m_x, &m_y, &m_z, &m_vx, &m_vy, &m_vz, &m_age, &m_radius};
    for (std::vector<float>* arr : arrays) {
        float* d = arr->data();
        size_t w = first;
        for (size_t i = first; i < n; ++i)
            if (!m_dead[i]) d[w++] = d[i];
        arr->resize(w);
    }
    size_t w = first;
    for (size_t i = first; i < n; ++i)
        if (!m_dead[i]) m_spray[w++] = m_spray[i];
    m_spray.resize(w);
}

void SplashParticles::clear() {
    for (std::vector<float>* arr : {&m_x, &m_y, &m_z, &m_vx, &m_vy, &m_vz, &m_age, &m_radius}) arr->clear();
    m_spray.clear();
    m_landings.clear();
}

void SplashParticles::hash(StateHasher& h) const {
    h.u64(uint64_t(m_x.size()));
    for (const std::vector<float>* arr : {&m_x, &m_y, &m_z, &m_vx, &m_vy, &m_vz, &m_age, &m_radius})
        h.f32s(arr->data(), arr->size());
    h.u64(m_rng);
    h.u64(m_stats.emitted);
    h.u64(m_stats.dropped);
    h.u64(m_stats.landed);
    h.u64(m_stats.expired);
    if (m_stats.spray > 0) {  // a sea that never sprayed hashes as before there was spray
        h.u64(m_stats.spray);
        h.bytes(m_spray.data(), m_spray.size());
        h.f32s(&m_air.x, 2);
    }
}

double stampLandings(interaction::RipplePatch& patch, std::span<const Landing> landings, float energyFraction) {
    // The drop's crater goes into the height of whichever solver runs (kang2008: Vh(t); ewave: h),
    // and with ewave levels into every coarse level that holds it (the same volume).
    const double cell = patch.def().cell_size, area = cell * cell;
    const environment::EnvironmentDef& env = patch.def().environment;
    double total = 0.0;
    for (const Landing& l : landings) {
        const double s2 = double(glm::dot(l.velocity, l.velocity));
        const double energy = double(energyFraction) * 0.5 * double(l.mass) * s2;  // J
        const double depth = std::sqrt(2.0 * energy / (double(env.water_density) * env.gravity * area));  // m
        if (patch.addCrater(glm::vec2(l.position.x, l.position.z), -depth * area)) total += energy;
    }
    return total;
}

} // namespace ob::splash
