// Render interpolation: a pose between the last two fixed steps.
#include "sim/step_poses.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace ob::game {

ecs::Transform drawnTransform(const StepPoses* poses, ecs::Entity e, const ecs::Transform& current, float alpha) {
    if (!poses || alpha >= 1.0f || !poses->before.has(e)) return current;
    const ecs::Transform& before = poses->before.get(e);
    return {glm::mix(before.position, current.position, alpha), glm::slerp(before.rotation, current.rotation, alpha)};
}

} // namespace ob::game
