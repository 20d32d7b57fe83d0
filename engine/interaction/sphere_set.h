// The bounding-sphere component: an object's spheres and their Table 2 contact state.
#pragma once
#include "interaction/sphere_stamp.h"

#include <vector>

namespace ob::interaction {

/// Spheres in the object's local frame, stamped into the ripple patch in order ([Kang2008]:
/// an object is one sphere or a set of spheres).
struct SphereSet {
    std::vector<BoundingSphere> spheres;
    std::vector<SphereContact> contacts;  ///< one per sphere, same order
    /// A hull driven through the water (a ship): bow spray from its foremost sphere (largest
    /// local z) and wake foam from every wetted one (game/sim/splash_foam_system.cpp).
    bool hull = false;
};

} // namespace ob::interaction
