// What the renderer is told of the world each frame: the camera, the objects, the splash
// drops. Plain data without GL, so the simulation side fills it without a context (the water
// layers, which live in GPU textures, are the renderer's WaterView).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>

namespace ob::assets {
struct HullOutline;
}

namespace ob::gfx {

/// What the camera sees from where: the render phase fills this from the camera entity.
struct CameraView {
    glm::vec3 position{0.0f};   ///< eye (world m)
    glm::mat4 view{1.0f};       ///< world → eye
    glm::mat4 projection{1.0f}; ///< eye → clip
    float nearM = 0.1f;         ///< near clip distance (m)
    float farM = 20000.0f;      ///< far clip distance (m)
    float waterHeight = 0.0f;   ///< composite water surface height under the eye (m): below it, the underwater look
    glm::vec2 waterSlope{0.0f}; ///< and its slope there (dh/dx, dh/dz): the tangent plane the near plane is tested against
};

/// The built-in shapes an object can be drawn as.
enum class MeshKind : uint8_t { Sphere, Box, Ring };

/// One opaque object to draw this frame.
struct ObjectDraw {
    MeshKind mesh = MeshKind::Sphere;
    glm::mat4 model{1.0f};          ///< unit mesh → world (scale, rotation, position)
    glm::vec3 color{0.8f};          ///< base colour (linear RGB)
    std::string modelFile;          ///< glTF file drawn instead of `mesh` ("" = built-in)
    glm::vec3 modelTint{1.0f};      ///< multiplies the model's own colours (a goal's state colour)
    float waterHeight = 0.0f;       ///< the water surface's height under the object's origin (m)
    glm::vec2 waterSlope{0.0f};     ///< and its slope there (dh/dx, dh/dz)
    bool highlight = false;         ///< lit up (the body under the player's cursor)
    bool hull = false;              ///< a floating hull (the water is clipped out of it): drawn in the main view even when wholly under the surface
};

/// A floating hull's clip volume: the water surface is not drawn inside it where the hull's own
/// surface lies behind (shaders/common_hull_clip.glsl), so no sea shows in a hull where the waves
/// rise above its deck or in an open boat. Its outline is the section of the model the body
/// draws (assets/hull_outline.h), or the whole box.
struct HullClip {
    glm::mat4 worldToHull{1.0f};  ///< world → the hull box's unit cube [−1, 1]³ (x across, y up from keel −1 to deck +1, z to the bow)
    std::shared_ptr<const assets::HullOutline> outline;  ///< the model's outline in that cube; null: the whole box (the built-in box mesh)
};

/// One splash drop to draw: world centre (xyz, m) and radius (w, m).
using SplashDrop = glm::vec4;

} // namespace ob::gfx
