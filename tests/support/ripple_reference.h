// Test references for the ripple field: [Kang2008] eq. 1–2 written plainly in double, its
// conserved energy, and random fields (header-only; shared by the unit, gl and scenario suites).
#pragma once
#include "interaction/kang2008/ripple_field.h"

#include <algorithm>
#include <random>
#include <vector>

namespace ob::test {

/// One step of eq. 1–2 in double on an n×m field: all 8 neighbours weigh 1/4, the centre 0;
/// interior cells only, the new outer ring is 0. Rotates the levels.
inline void naiveRippleStep(int n, int m, std::vector<double>& cur, std::vector<double>& prev, double df) {
    std::vector<double> next(cur.size(), 0.0);
    for (int z = 1; z < n - 1; ++z)
        for (int x = 1; x < m - 1; ++x) {
            double buff = 0.0;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    if (i != 0 || j != 0) buff += 0.25 * cur[size_t((z + j) * m + x + i)];
            next[size_t(z * m + x)] = (buff - prev[size_t(z * m + x)]) * df;
        }
    prev = cur;
    cur = next;
}

/// Energy of the undamped scheme: for u(t+1) + u(t−1) = A·u(t), A = ¼·(8-neighbour sum)
/// symmetric, E = |u(t)|² + |u(t−1)|² − u(t)·A·u(t−1) is the same every step; per eigenmode
/// of A (eigenvalue a ∈ [−1, 2) on the interior) it is u² + v² − a·u·v, positive definite.
inline double leapfrogEnergy(const interaction::RippleField& f) {
    const int n = f.rows(), m = f.cols();
    auto u = f.current();
    auto v = f.previous();
    double e = 0.0;
    for (int z = 1; z < n - 1; ++z)
        for (int x = 1; x < m - 1; ++x) {
            double av = 0.0;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    if (i != 0 || j != 0) av += 0.25 * v[size_t((z + j) * m + x + i)];
            const double uu = u[size_t(z * m + x)], vv = v[size_t(z * m + x)];
            e += uu * uu + vv * vv - uu * av;
        }
    return e;
}

/// `count` uniform values in [lo, hi) from a seeded generator.
inline std::vector<float> randomField(size_t count, unsigned seed, float lo = -1.0f, float hi = 1.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(lo, hi);
    std::vector<float> v(count);
    for (float& x : v) x = dist(rng);
    return v;
}

/// Sets both levels of a field.
inline void load(interaction::RippleField& f, const std::vector<float>& cur, const std::vector<float>& prev) {
    std::copy(cur.begin(), cur.end(), f.current().begin());
    std::copy(prev.begin(), prev.end(), f.previous().begin());
}

} // namespace ob::test
