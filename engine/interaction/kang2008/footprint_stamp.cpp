// Kang2008's footprint stamping: eq. 5 then eq. 7 over a sphere's footprint in the field.
#include "interaction/kang2008/footprint_stamp.h"

#include <algorithm>
#include <cassert>

namespace ob::interaction {

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

} // namespace ob::interaction
