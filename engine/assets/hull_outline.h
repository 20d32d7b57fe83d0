// A hull's clip outline taken from the model the body draws (any model): the section of its
// mesh across the hull box at stations along it, each as the keel's height and the half-beam
// at heights from the keel to the deck. The water pass clips the sea out of it
// (shaders/common_hull_clip.glsl reads the same table the same way as halfBeam() below).
#pragma once
#include "assets/model.h"

#include <glm/vec3.hpp>
#include <vector>

namespace ob::assets {

/// The outline in the hull box's unit cube (x across, y up from −1 to the deck at +1, z from the
/// stern at −1 to the bow at +1). Station i lies at w_i = −cos(π·i/(STATIONS − 1)) (dense at
/// the ends, where the deck's outline turns); at station i, HEIGHTS half-beams at the heights
/// y_ij = k_i + (1 − k_i)·t_j⁴, t_j = j/(HEIGHTS − 1) from its keel k_i (dense near the keel,
/// where a round bilge's half-beam rises fastest) up to the box's top. Between samples: linear.
struct HullOutline {
    static constexpr int STATIONS = 64;
    static constexpr int HEIGHTS = 24;
    static constexpr int ROW = HEIGHTS + 1;  ///< floats a station: its keel, then its half-beams
    /// STATIONS rows of ROW floats: the keel's height k_i (1: no hull at this station), then the
    /// half-beams (unit cube, ≥ 0) from the keel up.
    std::vector<float> table;
};

/// The outline of `model` in the box [boxMin, boxMax] (model metres): at each station the
/// section of every triangle of the model, the largest |x| at each height (from the box's
/// centre line).
HullOutline hullOutline(const ModelData& model, glm::vec3 boxMin, glm::vec3 boxMax);

/// The clip's half-beam at (w, y) in the unit cube (0: outside the hull), as the shader takes
/// it: the keel linear between the two stations around w; over it, both stations' half-beams
/// at the same share of their depth (as a lofted hull's sections), linear between them.
float halfBeam(const HullOutline& outline, float w, float y);

} // namespace ob::assets
