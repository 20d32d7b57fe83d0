// Kang2008's stamping of its field: a sphere's footprint written into Vh(t) (eq. 5) and Vh(t−1)
// (eq. 7), one sphere at a time (stepSphere) or batched (stamp_batch.h) (docs/references.md#ripple-layer).
#pragma once
#include "interaction/kang2008/ripple_field.h"
#include "interaction/sphere_stamp.h"

namespace ob::interaction {

/// Eq. 5 then eq. 7 over the footprint centred on cell (cx, cz):
///   Vh(t) = base + PH·heightScale,  Vh(t−1) = Vh(t) − Vh(t)·af,
/// with base in m and heightScale = SD·SHR·cell size (m per cell of PH). Cells outside the
/// field and on its outer ring (held at 0) are skipped.
void stampFootprint(RippleField& field, const FootprintProfile& footprint, int cx, int cz, float base,
                    float heightScale, float af);

/// Table 2 steps 1–6 for one sphere: planStamp, then stampFootprint with the footprint of SR
/// from the cache. Returns true if it stamped.
bool stepSphere(RippleField& field, FootprintCache& cache, float cellSize, const BoundingSphere& def,
                SphereContact& contact, const SphereMotion& motion);

} // namespace ob::interaction
