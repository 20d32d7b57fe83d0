// The foam a hull lays (laws (d)–(f) in foam_sources.h): the stern's streaked white water, the
// turbulent wake along its track, the breaking bow wave's arms.
#include "foam/foam_sources.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace ob::foam {

float wakeStreaks(float y, float depth) {
    // n(y) every STREAK_STEP over its period, 117 m (0.9, 1.5 and 2.6 m all divide it), linear
    // between (within 4e-4 of the sines): the turbulent wake asks for it at thousands of cells
    // a step.
    constexpr double STREAK_STEP = 0.01;
    constexpr int STREAK_SAMPLES = 11700;
    static const std::vector<float> table = [] {
        std::vector<float> t(STREAK_SAMPLES + 1);
        const double twoPi = 2.0 * std::numbers::pi;
        for (int k = 0; k <= STREAK_SAMPLES; ++k) {
            const double x = k * STREAK_STEP;
            t[size_t(k)] = float((std::sin(twoPi * x / 0.9 + 1.3) + 0.7 * std::sin(twoPi * x / 1.5 + 4.1) +
                                  0.5 * std::sin(twoPi * x / 2.6 + 2.2)) / 2.2);
        }
        return t;
    }();
    const double u = double(y) / STREAK_STEP, cell = std::floor(u);
    const int k = int(std::fmod(cell, double(STREAK_SAMPLES)) + (cell < 0.0 ? STREAK_SAMPLES : 0)) % STREAK_SAMPLES;
    const float w = float(u - cell);
    const float n = table[size_t(k)] + w * (table[size_t(k) + 1] - table[size_t(k)]);
    return 1.0f - depth * (0.5f + 0.5f * n);
}

void addWake(const FoamDef& def, const CoverageCells& cells, const glm::vec3& centre, const glm::vec3& velocity,
             float radius, float dt) {
    const float cell = cells.grid.cell;
    const int n = cells.grid.n;
    const glm::vec2 u(velocity.x, velocity.z);
    const float speed = std::sqrt(u.x * u.x + u.y * u.y);
    if (def.wake_weight <= 0.0f || speed <= 0.0f || radius <= 0.0f) return;
    const float amount = def.wake_weight * speed / radius * dt;
    const glm::vec2 c = cells.grid.toGrid(glm::vec2(centre.x, centre.z));
    const glm::vec2 side = glm::vec2(-u.y, u.x) / speed;  // across the track
    const float rCells = radius / cell;
    const int i0 = std::max(0, int(std::floor(c.x - rCells))), i1 = std::min(n - 1, int(std::ceil(c.x + rCells)));
    const int j0 = std::max(0, int(std::floor(c.y - rCells))), j1 = std::min(n - 1, int(std::ceil(c.y + rCells)));
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const glm::vec2 d(float(i) - c.x, float(j) - c.y);  // cells
            if (d.x * d.x + d.y * d.y > rCells * rCells) continue;
            if (d.x * u.x + d.y * u.y > 0.0f) continue;  // ahead of the sphere's centre
            cells.add(i, j, amount * wakeStreaks((d.x * side.x + d.y * side.y) * cell, def.wake_streaks));
        }
    }
}

void addWakeTrail(const FoamDef& def, const CoverageCells& cells, glm::vec2 from, glm::vec2 to, float age, float radius,
                  float dt) {
    const float cell = cells.grid.cell;
    const int n = cells.grid.n;
    const float as = def.wake_turbulence_s;
    const glm::vec2 d = to - from;
    const float length2 = d.x * d.x + d.y * d.y;
    if (def.wake_weight <= 0.0f || as <= 0.0f || radius <= 0.0f || length2 <= 0.0f || age < 0.0f) return;
    const float b = std::sqrt(radius * radius + 2.0f * def.wake_diffusivity * age);  // half-width, m
    const float rate = def.wake_weight * std::exp(-age / as) / as * (radius / b);
    const float amount = rate * dt;
    const float length = std::sqrt(length2);
    const glm::vec2 along = d / length, side(-along.y, along.x);
    const glm::vec2 g0 = cells.grid.toGrid(from), g1 = cells.grid.toGrid(to);
    // The strip's corners' bounds (cells): along a grid axis just the strip, not b past its ends.
    const glm::vec2 reach = glm::vec2(std::abs(side.x), std::abs(side.y)) * (b / cell);
    const int i0 = std::max(0, int(std::floor(std::min(g0.x, g1.x) - reach.x))), i1 = std::min(n - 1, int(std::ceil(std::max(g0.x, g1.x) + reach.x)));
    const int j0 = std::max(0, int(std::floor(std::min(g0.y, g1.y) - reach.y))), j1 = std::min(n - 1, int(std::ceil(std::max(g0.y, g1.y) + reach.y)));
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const glm::vec2 p = (glm::vec2(float(i), float(j)) - g0) * cell;  // m from the older end
            const float s = p.x * along.x + p.y * along.y;
            if (s < 0.0f || s >= length) continue;  // each cell beside a straight track in one segment
            const float y = p.x * side.x + p.y * side.y;
            if (std::abs(y) >= b) continue;
            const float across = std::sqrt(1.0f - (y / b) * (y / b));
            cells.add(i, j, amount * across * wakeStreaks(y * radius / b, def.wake_streaks));
        }
    }
}

void addBowWave(const FoamDef& def, const CoverageCells& cells, const glm::vec3& centre, const glm::vec3& velocity,
                float radius, float strength, float dt) {
    const float cell = cells.grid.cell;
    const int n = cells.grid.n;
    const glm::vec2 u(velocity.x, velocity.z);
    const float speed = std::sqrt(u.x * u.x + u.y * u.y);
    strength = std::min(strength, 1.0f);
    if (def.bow_weight <= 0.0f || speed <= 0.0f || radius <= 0.0f || strength <= 0.0f) return;
    const glm::vec2 ahead = u / speed, side(-ahead.y, ahead.x);
    const float sinK = 1.0f / 3.0f, cosK = std::sqrt(8.0f) / 3.0f;  // the Kelvin angle asin(1/3)
    const float width = std::max(2.0f * cell, 0.3f), length = 8.0f * radius * strength;
    const float amount = def.bow_weight * strength * speed * sinK / width * dt;
    for (float sign : {-1.0f, 1.0f}) {
        const glm::vec2 start = glm::vec2(centre.x, centre.z) + 0.5f * radius * ahead + sign * radius * side;
        const glm::vec2 arm = -cosK * ahead + sign * sinK * side;  // unit, back and out
        const glm::vec2 g0 = cells.grid.toGrid(start), g1 = cells.grid.toGrid(start + length * arm);
        const float w = 0.5f * width / cell;
        const int i0 = std::max(0, int(std::floor(std::min(g0.x, g1.x) - w))), i1 = std::min(n - 1, int(std::ceil(std::max(g0.x, g1.x) + w)));
        const int j0 = std::max(0, int(std::floor(std::min(g0.y, g1.y) - w))), j1 = std::min(n - 1, int(std::ceil(std::max(g0.y, g1.y) + w)));
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const glm::vec2 p = (glm::vec2(float(i), float(j)) - g0) * cell;
                const float s = p.x * arm.x + p.y * arm.y;
                if (s < 0.0f || s > length) continue;
                if (std::abs(p.x * arm.y - p.y * arm.x) > 0.5f * width) continue;
                cells.add(i, j, amount);
            }
        }
    }
}

} // namespace ob::foam
