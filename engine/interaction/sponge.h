// The absorbing sponge's profile across its band, shared by every ripple solver's Absorbing edge.
#pragma once
#include <cmath>
#include <numbers>

namespace ob::interaction {

/// Sponge profile s(d) at distance d cells from the outer ring for a band of width w:
/// sin²(π/2 · d/w) for 0 <= d < w (0 on the ring), 1 from w inwards. A solver's friction is
/// its maximum times (1 − s_row·s_col): it rises from 0 with zero slope at d = w, so the band
/// starts with no step in the medium (a step reflects).
inline float spongeProfile(int d, int w) {
    if (d >= w) return 1.0f;
    if (d <= 0) return 0.0f;
    const double s = std::sin(0.5 * std::numbers::pi * double(d) / double(w));
    return float(s * s);
}

} // namespace ob::interaction
