// Surface current layer: the step's stages, the forcing laws and the momentum bookkeeping (the
// law and the layout in current_layer.h; docs/currents.md).
#include "currents/current_layer.h"

#include "currents/current_advection.h"
#include "currents/current_projection.h"
#include "core/simd.h"
#include "core/parallel.h"
#include "core/thread_choice.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace ob::currents {

namespace {

// The wall solve stops at max |∇·u|·Δ ≤ WALL_TOLERANCE × the flow's speed scale (the largest
// face speed, at least MIN_SPEED_SCALE), or after WALL_MAX_ITERATIONS (the rest carries to the
// next step's warm start).
constexpr float WALL_TOLERANCE = 1e-4f;
constexpr float MIN_SPEED_SCALE = 0.01f;  // m/s
constexpr int WALL_MAX_ITERATIONS = 200;
// Grids from this side on have their step's threads measured; smaller ones run on one.
constexpr int PARALLEL_MIN_RESOLUTION = 256;

// Weight of a point r cells from a disc's centre, R cells its radius: 1 inside, a linear edge one
// cell wide centred on the rim (a small or moving disc changes what it covers smoothly).
inline float discWeight(float r, float R) { return std::clamp(0.5f + (R - r), 0.0f, 1.0f); }

// f ← bg + (f − bg)·a over n faces (the decay), after f += shift when `shifted` (a uniform change
// of the background: the same two roundings as the shift's own pass and then the decay's).
OB_VECTOR_KERNEL void decayKernel(float* __restrict f, int n, bool shifted, float shift, float bg, float a) {
    if (shifted)
        for (int i = 0; i < n; ++i) f[i] = bg + ((f[i] + shift) - bg) * a;
    else
        for (int i = 0; i < n; ++i) f[i] = bg + (f[i] - bg) * a;
}

} // namespace

CurrentLayer::CurrentLayer(const CurrentsDef& def, float waterDensity)
    : m_def(def), m_rho(waterDensity), m_grid(ScrollingGrid::centredOn(glm::vec2(0.0f), def.cell_size, def.resolution)) {
    assert(def.resolution >= 4 && def.cell_size > 0.0f && waterDensity > 0.0f);
    const size_t padded = size_t(def.resolution + 2) * size_t(def.resolution + 2);
    m_appliedUniform = def.uniform;
    m_u.assign(padded, def.uniform.x);
    m_v.assign(padded, def.uniform.y);
    m_u0 = m_u;
    m_v0 = m_v;
    m_projection = std::make_unique<CurrentProjection>(def.resolution, def.edge == CurrentEdge::Open);
    m_openCount = glm::dvec2(double(def.resolution) * double(def.resolution));
    m_sum = faceSum();
    chooseThreads();
}

// One thread or two for the open step's advection and projection, measured once per machine and
// size (core/thread_choice.h) from 256² on (below, a hand-off costs more than half the work): on
// scratch copies of the faces, so the state is untouched. The bits do not depend on the choice.
void CurrentLayer::chooseThreads() {
    const int n = m_grid.n;
    if (n < PARALLEL_MIN_RESOLUTION) return;
    const std::string size = std::to_string(n) + "x" + std::to_string(n);
    m_threads = measuredThreads("currents step " + size, std::min(2, workerCount()), [&](int threads) {
        m_projection->setThreads(threads);
        advectFaces(m_u.data(), m_v.data(), m_u0.data(), m_v0.data(), n, m_grid.cell, 1.0f / 60.0f, threads);
        m_projection->projectPeriodic(m_u0.data(), m_v0.data());
    });
    m_projection->setThreads(m_threads);
}

CurrentLayer::~CurrentLayer() = default;

void CurrentLayer::centerOn(glm::vec2 world) {
    join();
    const glm::ivec2 shift = m_grid.centreOn(world);
    if (shift == glm::ivec2(0)) return;
    const int s = m_grid.n + 2;
    const glm::vec2 bg = backgroundNow();
    // The padded arrays scroll whole: what enters from beyond the ring is the background, as the
    // ring itself holds.
    scrollCells(m_u.data(), s, s, shift, bg.x);
    scrollCells(m_v.data(), s, s, shift, bg.y);
    fillGhosts();
    m_projection->scroll(shift);
    m_sum = faceSum();  // what left and what entered
}

void CurrentLayer::setWind(glm::vec2 u10) {
    join();
    m_wind = u10;
}

void CurrentLayer::setWalls(std::span<const interaction::ObstacleShape> shapes) {
    join();
    m_shapes.assign(shapes.begin(), shapes.end());
}

void CurrentLayer::addImpulse(glm::vec2 world, glm::vec2 impulse, float radius) {
    join();
    m_impulses.push_back({world, impulse, radius});
}

void CurrentLayer::retune(const CurrentsDef& def) {
    join();
    m_def.uniform = def.uniform;
    m_def.decay_time = def.decay_time;
    m_def.wind_drift = def.wind_drift;
    m_def.arrows = def.arrows;
}

void CurrentLayer::setFaces(std::span<const float> u, std::span<const float> v) {
    join();
    const int n = m_grid.n;
    assert(u.size() == size_t(n) * size_t(n) && v.size() == u.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m_u[at(i, j)] = u[size_t(j) * size_t(n) + size_t(i)];
            m_v[at(i, j)] = v[size_t(j) * size_t(n) + size_t(i)];
        }
    m_sum = faceSum();
}

// --- the step
void CurrentLayer::step(float dt) {
    if (!m_pipelined) {
        join();
        stepNow(dt);
        return;
    }
    // What the step touches (the faces, the walls, the impulses, the drift, the projection)
    // every other member waits for; the main thread goes on with the ripples meanwhile.
    m_stepTask.start([this, dt] { stepNow(dt); });
}

void CurrentLayer::stepNow(float dt) {
    if (!(dt > 0.0f)) return;
    // --- walls where the grid now stands
    rasteriseWalls();
    // --- forcing: the background's change, wind, decay, sources, impulses (each exact over dt)
    applyForcing(dt);
    fillGhosts();
    if (m_walls) {
        zeroWallFaces();  // what a wall closed over is the wall's
        m_sum = faceSum();
    }
    // --- self-advection, then the global conservative correction: semi-Lagrangian resampling
    // does not keep Σu (neither in the interior, where the bilinear weights of a non-uniform
    // backtrace do not sum to one per source face, nor at the edges, where the ghost ring's
    // background replaces what leaves). The sum before it (m_sum: kept through the forcing, whose
    // every change is known, so no pass sums it) is given back as one uniform velocity over the
    // open faces: a uniform field has no divergence and no shear, so the projection below keeps
    // it, and the layer's momentum changes only by the forcing (and the walls' pressure).
    advectFaces(m_u.data(), m_v.data(), m_u0.data(), m_v0.data(), m_grid.n, m_grid.cell, dt, m_threads);
    m_u.swap(m_u0);
    m_v.swap(m_v0);
    fillGhosts();  // the other buffer's ring
    if (m_walls) zeroWallFaces();
    // An open edge lets momentum leave with the water: no correction (it would put back what left).
    const bool conserve = m_conserve && m_def.edge == CurrentEdge::Periodic;
    glm::dvec2 correction(0.0);
    if (conserve) {
        const glm::dvec2 after = faceSum();
        correction = glm::dvec2(m_openCount.x > 0.0 ? (m_sum.x - after.x) / m_openCount.x : 0.0,
                                m_openCount.y > 0.0 ? (m_sum.y - after.y) / m_openCount.y : 0.0);
    }
    // --- projection: no divergence, no flow through walls
    if (m_walls) {
        addUniform(correction);
        float speed = std::max(glm::length(backgroundNow()), MIN_SPEED_SCALE);
        for (int j = 0; j < m_grid.n; ++j)
            for (int i = 0; i < m_grid.n; ++i) speed = std::max({speed, std::abs(m_u[at(i, j)]), std::abs(m_v[at(i, j)])});
        m_wallSolve = m_projection->projectWithWalls(m_u.data(), m_v.data(), m_solid.data(), WALL_TOLERANCE * speed, WALL_MAX_ITERATIONS);
        if (conserve) m_sum = faceSum();  // the walls' pressure moved momentum
    } else {
        // The correction rides on the gradient's pass (a uniform field adds no divergence); the
        // projection keeps Σu (k = 0), so m_sum stands. Without the correction (the open edge, whose
        // sine transform has no mean mode to keep) nothing reads m_sum: setConserveMomentum sums it anew.
        m_projection->projectPeriodic(m_u.data(), m_v.data(), glm::vec2(correction));
        m_wallSolve = {};
    }
}

// Whether two footprints are the same shape in the same place (field by field: no padding compared).
static bool sameShape(const interaction::ObstacleShape& a, const interaction::ObstacleShape& b) {
    return a.kind == b.kind && a.centre == b.centre && a.axis == b.axis && a.half == b.half && a.displaces == b.displaces &&
           a.hollow == b.hollow;
}

// A cell is a wall where its centre is inside a footprint (rasteriseObstacles' keep < ½). The same
// footprints on the grid where it stood (fixed walls, the common case) give the same mask: kept.
void CurrentLayer::rasteriseWalls() {
    const int n = m_grid.n;
    if (m_rastered && m_rasterOrigin == m_grid.originCell &&
        std::equal(m_shapes.begin(), m_shapes.end(), m_rasterShapes.begin(), m_rasterShapes.end(), sameShape))
        return;
    m_rastered = true;
    m_rasterOrigin = m_grid.originCell;
    m_rasterShapes = m_shapes;
    const bool had = m_walls;
    m_walls = false;
    m_openCount = glm::dvec2(double(n) * double(n));
    if (m_shapes.empty()) {
        if (had) m_projection->clearWarmStart();
        return;
    }
    interaction::rasteriseObstacles(m_shapes, n, n, m_grid.cell, [this](glm::vec2 w) { return m_grid.toGrid(w); }, m_cells);
    m_solid.assign(size_t(n) * size_t(n), 0);
    for (const interaction::ObstructionCell& c : m_cells)
        if (c.keep < 0.5f) m_solid[c.index] = 1, m_walls = true;
    if (!m_walls) {
        if (had) m_projection->clearWarmStart();
        return;
    }
    m_openU.assign(size_t(n) * size_t(n), 0);
    m_openV.assign(size_t(n) * size_t(n), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const size_t c = size_t(j) * size_t(n) + size_t(i);
            const bool open = !m_solid[c];
            m_openU[c] = open && !m_solid[size_t(j) * size_t(n) + size_t((i + 1) % n)];
            m_openV[c] = open && !m_solid[size_t((j + 1) % n) * size_t(n) + size_t(i)];
        }
    m_openCount = glm::dvec2(double(std::count(m_openU.begin(), m_openU.end(), uint8_t(1))),
                             double(std::count(m_openV.begin(), m_openV.end(), uint8_t(1))));
}

void CurrentLayer::applyForcing(float dt) {
    const int n = m_grid.n;
    // --- a retuned background current moves the whole layer (the departures stay)
    if (m_def.uniform != m_appliedUniform) {
        addUniform(glm::dvec2(m_def.uniform - m_appliedUniform));
        m_appliedUniform = m_def.uniform;
    }
    // --- wind: the drift relaxes to wind_drift·U10 in wind_time, d(drift)/dt = (target − drift)/T_w,
    // exactly over dt; the layer takes the drift's change as a uniform acceleration (the wind's
    // stress acts on every cell alike; walls hold it back through the projection)
    const glm::vec2 target = m_def.wind_drift * m_wind;
    const glm::vec2 drift = target + (m_drift - target) * float(std::exp(-double(dt) / double(m_def.wind_time)));
    const bool shifted = drift != m_drift;
    const glm::vec2 shift = drift - m_drift;
    m_drift = drift;
    // --- decay: the departure from the background falls as e^(−t/decay_time) (bottom friction, mixing);
    // without walls the wind's shift rides on its pass (addUniform's sum and additions, then the decay)
    const bool decay = m_def.decay_time > 0.0f;
    if (shifted && (!decay || m_walls)) addUniform(glm::dvec2(shift));
    if (decay) {
        const bool fused = shifted && !m_walls;
        if (fused) m_sum += glm::dvec2(shift) * m_openCount;
        const glm::vec2 bg = backgroundNow();
        const float a = float(std::exp(-double(dt) / double(m_def.decay_time)));
        const glm::dvec2 bgSum = glm::dvec2(bg) * m_openCount;
        m_sum = bgSum + (m_sum - bgSum) * double(a);
        for (int j = 0; j < n; ++j) {
            decayKernel(m_u.data() + at(0, j), n, fused, shift.x, bg.x, a);
            decayKernel(m_v.data() + at(0, j), n, fused, shift.y, bg.y, a);
        }
    }
    // --- sources: u ← s + (u − s)·e^(−w·dt/T) on the faces of the disc, w its soft-edged weight
    for (const CurrentSource& src : m_def.sources) {
        const glm::vec2 g = m_grid.toGrid(src.center);
        const float R = src.radius / m_grid.cell;
        const int x0 = std::max(0, int(std::floor(g.x - R - 1.0f))), x1 = std::min(n - 1, int(std::ceil(g.x + R + 1.0f)));
        const int z0 = std::max(0, int(std::floor(g.y - R - 1.0f))), z1 = std::min(n - 1, int(std::ceil(g.y + R + 1.0f)));
        for (int j = z0; j <= z1; ++j)
            for (int i = x0; i <= x1; ++i) {
                const size_t c = size_t(j) * size_t(n) + size_t(i);
                const float wu = m_walls && !m_openU[c] ? 0.0f : discWeight(glm::length(glm::vec2(float(i) + 0.5f, float(j)) - g), R);
                const float wv = m_walls && !m_openV[c] ? 0.0f : discWeight(glm::length(glm::vec2(float(i), float(j) + 0.5f) - g), R);
                if (wu > 0.0f) {
                    const float f = float(std::exp(-double(wu) * double(dt) / double(src.time)));
                    const float old = m_u[at(i, j)];
                    m_u[at(i, j)] = src.velocity.x + (old - src.velocity.x) * f;
                    m_sum.x += double(m_u[at(i, j)]) - double(old);
                }
                if (wv > 0.0f) {
                    const float f = float(std::exp(-double(wv) * double(dt) / double(src.time)));
                    const float old = m_v[at(i, j)];
                    m_v[at(i, j)] = src.velocity.y + (old - src.velocity.y) * f;
                    m_sum.y += double(m_v[at(i, j)]) - double(old);
                }
            }
    }
    // --- impulses (Newton's third law: what bodies gave back)
    for (const Impulse& imp : m_impulses) depositImpulse(imp);
    m_impulses.clear();
}

// Δu on each open face = J·w/(Σw·ρ·d·Δ²): the weights sum to one over the faces each component
// lives on, so Σ ρ·d·Δ²·Δu = J exactly (up to float rounding).
void CurrentLayer::depositImpulse(const Impulse& imp) {
    const int n = m_grid.n;
    const glm::vec2 g = m_grid.toGrid(imp.world);
    const float R = std::max(imp.radius / m_grid.cell, 1.0f);
    const int x0 = std::max(0, int(std::floor(g.x - R - 1.0f))), x1 = std::min(n - 1, int(std::ceil(g.x + R + 1.0f)));
    const int z0 = std::max(0, int(std::floor(g.y - R - 1.0f))), z1 = std::min(n - 1, int(std::ceil(g.y + R + 1.0f)));
    if (x0 > x1 || z0 > z1) return;
    auto weightU = [&](int i, int j) {
        if (m_walls && !m_openU[size_t(j) * size_t(n) + size_t(i)]) return 0.0f;
        return discWeight(glm::length(glm::vec2(float(i) + 0.5f, float(j)) - g), R);
    };
    auto weightV = [&](int i, int j) {
        if (m_walls && !m_openV[size_t(j) * size_t(n) + size_t(i)]) return 0.0f;
        return discWeight(glm::length(glm::vec2(float(i), float(j) + 0.5f) - g), R);
    };
    double sumU = 0.0, sumV = 0.0;
    for (int j = z0; j <= z1; ++j)
        for (int i = x0; i <= x1; ++i) sumU += weightU(i, j), sumV += weightV(i, j);
    const double faceMass = double(m_rho) * double(m_def.depth) * double(m_grid.cell) * double(m_grid.cell);  // kg
    const double du = sumU > 0.0 ? double(imp.impulse.x) / (sumU * faceMass) : 0.0;
    const double dv = sumV > 0.0 ? double(imp.impulse.y) / (sumV * faceMass) : 0.0;
    for (int j = z0; j <= z1; ++j)
        for (int i = x0; i <= x1; ++i) {
            const float ou = m_u[at(i, j)], ov = m_v[at(i, j)];
            m_u[at(i, j)] = ou + float(du * weightU(i, j));
            m_v[at(i, j)] = ov + float(dv * weightV(i, j));
            m_sum += glm::dvec2(double(m_u[at(i, j)]) - double(ou), double(m_v[at(i, j)]) - double(ov));
        }
}

void CurrentLayer::fillGhosts() {
    const int s = m_grid.n + 2;
    const glm::vec2 bg = backgroundNow();
    for (int k = 0; k < s; ++k) {
        const size_t ring[4] = {size_t(k), size_t(s - 1) * size_t(s) + size_t(k), size_t(k) * size_t(s), size_t(k) * size_t(s) + size_t(s - 1)};
        for (size_t r : ring) m_u[r] = bg.x, m_v[r] = bg.y;
    }
}

void CurrentLayer::zeroWallFaces() {
    const int n = m_grid.n;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const size_t c = size_t(j) * size_t(n) + size_t(i);
            if (!m_openU[c]) m_u[at(i, j)] = 0.0f;
            if (!m_openV[c]) m_v[at(i, j)] = 0.0f;
        }
}

// Σ over the open faces, in double: each row in sixteen interleaved partial sums (a vector's lanes,
// in a fixed order), rows in index order, so the bits do not depend on the workers.
namespace {
OB_VECTOR_KERNEL double rowSum(const float* r, const uint8_t* open, int n) {
    constexpr int LANES = 16;  // four AVX2 vectors of doubles: the adds' latency hidden
    double lane[LANES] = {};
    int i = 0;
    if (open)
        for (; i + LANES <= n; i += LANES)
            for (int l = 0; l < LANES; ++l) lane[l] += double(r[i + l]) * double(open[i + l]);
    else
        for (; i + LANES <= n; i += LANES)
            for (int l = 0; l < LANES; ++l) lane[l] += double(r[i + l]);
    for (; i < n; ++i) lane[0] += double(r[i]) * (open ? double(open[i]) : 1.0);
    double sum = 0.0;
    for (int l = 0; l < LANES; ++l) sum += lane[l];
    return sum;
}
} // namespace

glm::dvec2 CurrentLayer::faceSum() const {
    const int n = m_grid.n;
    double su = 0.0, sv = 0.0;
    for (int j = 0; j < n; ++j) {
        su += rowSum(m_u.data() + at(0, j), m_walls ? m_openU.data() + size_t(j) * size_t(n) : nullptr, n);
        sv += rowSum(m_v.data() + at(0, j), m_walls ? m_openV.data() + size_t(j) * size_t(n) : nullptr, n);
    }
    return {su, sv};
}

void CurrentLayer::addUniform(glm::dvec2 du) {
    const int n = m_grid.n;
    m_sum += du * m_openCount;
    const float dx = float(du.x), dz = float(du.y);
    for (int j = 0; j < n; ++j) {
        float* ur = m_u.data() + at(0, j);
        float* vr = m_v.data() + at(0, j);
        if (!m_walls) {
            for (int i = 0; i < n; ++i) ur[i] += dx, vr[i] += dz;
            continue;
        }
        const uint8_t* ou = m_openU.data() + size_t(j) * size_t(n);
        const uint8_t* ov = m_openV.data() + size_t(j) * size_t(n);
        for (int i = 0; i < n; ++i) {
            if (ou[i]) ur[i] += dx;
            if (ov[i]) vr[i] += dz;
        }
    }
}

// --- queries
glm::vec2 CurrentLayer::flowAt(glm::vec2 world) const {
    join();
    if (!std::isfinite(world.x) || !std::isfinite(world.y)) return glm::vec2(0.0f);  // no point: no flow (never an index)
    const glm::vec2 g = m_grid.toGrid(world);
    const int n = m_grid.n;
    return {samplePadded(m_u.data(), n, g + glm::vec2(0.5f, 1.0f)), samplePadded(m_v.data(), n, g + glm::vec2(1.0f, 0.5f))};
}

glm::vec2 CurrentLayer::velocityAt(glm::vec2 world) const {
    glm::vec2 u = flowAt(world);
    // A 2-D source of outflow q at s moves the water at q/(2π)·r/|r|², r = x − s.
    for (const Displacer& d : m_displacers) {
        const glm::vec2 a = world - d.source, b = world - d.sink;
        const float c2 = d.core * d.core;
        u += d.strength / (2.0f * float(M_PI)) * (a / (glm::dot(a, a) + c2) - b / (glm::dot(b, b) + c2));
    }
    return u;
}

void CurrentLayer::velocityBatch(std::span<const glm::vec2> world, std::span<glm::vec2> out) const {
    assert(out.size() >= world.size());
    for (size_t k = 0; k < world.size(); ++k) out[k] = velocityAt(world[k]);
}

glm::vec2 CurrentLayer::cellVelocity(int i, int j) const {
    join();
    return {0.5f * (m_u[at(i - 1, j)] + m_u[at(i, j)]), 0.5f * (m_v[at(i, j - 1)] + m_v[at(i, j)])};
}

glm::vec2 CurrentLayer::momentum() const {
    join();
    const double faceMass = double(m_rho) * double(m_def.depth) * double(m_grid.cell) * double(m_grid.cell);
    return glm::vec2(faceSum() * faceMass);
}

float CurrentLayer::maxDivergence() const {
    join();
    const int n = m_grid.n;
    std::vector<float> d(size_t(n) * size_t(n));
    m_projection->divergence(m_u.data(), m_v.data(), d.data());
    float worst = 0.0f;
    for (size_t c = 0; c < d.size(); ++c)
        if (!m_walls || !m_solid[c]) worst = std::max(worst, std::abs(d[c]));
    return worst;
}

double CurrentLayer::fluxThrough(std::span<const uint32_t> cells) const {
    join();
    const int n = m_grid.n;
    double flux = 0.0;
    for (uint32_t c : cells) {
        const int i = int(c % uint32_t(n)), j = int(c / uint32_t(n));
        const bool open = m_def.edge == CurrentEdge::Open;  // the west and south edge faces are the ghosts
        flux += std::abs(m_u[at(i, j)]) + std::abs(m_u[at(open ? i - 1 : (i + n - 1) % n, j)]) + std::abs(m_v[at(i, j)]) +
                std::abs(m_v[at(i, open ? j - 1 : (j + n - 1) % n)]);
    }
    return flux * double(m_grid.cell);
}

std::vector<CurrentLevel> CurrentLayer::levels() const {
    join();
    return {{"u", m_u}, {"v", m_v}, {"phi", m_projection->phi()}};
}

bool CurrentLayer::finite() const {
    for (const CurrentLevel& l : levels())
        for (float x : l.values)
            if (!std::isfinite(x)) return false;
    return std::isfinite(m_drift.x) && std::isfinite(m_drift.y);
}

void CurrentLayer::hashState(StateHasher& h) const {
    join();
    h.u64(uint64_t(uint32_t(m_grid.originCell.x)) << 32 | uint32_t(m_grid.originCell.y));
    h.f32s(m_u.data(), m_u.size());
    h.f32s(m_v.data(), m_v.size());
    h.f32s(m_projection->phi().data(), m_projection->phi().size());
    h.f32(m_drift.x);
    h.f32(m_drift.y);
    h.f32(m_appliedUniform.x);
    h.f32(m_appliedUniform.y);
}

} // namespace ob::currents
