// The wind's part of the foam's velocity: the drift and the streak cells' rolls, from phase
// tables by column and by row that move with the map (laws in foam_wind.h).
#include "foam/foam_wind.h"

#include "core/simd.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace ob::foam {

// θ_m = K_m·p + (ω_m − K_m·drift)·t + β_m, split in the column's part K_x·x, the row's K_z·z
// (both tabulated when the map scrolls) and the time's (each step): the phases in double, reduced
// mod 2π, from world sample indices (a map far from the origin loses nothing).
namespace {
constexpr double TWO_PI_D = 2.0 * 3.141592653589793;
// splitmix64 of a fixed seed and a draw's index → [0, 1).
double streakDraw(uint64_t index) {
    uint64_t z = STREAK_SEED + index * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}
// out[i] = init + Σ_m (a[m]·ca[m][i] + b[m]·sa[m][i]) over `modes` rolls, the tables [m][n]: in
// blocks of columns whose sums stay in registers over all the rolls (one store a sample).
constexpr int STREAK_BLOCK = 32;
OB_VECTOR_KERNEL void streakSumKernel(float* __restrict out, const float* __restrict ca, const float* __restrict sa,
                                      const float* __restrict a, const float* __restrict b, int modes, int n, float init) {
    int i0 = 0;
    for (; i0 + STREAK_BLOCK <= n; i0 += STREAK_BLOCK) {
        float acc[STREAK_BLOCK];
        for (int k = 0; k < STREAK_BLOCK; ++k) acc[k] = init;
        for (int m = 0; m < modes; ++m) {
            const float am = a[m], bm = b[m];
            const float* c = ca + size_t(m) * size_t(n) + i0;
            const float* s = sa + size_t(m) * size_t(n) + i0;
            for (int k = 0; k < STREAK_BLOCK; ++k) acc[k] += am * c[k] + bm * s[k];
        }
        for (int k = 0; k < STREAK_BLOCK; ++k) out[i0 + k] = acc[k];
    }
    for (int i = i0; i < n; ++i) {
        float acc = init;
        for (int m = 0; m < modes; ++m) acc += a[m] * ca[size_t(m) * size_t(n) + i] + b[m] * sa[size_t(m) * size_t(n) + i];
        out[i] = acc;
    }
}

} // namespace

std::vector<StreakMode> foamStreakModes(const WindFlow& wind) {
    std::vector<StreakMode> modes;
    if (!wind.streaks()) return modes;
    const glm::dvec2 w = glm::normalize(glm::dvec2(wind.direction)), c(-w.y, w.x);
    for (int m = 0; m < STREAK_MODES; ++m) {
        const uint64_t d = uint64_t(m) * 4;
        const double u = (m + streakDraw(d)) / STREAK_MODES;
        const double spacing = double(wind.streakSpacing) / (1.0 - (1.0 - 1.0 / STREAK_SPACING_RANGE) * u);
        const double slant = STREAK_SLANT * (2.0 * streakDraw(d + 1) - 1.0), k = TWO_PI_D / spacing;
        StreakMode mode;
        mode.k = k * (std::cos(slant) * c + std::sin(slant) * w);
        mode.speed = double(wind.streakSpeed) * std::sqrt(2.0 / STREAK_MODES * spacing / double(wind.streakSpacing));
        // Lines moving across at ±spacing per lifetime, so the pattern renews over it.
        mode.omega = TWO_PI_D / STREAK_LIFE_S * (2.0 * streakDraw(d + 2) - 1.0);
        mode.phase = TWO_PI_D * streakDraw(d + 3);
        modes.push_back(mode);
    }
    return modes;
}

void FoamWind::set(const WindFlow& wind) {
    if (wind == m_wind) return;
    m_wind = wind;
    m_modes = foamStreakModes(wind);
    fillTables();
    fillTime();
}

void FoamWind::setTime(double t) {
    m_time = t;
    fillTime();
}

void FoamWind::fillTime() {
    m_timeCos.resize(m_modes.size());
    m_timeSin.resize(m_modes.size());
    for (size_t m = 0; m < m_modes.size(); ++m) {
        const StreakMode& mode = m_modes[m];
        const double a = std::fmod((mode.omega - glm::dot(mode.k, glm::dvec2(m_wind.drift))) * m_time, TWO_PI_D) + mode.phase;
        m_timeCos[m] = float(std::cos(a));
        m_timeSin[m] = float(std::sin(a));
    }
}

void FoamWind::fillTables() {
    const size_t n = size_t(m_grid.n), count = m_modes.size();
    m_columnCos.resize(count * n), m_columnSin.resize(count * n);
    m_rowCos.resize(count * n), m_rowSin.resize(count * n);
    fillTable(0, 0, m_grid.n);
    fillTable(1, 0, m_grid.n);
}

// Entries [lo, hi) of the column (axis 0: cos, sin of K_x·x) or row (axis 1: K_z·z) tables.
void FoamWind::fillTable(int axis, int lo, int hi) {
    const size_t n = size_t(m_grid.n);
    float* c = axis == 0 ? m_columnCos.data() : m_rowCos.data();
    float* s = axis == 0 ? m_columnSin.data() : m_rowSin.data();
    const int64_t origin = axis == 0 ? m_grid.originCell.x : m_grid.originCell.y;
    for (size_t m = 0; m < m_modes.size(); ++m) {
        const double k = m_modes[m].k[axis] * double(m_grid.cell);
        for (int i = lo; i < hi; ++i) {
            const double a = std::fmod(k * double(origin + i), TWO_PI_D);
            c[m * n + size_t(i)] = float(std::cos(a));
            s[m * n + size_t(i)] = float(std::sin(a));
        }
    }
}

// The map moved by `shift` samples: the tables' entries it keeps move with it (the same bits as
// filling them anew), only the ones it scrolled onto are computed.
void FoamWind::scrollTables(glm::ivec2 shift) {
    const int n = m_grid.n;
    for (int axis = 0; axis < 2; ++axis) {
        const int d = shift[axis];
        if (d == 0) continue;
        if (std::abs(d) >= n) {
            fillTable(axis, 0, n);
            continue;
        }
        std::vector<float>* const tables[2] = {axis == 0 ? &m_columnCos : &m_rowCos, axis == 0 ? &m_columnSin : &m_rowSin};
        for (std::vector<float>* t : tables)
            for (size_t m = 0; m < m_modes.size(); ++m) {
                float* row = t->data() + m * size_t(n);
                if (d > 0) std::copy(row + d, row + n, row);  // new i = old i + d
                else std::copy_backward(row, row + n + d, row + n);
            }
        if (d > 0) fillTable(axis, n - d, n);
        else fillTable(axis, 0, -d);
    }
}

float FoamWind::max() const {
    const glm::vec2 w = m_wind.direction, c(-w.y, w.x);
    double v = 0.0;
    for (const StreakMode& mode : m_modes) v += mode.speed;
    return std::max(std::abs(m_wind.drift.x) + float(v) * (std::abs(w.x) + std::abs(c.x)),
                    std::abs(m_wind.drift.y) + float(v) * (std::abs(w.y) + std::abs(c.y)));
}

// u_w = drift + Σ_m V_m·(cos θ_m·ŵ − sin θ_m·ĉ), θ_m = a_i + b_j: with cos θ = ca·cb − sa·sb and
// sin θ = sa·cb + ca·sb, each roll adds A·ca_i + B·sa_i, A = V·(ŵ·cb − ĉ·sb), B = −V·(ŵ·sb + ĉ·cb).
void FoamWind::row(int j, int component, float* out) const {
    const int n = m_grid.n, count = int(m_modes.size());
    const float d = m_wind.drift[component];
    if (count == 0) return std::fill(out, out + n, d);
    const glm::vec2 w = m_wind.direction, c(-w.y, w.x);
    float A[STREAK_MODES], B[STREAK_MODES];
    for (int m = 0; m < count; ++m) {
        float cb, sb;
        rowPhase(size_t(m), j, cb, sb);
        const float v = float(m_modes[size_t(m)].speed);
        A[m] = v * (w[component] * cb - c[component] * sb), B[m] = -v * (w[component] * sb + c[component] * cb);
    }
    streakSumKernel(out, m_columnCos.data(), m_columnSin.data(), A, B, count, n, d);
}

// ∇·u_w = −Σ_m V_m·((K_m·ĉ)·cos θ_m + (K_m·ŵ)·sin θ_m); with P = dt·V·K·ĉ, Q = dt·V·K·ŵ,
// −dt·∇·u_w adds ca·(P·cb + Q·sb) + sa·(Q·cb − P·sb) a roll.
void FoamWind::gatherRow(int j, float dt, float* out) const {
    const int n = m_grid.n, count = int(m_modes.size());
    if (count == 0) return std::fill(out, out + n, 1.0f);
    const glm::dvec2 w(m_wind.direction), c(-w.y, w.x);
    float X[STREAK_MODES], Y[STREAK_MODES];
    for (int m = 0; m < count; ++m) {
        const StreakMode& mode = m_modes[size_t(m)];
        const double g = double(dt) * mode.speed;
        const double P = g * glm::dot(mode.k, c), Q = g * glm::dot(mode.k, w);
        float cb, sb;
        rowPhase(size_t(m), j, cb, sb);
        X[m] = float(P) * cb + float(Q) * sb, Y[m] = float(Q) * cb - float(P) * sb;
    }
    streakSumKernel(out, m_columnCos.data(), m_columnSin.data(), X, Y, count, n, 1.0f);
}

void FoamWind::follow(const ScrollingGrid& grid) {
    const glm::ivec2 scroll = grid.originCell - m_grid.originCell;
    const bool resized = grid.n != m_grid.n || grid.cell != m_grid.cell;
    m_grid = grid;
    if (!m_modes.empty() && resized) fillTables();
    else if (!m_modes.empty() && scroll != glm::ivec2(0)) scrollTables(scroll);
}

} // namespace ob::foam
