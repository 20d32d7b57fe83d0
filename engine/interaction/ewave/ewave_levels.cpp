// Nested ewave levels: placement, sources, the strided steps and the Hermite read in time.
#include "interaction/ewave/ewave_levels.h"

#include "interaction/ripple_def.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace ob::interaction {

float levelWeight(glm::vec2 g, int n, int sponge) {
    const float band = float(std::max(sponge, 1));
    auto axis = [&](float x) {
        const float d = std::min(x, float(n - 1) - x);
        const float s = std::clamp((d - band) / band, 0.0f, 1.0f);
        return s * s * (3.0f - 2.0f * s);
    };
    return axis(g.x) * axis(g.y);
}

EWaveLevels::EWaveLevels(const RippleDef& def) : m_sponge(def.sponge_width), m_cell0(def.cell_size) {
    assert(def.levels >= 2);
    const EWaveMedium medium = EWaveMedium::of(def.environment, def.depth);
    const int n = def.resolution;
    float cell = def.cell_size;
    int stride = 1;
    m_levels.resize(size_t(def.levels - 1));
    for (int L = 1; L < def.levels; ++L) {
        cell *= float(RATIO);
        stride *= RATIO;
        Level& lv = m_levels[size_t(L - 1)];
        lv.grid = ScrollingGrid::centredOn(def.center, cell, n);
        lv.solver = std::make_unique<EWaveSolver>(n, cell, def, medium, def.boundary, def.sponge_width);
        lv.stride = stride;
        // The still water counts as level L's state at frame L, so its first step is at frame
        // L + 1 and no two levels step on the same frame while 4^L > L.
        lv.b = L;
        lv.a = L - stride;
        for (auto* f : {&lv.h0, &lv.v0, &lv.h1, &lv.v1, &lv.shown}) f->assign(size_t(n) * size_t(n), 0.0f);
        for (int a = 0; a < 2; ++a)
            for (auto* f : {&lv.x0[a], &lv.u0[a], &lv.x1[a], &lv.u1[a]}) f->assign(size_t(n) * size_t(n), 0.0f);
        lv.solver->field().keepHorizontalDisplacement(true);  // the Hermite of u reads ξ
    }
    m_sponge = m_levels.front().solver->field().spongeWidth();  // as the field clamps it
}

EWaveLevels::~EWaveLevels() = default;

namespace {

// scrollCells with the new cells at f's mean and the sum (in double) put back as a uniform
// shift: EWaveField::scroll on a float copy.
void scrollKeepingSum(std::vector<float>& f, int n, glm::ivec2 shift) {
    auto sum = [&f] {
        double s = 0.0;
        for (float x : f) s += double(x);
        return s;
    };
    const double before = sum(), cells = double(f.size());
    scrollCells(f.data(), n, n, shift, float(before / cells));
    const float back = float((before - sum()) / cells);
    for (float& x : f) x += back;
}

} // namespace

// The solver's state as the Hermite's end at b: h's float copy, and v less its mean. v's mean is
// no motion (the step drops it: the volume is kept), but the sponge and a scroll leave some
// there; in the Hermite's S·v terms it would move the level's mean between two states.
void EWaveLevels::keepState(Level& lv) {
    const std::span<const float> h = lv.solver->height();
    std::copy(h.begin(), h.end(), lv.h1.begin());
    const std::span<const double> v = lv.solver->field().velocityState();
    double mean = 0.0;
    for (double x : v) mean += x;
    mean /= double(v.size());
    std::transform(v.begin(), v.end(), lv.v1.begin(), [mean](double x) { return float(x - mean); });
    const EWaveField& f = lv.solver->field();
    for (int a = 0; a < 2; ++a) {
        std::copy(f.horizontalDisplacement(a).begin(), f.horizontalDisplacement(a).end(), lv.x1[a].begin());
        std::copy(f.horizontalVelocity(a).begin(), f.horizontalVelocity(a).end(), lv.u1[a].begin());
    }
}

void EWaveLevels::centerOn(glm::vec2 world) {
    for (Level& lv : m_levels) {
        const glm::ivec2 shift = lv.grid.centreOn(world);
        if (shift == glm::ivec2(0)) continue;
        // The state at b keeps its volume (EWaveField::scroll); its copies follow it, and the
        // state at a is scrolled the same way: new cells at its mean level (v at 0), what left
        // put back uniformly, so the Hermite between them keeps the level's mean too.
        lv.solver->scroll(shift);
        keepState(lv);
        scrollKeepingSum(lv.h0, lv.grid.n, shift);
        scrollCells(lv.v0.data(), lv.grid.n, lv.grid.n, shift);
        double v0 = 0.0;  // its mean back to 0, as keepState's
        for (float x : lv.v0) v0 += double(x);
        const float back = float(v0 / double(lv.v0.size()));
        for (float& x : lv.v0) x -= back;
        for (int a = 0; a < 2; ++a) {  // derived, mean 0: new cells 0
            scrollCells(lv.x0[a].data(), lv.grid.n, lv.grid.n, shift);
            scrollCells(lv.u0[a].data(), lv.grid.n, lv.grid.n, shift);
        }
        lv.shownFrame = -1;
    }
}

float EWaveLevels::weightAt(int L, glm::vec2 world) const {
    if (L == count() - 1) return 1.0f;  // the coarsest: what it holds, 0 off its grid
    return levelWeight(grid(L).toGrid(world), grid(L).n, m_sponge);
}

int EWaveLevels::finestAt(glm::vec2 world) const {
    for (int L = 1; L < count() - 1; ++L)
        if (weightAt(L, world) > 0.0f) return L;
    return count() - 1;
}

void EWaveLevels::pushSource(glm::vec2 centre, float radius, float accel, int from) {
    for (int L = std::max(from, 1); L < count(); ++L) m_levels[size_t(L - 1)].queued.push_back({centre, radius, accel * radius * radius});
}

bool EWaveLevels::addCrater(glm::vec2 world, double volume, int from) {
    bool held = false;
    for (int L = std::max(from, 1); L < count(); ++L) {
        Level& lv = m_levels[size_t(L - 1)];
        const glm::vec2 g = lv.grid.toGrid(world);
        if (!(g.x >= 0.0f && g.y >= 0.0f && g.x <= float(lv.grid.n - 1) && g.y <= float(lv.grid.n - 1))) continue;
        lv.craters.push_back({world, volume});
        held = true;
    }
    return held;
}

bool EWaveLevels::stampSphere(const BoundingSphere& sphere, SphereContact& contact, SphereMotion motion, glm::vec2 centre) {
    const int L = finestAt(centre);
    const Level& lv = level(L);
    const glm::vec2 g = lv.grid.toGrid(centre);
    motion.gridX = g.x;
    motion.gridZ = g.y;
    EWaveSource s;
    if (!lv.solver->planSource(sphere, contact, motion, s)) return false;
    // The source as level 0 would make it, radius max(r, Δ₀): planned here its radius is
    // max(r, Δ_L), and with the same accel a sphere smaller than this level's cell would push
    // (Δ_L/max(r, Δ₀))² times too hard (16 times for a 1 m sphere on 4 m cells). pushSource
    // then widens it to this level's cell keeping ∫a·w dA. (The stagnation term of accel is
    // this level's, v²/(2·max(r, Δ_L)): smaller, for a body moving up or down only.)
    pushSource(centre, std::max(s.radiusCells * lv.grid.cell, m_cell0), s.accel, L);
    return true;
}

void EWaveLevels::step(float dt, std::span<const ObstacleShape> obstacles) {
    ++m_frame;
    m_dt = dt;
    for (Level& lv : m_levels)
        if (m_frame > lv.b) stepLevel(lv, dt, obstacles);
}

// One step of the level over stride·dt from frame b. Its queued sources, each a frame's push,
// are applied over the whole step at 1/stride of their accel: the same impulse, at most one
// step early or late (a 5 m/s ship moves 1.3 m in level 2's 16 frames, under its 3–4 m cell).
void EWaveLevels::stepLevel(Level& lv, float dt, std::span<const ObstacleShape> obstacles) {
    const float cell = lv.grid.cell;
    for (const WorldSource& ws : lv.queued) {
        const glm::vec2 g = lv.grid.toGrid(ws.centre);
        const float r = std::max(ws.radius / cell, 1.0f);  // cells; ∫w dA = π(r·cell)²/3 keeps strength
        lv.solver->addSource({g.x, g.y, r, ws.strength / (r * cell * r * cell) / float(lv.stride)});
    }
    lv.queued.clear();
    // Craters: into the state at b and its copy (they appear at frame b + 1, at most one step
    // late, as level 0's would at its next step), their volume taken back by the solver's step.
    const int n = lv.grid.n;
    double craterVolume = 0.0;
    for (const WorldCrater& c : lv.craters) {
        const glm::vec2 g = lv.grid.toGrid(c.centre);
        if (!(g.x >= 0.0f && g.y >= 0.0f && g.x <= float(n - 1) && g.y <= float(n - 1))) continue;  // scrolled off since
        const int x0 = std::min(int(std::floor(g.x)), n - 2), z0 = std::min(int(std::floor(g.y)), n - 2);
        const double fx = double(g.x) - x0, fz = double(g.y) - z0, depth = c.volume / (double(cell) * double(cell));
        const double w[4] = {(1 - fx) * (1 - fz), fx * (1 - fz), (1 - fx) * fz, fx * fz};
        for (int k = 0; k < 4; ++k) {
            const int x = x0 + (k & 1), z = z0 + (k >> 1);
            lv.solver->addHeight(x, z, depth * w[k]);
            lv.h1[size_t(z) * size_t(n) + size_t(x)] += float(depth * w[k]);
        }
        craterVolume += depth;
    }
    lv.craters.clear();
    if (craterVolume != 0.0 && lv.solver->field().boundary() != RippleBoundary::Fixed) {
        const float back = float(-craterVolume / (double(n) * double(n)));
        for (float& x : lv.h1) x += back;  // as the solver's step will (the Hermite's start keeps the mean)
    }
    if (!obstacles.empty() || !lv.obstruction.empty()) {
        rasteriseObstacles(obstacles, lv.grid.n, lv.grid.n, cell, [&lv](glm::vec2 w) { return lv.grid.toGrid(w); },
                           lv.obstruction);
        lv.solver->setObstruction(lv.obstruction);
    }
    std::swap(lv.h0, lv.h1);
    std::swap(lv.v0, lv.v1);
    for (int a = 0; a < 2; ++a) {
        std::swap(lv.x0[a], lv.x1[a]);
        std::swap(lv.u0[a], lv.u1[a]);
    }
    lv.solver->step(dt * float(lv.stride));
    keepState(lv);
    lv.a = lv.b;
    lv.b += lv.stride;
}

namespace {

// The cubic Hermite basis at p ∈ [0, 1] (h00, h10, h01, h11) and its derivative in p.
struct Hermite {
    float h00, h10, h01, h11;
    static Hermite at(float p) {
        const float p2 = p * p, p3 = p2 * p;
        return {2 * p3 - 3 * p2 + 1, p3 - 2 * p2 + p, -2 * p3 + 3 * p2, p3 - p2};
    }
    static Hermite slope(float p) {
        const float p2 = p * p;
        return {6 * p2 - 6 * p, 3 * p2 - 4 * p + 1, -6 * p2 + 6 * p, 3 * p2 - 2 * p};
    }
};

} // namespace

// h(t) between the states at frames a and b (p = (frame − a)/stride, S = stride·dt seconds):
// h00·h_a + h10·S·v_a + h01·h_b + h11·S·v_b, exact at both ends in h and v; for a wave of
// ω·S = 0.8 rad (level 2's shortest) its error is under (ωS)⁴/384 ≈ 0.1% of the amplitude.
// Made only when asked (the renderer, once a frame): the simulation reads pointwise.
std::span<const float> EWaveLevels::height(int L) const {
    const Level& lv = level(L);
    if (lv.shownFrame != m_frame) {
        const Hermite w = Hermite::at(phase(lv));
        const float s = m_dt * float(lv.stride);
        const float a0 = w.h00, a1 = w.h01, b0 = w.h10 * s, b1 = w.h11 * s;
        for (size_t i = 0; i < lv.shown.size(); ++i) lv.shown[i] = a0 * lv.h0[i] + a1 * lv.h1[i] + b0 * lv.v0[i] + b1 * lv.v1[i];
        lv.shownFrame = m_frame;
    }
    return lv.shown;
}

float EWaveLevels::heightAt(int L, glm::vec2 world) const {
    const Level& lv = level(L);
    const glm::vec2 g = lv.grid.toGrid(world);
    const int n = lv.grid.n;
    const Hermite w = Hermite::at(phase(lv));
    const float s = m_dt * float(lv.stride);
    return w.h00 * bilinear<float>(lv.h0, n, n, g) + w.h01 * bilinear<float>(lv.h1, n, n, g) +
           s * (w.h10 * bilinear<float>(lv.v0, n, n, g) + w.h11 * bilinear<float>(lv.v1, n, n, g));
}

float EWaveLevels::velocityAt(int L, glm::vec2 world) const {
    const Level& lv = level(L);
    const float s = m_dt * float(lv.stride);
    if (s <= 0.0f) return 0.0f;
    const glm::vec2 g = lv.grid.toGrid(world);
    const int n = lv.grid.n;
    const Hermite w = Hermite::slope(phase(lv));
    return (w.h00 * bilinear<float>(lv.h0, n, n, g) + w.h01 * bilinear<float>(lv.h1, n, n, g)) / s +
           w.h10 * bilinear<float>(lv.v0, n, n, g) + w.h11 * bilinear<float>(lv.v1, n, n, g);
}

// The same Hermite slope as velocityAt, on ξ and u: ξ = R[h] and u = R[v] = ∂ξ/∂t with R the
// per-mode i·K/(|K|·tanh(|K|d)), linear and the same at both ends, so this is R of velocityAt's
// v(t) (the craters a step adds reach ξ with the step after: one coarse step late at most).
glm::vec2 EWaveLevels::horizontalVelocityAt(int L, glm::vec2 world) const {
    const Level& lv = level(L);
    const float s = m_dt * float(lv.stride);
    if (s <= 0.0f) return {0.0f, 0.0f};
    const glm::vec2 g = lv.grid.toGrid(world);
    const int n = lv.grid.n;
    const Hermite w = Hermite::slope(phase(lv));
    glm::vec2 u;
    for (int a = 0; a < 2; ++a)
        u[a] = (w.h00 * bilinear<float>(lv.x0[a], n, n, g) + w.h01 * bilinear<float>(lv.x1[a], n, n, g)) / s +
               w.h10 * bilinear<float>(lv.u0[a], n, n, g) + w.h11 * bilinear<float>(lv.u1[a], n, n, g);
    return u;
}

void EWaveLevels::hashState(StateHasher& h) const {
    h.u64(uint64_t(m_frame));
    for (const Level& lv : m_levels) {
        lv.solver->hashState(h);
        h.f32s(lv.h0.data(), lv.h0.size());  // the state before (the Hermite's other end)
        h.f32s(lv.v0.data(), lv.v0.size());
        for (const WorldSource& s : lv.queued) {
            h.f32s(&s.centre.x, 2);
            h.f32(s.radius);
            h.f32(s.strength);
        }
        for (const WorldCrater& c : lv.craters) {
            h.f32s(&c.centre.x, 2);
            h.bytes(&c.volume, sizeof c.volume);
        }
    }
}

} // namespace ob::interaction
