// The one setting of a ripple solver that a live panel offers (the sea panel's slider).
#pragma once

namespace ob::interaction {

/// A float key of a solver's Def as a slider: the key the timeline's set takes, its member, and
/// how to show it.
template <class Def> struct RippleKnob {
    const char* key;     ///< live key, "ripples.damping"
    float Def::*value;   ///< the Def's member it sets
    const char* label;   ///< slider label
    float lo, hi;        ///< slider range (within the key's Limits)
    const char* format;  ///< printf format of the value
    const char* help;    ///< tooltip
};

} // namespace ob::interaction
