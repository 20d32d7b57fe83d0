// How the foam lies: the autocorrelation length of a coverage map along a direction
// (docs/splash_foam.md §2.2). Foam streaks along the wind have a longer length along it than
// across it.
#pragma once
#include <span>
#include <glm/vec2.hpp>

namespace ob::foam {

/// The lag r (m) at which the coverage's autocorrelation along `direction` first falls to 1/e:
/// C(r) = ⟨(f(p) − f̄)·(f(p + r·d̂) − f̄)⟩ / ⟨(f − f̄)²⟩, the mean over the samples p whose
/// partner p + r·d̂ lies inside the map (bilinear there), f̄ and the variance over the whole
/// map; r in steps of one sample `cell` m apart, linear between the two around the crossing.
/// `f` is n×n row-major (index j·n + i, i along x). Returns maxLag when C stays above 1/e
/// that far, 0 for a map that does not vary.
float autocorrelationLength(std::span<const float> f, int n, float cell, glm::vec2 direction, float maxLag);

/// C(r) above at one lag r (m) along `direction` (0 for a map that does not vary).
float autocorrelation(std::span<const float> f, int n, float cell, glm::vec2 direction, float lag);

} // namespace ob::foam
