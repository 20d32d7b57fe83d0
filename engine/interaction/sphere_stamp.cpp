// Bounding spheres: [Kang2008] eq. 3–6 and Table 2's decision, base height read as in docs/references.md#ripple-layer.
// Eq. 5's base Vh(x,z)(t) is the centre cell's ripple height remembered at first contact,
// so a sphere resting on the water rewrites the same shape each step instead of digging.
#include "interaction/sphere_stamp.h"

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

bool planSphereStamp(std::span<const float> current, int rows, int cols, float cellSize, const BoundingSphere& def,
                     SphereContact& contact, const SphereMotion& m, RippleStamp& out) {
    assert(cellSize > 0.0f && def.radius > 0.0f && current.size() == size_t(rows) * size_t(cols));
    return planStamp(rows, cols, cellSize, def, contact, m,
                     [&](int x, int z) { return current[size_t(z) * size_t(cols) + size_t(x)]; }, out);
}

} // namespace ob::interaction
