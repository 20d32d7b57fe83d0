// Components shared by every subsystem (plain data).
#pragma once
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace ob::ecs {

/// Where an entity is: world position (m) and orientation.
struct Transform {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};

} // namespace ob::ecs
