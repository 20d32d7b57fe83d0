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

/// How an entity moves: velocity (m/s, world) and mass (kg), written by physics or scripts.
struct Motion {
    glm::vec3 velocity{0.0f};
    float mass = 1.0f;
};

} // namespace ob::ecs
