// Semi-Lagrangian self-advection of the current layer's faces (Stam 1999, "Stable Fluids" §2.2):
//   u_new(x) = u(x_d),  x_d = x − dt·u(x − ½dt·u(x))   (RK2 / midpoint backtrace, bilinear),
// for each u face and each v face of the staggered grid (layout: current_layer.h). Every face's
// value depends only on the previous faces, so rows split over workers give the same bits.
// Where the backtrace leaves the grid it reads the ghost ring: the background flow enters.
// Fast path: where no face moves more than half a cell a step (|u|·dt ≤ ½Δ, the usual case:
// 1 m/s × 1/60 s over 2 m cells is 0.008), the midpoint lies in a fixed 2 × 2 stencil of the
// other component and the departure point beside its face, so a row is a vector loop with no
// gathers; a row with a faster face is redone by a general bilinear lookup.
#pragma once
#include <glm/vec2.hpp>

namespace ob::currents {

/// Advects the faces u0, v0 (padded (n + 2)², ghost ring = background) over dt s on cells of
/// `cell` m into u, v (same layout; the ghost ring is not written), the rows split over at most
/// `threads` workers.
void advectFaces(const float* u0, const float* v0, float* u, float* v, int n, float cell, float dt, int threads = 1);

/// Bilinear lookup of a padded face array at padded coordinates p (clamped to the ghost ring:
/// beyond it the ghosts' background).
float samplePadded(const float* f, int n, glm::vec2 p);

} // namespace ob::currents
