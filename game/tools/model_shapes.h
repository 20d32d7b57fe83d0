// The project's own models built in code (ship, fish, cannonball, cannon and the props): closed,
// outward-facing triangle meshes in glTF conventions (metres, +y up, front towards +z).
#pragma once
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ob::game {

/// One primitive of a generated model: closed surfaces wound counter-clockwise seen from
/// outside, and the material they are drawn with.
struct ShapePart {
    std::string name;
    glm::vec3 color{0.8f};            ///< base colour, linear RGB
    float metallic = 0.0f;            ///< [0, 1]
    float roughness = 0.8f;           ///< [0, 1]
    std::vector<glm::vec3> positions; ///< m
    std::vector<glm::vec3> normals;   ///< unit, outward
    std::vector<uint32_t> indices;    ///< 3 per triangle
};

/// A generated model: its file stem ("ship" → ship.gltf) and its parts.
struct ShapeModel {
    std::string name;
    std::vector<ShapePart> parts;
};

/// Every model, in this order (the props after the four below, see buildPropModels):
/// - ship: hull z ∈ [−5, 5] (bow at +z), x ∈ [−1.5, 1.5], keel y = −0.75 to deck y = 0.75;
///   cabin, mast, yard and sail on deck up to y = 7.
/// - fish: z ∈ [−0.5, 0.5] (nose at +z), tail fin at −z, dorsal fin on top; origin on the
///   body's axis at the middle of its length.
/// - cannonball: sphere of radius 1 about the origin.
/// - cannon: barrel along +z with the muzzle at z = 1.5 on a wooden carriage; origin at the
///   trunnions (the barrel's pivot).
/// The output depends on nothing but this code: every number comes from +, −, ×, ÷ and
/// sqrt (no libm transcendental), so the files are the same bytes on every machine.
std::vector<ShapeModel> buildProjectModels();

/// The props (model_props.cpp): crate, barrel, raft and target span [−1, 1]³ (a box object
/// stretches them to its size); ball and buoy are of radius 1 (the buoy's topmark stands
/// above it, to y = 2.3); the pillar and the wall span [−1, 1]³ (the cannon stands on one,
/// the harbour's breakwaters are the other).
std::vector<ShapeModel> buildPropModels();

} // namespace ob::game
