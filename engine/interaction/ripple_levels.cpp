// Nested ripple levels: placement, sources, the strided steps and the Hermite read in time.
#include "interaction/ripple_levels.h"

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

RippleLevels::RippleLevels(const RippleDef& def, const RippleSolver& fine)
    : m_boundary(def.boundary), m_sponge(fine.spongeCells()), m_cell0(def.cell_size) {
    assert(def.levels >= 2 && !fine.levelRefusal());
    const int n = def.resolution;
    float cell = def.cell_size;
    int stride = 1;
    m_levels.resize(size_t(def.levels - 1));
    for (int L = 1; L < def.levels; ++L) {
        cell *= float(RATIO);
        stride *= RATIO;
        Level& lv = m_levels[size_t(L - 1)];
        lv.grid = ScrollingGrid::centredOn(def.center, cell, n);
        lv.solver = fine.makeLevel(cell);
        lv.stride = stride;
        // The still water counts as level L's state at frame L, so its first step is at frame
        // L + 1 and no two levels step on the same frame while 4^L > L.
        lv.b = L;
        lv.a = L - stride;
        lv.solver->keepLevelState(lv.s1);
        lv.s0 = lv.s1;
        lv.shown.assign(size_t(n) * size_t(n), 0.0f);
    }
    m_sponge = m_levels.front().solver->spongeCells();  // as the solver clamps it
}

RippleLevels::~RippleLevels() = default;

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

// The solver's state as the Hermite's end at b (RippleSolver::keepLevelState).
void RippleLevels::keepState(Level& lv) { lv.solver->keepLevelState(lv.s1); }

void RippleLevels::centerOn(glm::vec2 world) {
    for (Level& lv : m_levels) {
        const glm::ivec2 shift = lv.grid.centreOn(world);
        if (shift == glm::ivec2(0)) continue;
        // The state at b keeps its volume (EWaveField::scroll); its copies follow it, and the
        // state at a is scrolled the same way: new cells at its mean level (v at 0), what left
        // put back uniformly, so the Hermite between them keeps the level's mean too.
        lv.solver->scroll(shift);
        keepState(lv);
        LevelState& s0 = lv.s0;
        scrollKeepingSum(s0.h, lv.grid.n, shift);
        scrollCells(s0.v.data(), lv.grid.n, lv.grid.n, shift);
        double v0 = 0.0;  // its mean back to 0, as keepLevelState's
        for (float x : s0.v) v0 += double(x);
        const float back = float(v0 / double(s0.v.size()));
        for (float& x : s0.v) x -= back;
        for (int a = 0; a < 2; ++a) {  // derived, mean 0: new cells 0
            if (!s0.xi[a].empty()) scrollCells(s0.xi[a].data(), lv.grid.n, lv.grid.n, shift);
            if (!s0.u[a].empty()) scrollCells(s0.u[a].data(), lv.grid.n, lv.grid.n, shift);
        }
        lv.shownFrame = -1;
        ++lv.version;
    }
}

float RippleLevels::weightAt(int L, glm::vec2 world) const {
    if (L == count() - 1) return 1.0f;  // the coarsest: what it holds, 0 off its grid
    return levelWeight(grid(L).toGrid(world), grid(L).n, m_sponge);
}

int RippleLevels::finestAt(glm::vec2 world) const {
    for (int L = 1; L < count() - 1; ++L)
        if (weightAt(L, world) > 0.0f) return L;
    return count() - 1;
}

void RippleLevels::pushSource(glm::vec2 centre, float radius, float accel, int from) {
    for (int L = std::max(from, 1); L < count(); ++L) m_levels[size_t(L - 1)].queued.push_back({centre, radius, accel * radius * radius});
}

bool RippleLevels::addCrater(glm::vec2 world, double volume, int from) {
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

bool RippleLevels::stampSphere(const BoundingSphere& sphere, SphereContact& contact, SphereMotion motion, glm::vec2 centre) {
    const int L = finestAt(centre);
    const Level& lv = level(L);
    const glm::vec2 g = lv.grid.toGrid(centre);
    motion.gridX = g.x;
    motion.gridZ = g.y;
    LevelSource s;
    if (!lv.solver->planLevelSource(sphere, contact, motion, s)) return false;
    // The source as level 0 would make it, radius max(r, Δ₀): planned here its radius is
    // max(r, Δ_L), and with the same accel a sphere smaller than this level's cell would push
    // (Δ_L/max(r, Δ₀))² times too hard (16 times for a 1 m sphere on 4 m cells). pushSource
    // then widens it to this level's cell keeping ∫a·w dA. (The stagnation term of accel is
    // this level's, v²/(2·max(r, Δ_L)): smaller, for a body moving up or down only.)
    pushSource(centre, std::max(s.radiusCells * lv.grid.cell, m_cell0), s.accel, L);
    return true;
}

void RippleLevels::step(float dt, std::span<const ObstacleShape> obstacles) {
    ++m_frame;
    m_dt = dt;
    for (Level& lv : m_levels)
        if (m_frame > lv.b) stepLevel(lv, dt, obstacles);
}

// One step of the level over stride·dt from frame b. Its queued sources, each a frame's push,
// are applied over the whole step at 1/stride of their accel: the same impulse, at most one
// step early or late (a 5 m/s ship moves 1.3 m in level 2's 16 frames, under its 3–4 m cell).
void RippleLevels::stepLevel(Level& lv, float dt, std::span<const ObstacleShape> obstacles) {
    const float cell = lv.grid.cell;
    for (const WorldSource& ws : lv.queued) {
        const glm::vec2 g = lv.grid.toGrid(ws.centre);
        const float r = std::max(ws.radius / cell, 1.0f);  // cells; ∫w dA = π(r·cell)²/3 keeps strength
        lv.solver->addLevelSource({g.x, g.y, r, ws.strength / (r * cell * r * cell) / float(lv.stride)});
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
            lv.s1.h[size_t(z) * size_t(n) + size_t(x)] += float(depth * w[k]);
        }
        craterVolume += depth;
    }
    lv.craters.clear();
    if (craterVolume != 0.0 && m_boundary != RippleBoundary::Fixed) {
        const float back = float(-craterVolume / (double(n) * double(n)));
        for (float& x : lv.s1.h) x += back;  // as the solver's step will (the Hermite's start keeps the mean)
    }
    if (!obstacles.empty() || !lv.obstruction.empty()) {
        rasteriseObstacles(obstacles, lv.grid.n, lv.grid.n, cell, [&lv](glm::vec2 w) { return lv.grid.toGrid(w); },
                           lv.obstruction);
        lv.solver->setObstruction(lv.obstruction);
    }
    std::swap(lv.s0, lv.s1);
    lv.solver->step(dt * float(lv.stride));
    keepState(lv);
    lv.a = lv.b;
    lv.b += lv.stride;
    ++lv.version;
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
std::span<const float> RippleLevels::height(int L) const {
    const Level& lv = level(L);
    if (lv.shownFrame != m_frame) {
        const Hermite w = Hermite::at(phase(lv));
        const float s = m_dt * float(lv.stride);
        const float a0 = w.h00, a1 = w.h01, b0 = w.h10 * s, b1 = w.h11 * s;
        const float *h0 = lv.s0.h.data(), *h1 = lv.s1.h.data(), *v0 = lv.s0.v.data(), *v1 = lv.s1.v.data();
        for (size_t i = 0; i < lv.shown.size(); ++i) lv.shown[i] = a0 * h0[i] + a1 * h1[i] + b0 * v0[i] + b1 * v1[i];
        lv.shownFrame = m_frame;
    }
    return lv.shown;
}

void RippleLevels::publish() {
    for (Level& lv : m_levels) {
        if (lv.drawn.version == lv.version) continue;
        lv.drawn.h0 = lv.s0.h;
        lv.drawn.h1 = lv.s1.h;
        lv.drawn.v0 = lv.s0.v;
        lv.drawn.v1 = lv.s1.v;
        lv.drawn.a = lv.a;
        lv.drawn.seconds = m_dt * float(lv.stride);
        lv.drawn.origin = lv.grid.origin();
        lv.drawn.version = lv.version;
        const std::vector<float>* states[4] = {&lv.drawn.h0, &lv.drawn.h1, &lv.drawn.v0, &lv.drawn.v1};
        for (int k = 0; k < 4; ++k) {
            const auto [lo, hi] = std::minmax_element(states[k]->begin(), states[k]->end());
            lv.drawn.extremes[size_t(k)] = glm::vec2(*lo, *hi);
        }
    }
}

LevelDraw RippleLevels::draw(int L, int64_t frame) const {
    const Level& lv = level(L);
    const auto& d = lv.drawn;
    const Hermite w = Hermite::at(std::clamp(float(frame - d.a) / float(lv.stride), 0.0f, 1.0f));
    return {d.h0, d.h1, d.v0, d.v1, d.version, glm::vec4(w.h00, w.h01, w.h10 * d.seconds, w.h11 * d.seconds), d.extremes, d.origin,
            lv.grid.cell};
}

float RippleLevels::heightAt(int L, glm::vec2 world) const {
    const Level& lv = level(L);
    const glm::vec2 g = lv.grid.toGrid(world);
    const int n = lv.grid.n;
    const Hermite w = Hermite::at(phase(lv));
    const float s = m_dt * float(lv.stride);
    return w.h00 * bilinear<float>(lv.s0.h, n, n, g) + w.h01 * bilinear<float>(lv.s1.h, n, n, g) +
           s * (w.h10 * bilinear<float>(lv.s0.v, n, n, g) + w.h11 * bilinear<float>(lv.s1.v, n, n, g));
}

float RippleLevels::velocityAt(int L, glm::vec2 world) const {
    const Level& lv = level(L);
    const float s = m_dt * float(lv.stride);
    if (s <= 0.0f) return 0.0f;
    const glm::vec2 g = lv.grid.toGrid(world);
    const int n = lv.grid.n;
    const Hermite w = Hermite::slope(phase(lv));
    return (w.h00 * bilinear<float>(lv.s0.h, n, n, g) + w.h01 * bilinear<float>(lv.s1.h, n, n, g)) / s +
           w.h10 * bilinear<float>(lv.s0.v, n, n, g) + w.h11 * bilinear<float>(lv.s1.v, n, n, g);
}

// The same Hermite slope as velocityAt, on ξ and u: ξ = R[h] and u = R[v] = ∂ξ/∂t with R the
// per-mode i·K/(|K|·tanh(|K|d)), linear and the same at both ends, so this is R of velocityAt's
// v(t) (the craters a step adds reach ξ with the step after: one coarse step late at most).
glm::vec2 RippleLevels::horizontalVelocityAt(int L, glm::vec2 world) const {
    const Level& lv = level(L);
    const float s = m_dt * float(lv.stride);
    if (s <= 0.0f || lv.s0.xi[0].empty()) return {0.0f, 0.0f};
    const glm::vec2 g = lv.grid.toGrid(world);
    const int n = lv.grid.n;
    const Hermite w = Hermite::slope(phase(lv));
    glm::vec2 u;
    for (int a = 0; a < 2; ++a)
        u[a] = (w.h00 * bilinear<float>(lv.s0.xi[a], n, n, g) + w.h01 * bilinear<float>(lv.s1.xi[a], n, n, g)) / s +
               w.h10 * bilinear<float>(lv.s0.u[a], n, n, g) + w.h11 * bilinear<float>(lv.s1.u[a], n, n, g);
    return u;
}

void RippleLevels::hashState(StateHasher& h) const {
    h.u64(uint64_t(m_frame));
    for (const Level& lv : m_levels) {
        lv.solver->hashState(h);
        h.f32s(lv.s0.h.data(), lv.s0.h.size());  // the state before (the Hermite's other end)
        h.f32s(lv.s0.v.data(), lv.s0.v.size());
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
