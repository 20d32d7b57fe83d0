// Bounding-sphere stamping: [Kang2008] eq. 3–7 and Table 2, base height read as in docs/references.md#ripple-layer.
// Eq. 5's base Vh(x,z)(t) is the centre cell's ripple height remembered at first contact,
// so a sphere resting on the water rewrites the same shape each step instead of digging.
#include "interaction/sphere_stamp.h"

#include "interaction/kang2008/ripple_field.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

namespace ob::interaction {

float accelerationFactor(float w, float v, float s, float refW, float refV, float refS) {
    assert(s > 0.0f && refW > 0.0f && refV > 0.0f && refS > 0.0f);
    return ((w * v) / s) / ((refW * refV) / refS) - 1.0f;  // eq. 6
}

FootprintProfile makeFootprint(float radiusCells) {
    FootprintProfile fp;
    fp.radiusCells = radiusCells;
    if (!(radiusCells > 0.0f)) return fp;
    const double sr2 = double(radiusCells) * double(radiusCells);
    // Largest |dz| with dz² < SR²: rows beyond it have no cell with PR < SR.
    int reach = 0;
    while (double(reach + 1) * double(reach + 1) < sr2) ++reach;
    for (int dz = -reach; dz <= reach; ++dz) {
        const double dz2 = double(dz) * double(dz);
        int hw = 0;
        while (double(hw + 1) * double(hw + 1) + dz2 < sr2) ++hw;
        FootprintRow row{dz, -hw, 2 * hw + 1, int(fp.ph.size())};
        for (int dx = -hw; dx <= hw; ++dx) {
            const double pr2 = double(dx) * double(dx) + dz2;  // eq. 3, squared
            fp.ph.push_back(float(std::sqrt(sr2 - pr2)));     // eq. 4
        }
        fp.rows.push_back(row);
    }
    return fp;
}

const FootprintProfile& FootprintCache::get(float radiusCells) {
    const uint32_t key = std::bit_cast<uint32_t>(radiusCells);
    auto it = m_profiles.find(key);
    if (it == m_profiles.end()) it = m_profiles.emplace(key, makeFootprint(radiusCells)).first;
    return it->second;
}

void stampFootprint(RippleField& field, const FootprintProfile& fp, int cx, int cz, float base, float heightScale,
                    float af) {
    const int rows = field.rows(), cols = field.cols();
    float* const cur = field.current().data();
    float* const prev = field.previous().data();
    for (const FootprintRow& r : fp.rows) {
        const int z = cz + r.dz;
        if (z < 1 || z > rows - 2) continue;  // outside, or on the ring held at 0
        // Clip the span [x0, x0 + count) to the interior columns [1, cols − 2].
        const int x0 = cx + r.dx0;
        const int a = std::max(x0, 1), b = std::min(x0 + r.count, cols - 1);
        if (a >= b) continue;
        const float* __restrict ph = fp.ph.data() + r.offset + (a - x0);
        float* __restrict c = cur + size_t(z) * size_t(cols) + size_t(a);
        float* __restrict p = prev + size_t(z) * size_t(cols) + size_t(a);
        for (int i = 0; i < b - a; ++i) {
            const float v = base + ph[i] * heightScale;  // eq. 5, PH·SD·SHR in metres
            c[i] = v;
            p[i] = v - v * af;                           // eq. 7
        }
    }
}

bool stepSphere(RippleField& field, FootprintCache& cache, float cellSize, const BoundingSphere& def,
                SphereContact& contact, const SphereMotion& m) {
    assert(cellSize > 0.0f && def.radius > 0.0f);
    RippleStamp st;
    if (!planStamp(field.rows(), field.cols(), cellSize, def, contact, m,
                   [&](int x, int z) { return field.currentAt(x, z); }, st))
        return false;
    stampFootprint(field, cache.get(st.radiusCells), st.cx, st.cz, st.base, st.heightScale, st.accelerationFactor);
    return true;
}

bool planSphereStamp(std::span<const float> current, int rows, int cols, float cellSize, const BoundingSphere& def,
                     SphereContact& contact, const SphereMotion& m, RippleStamp& out) {
    assert(cellSize > 0.0f && def.radius > 0.0f && current.size() == size_t(rows) * size_t(cols));
    return planStamp(rows, cols, cellSize, def, contact, m,
                     [&](int x, int z) { return current[size_t(z) * size_t(cols) + size_t(x)]; }, out);
}

} // namespace ob::interaction
