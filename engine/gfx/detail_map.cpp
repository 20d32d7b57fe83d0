// Detail map: a random height field h(u, v) = Σ a·cos(2π(k·uv) + φ) over integer wave
// vectors k, so h tiles; DU/DV is its gradient, foam a sharpened second field.
#include "gfx/detail_map.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace ob::gfx {

namespace {

struct Wave {
    float kx, ky, amplitude, phase;
};

std::vector<Wave> randomWaves(std::mt19937& rng, int count, int maxK, float slope) {
    std::uniform_int_distribution<int> k(-maxK, maxK);
    std::uniform_real_distribution<float> phase(0.0f, 2.0f * float(M_PI));
    std::vector<Wave> waves;
    while (int(waves.size()) < count) {
        int kx = k(rng), ky = k(rng);
        if (kx == 0 && ky == 0) continue;
        float len = std::sqrt(float(kx * kx + ky * ky));
        waves.push_back({float(kx), float(ky), std::pow(len, -slope), phase(rng)});
    }
    return waves;
}

} // namespace

std::vector<glm::vec4> makeDetailMap(int size, uint32_t seed) {
    std::mt19937 rng(seed);
    const std::vector<Wave> distortion = randomWaves(rng, 24, 8, 1.5f);
    const std::vector<Wave> foam = randomWaves(rng, 24, 12, 1.0f);
    std::vector<glm::vec4> map(size_t(size) * size_t(size));
    float maxGrad = 0.0f, minFoam = 1e30f, maxFoam = -1e30f;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float u = float(x) / float(size), v = float(y) / float(size);
            float du = 0.0f, dv = 0.0f, f = 0.0f;
            for (const Wave& w : distortion) {
                float s = -w.amplitude * std::sin(2.0f * float(M_PI) * (w.kx * u + w.ky * v) + w.phase);
                du += s * w.kx;
                dv += s * w.ky;
            }
            for (const Wave& w : foam) f += w.amplitude * std::cos(2.0f * float(M_PI) * (w.kx * u + w.ky * v) + w.phase);
            map[size_t(y) * size_t(size) + size_t(x)] = glm::vec4(du, dv, f, 1.0f);
            maxGrad = std::max({maxGrad, std::abs(du), std::abs(dv)});
            minFoam = std::min(minFoam, f);
            maxFoam = std::max(maxFoam, f);
        }
    for (glm::vec4& t : map) {
        t.x /= maxGrad;
        t.y /= maxGrad;
        // Foam streaks: the ridges of the second field, sharpened.
        float ridge = 1.0f - std::abs(2.0f * (t.z - minFoam) / (maxFoam - minFoam) - 1.0f);
        t.z = std::pow(ridge, 3.0f);
    }
    return map;
}

} // namespace ob::gfx
