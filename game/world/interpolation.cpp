// Render interpolation: the poses each fixed step starts from, and the weight a frame draws with.
#include "world/interpolation.h"

#include "sim/step_poses.h"
#include "world/scene_settings.h"

#include <memory>

namespace ob::game {

void rememberPosesSystem(ecs::World& world, const ecs::Tick&) {
    auto* poses = world.resource<StepPoses>();
    if (!sceneSettings(world).def.render.interpolate) {
        if (poses) poses->before = {};  // switched on again, it starts from the next step
        return;
    }
    if (!poses) poses = &world.setResource(std::make_unique<StepPoses>());
    poses->before = world.pool<ecs::Transform>();  // the arrays keep their capacity from step to step
}

void drawnAlphaSystem(ecs::World& world, const ecs::Tick& tick) {
    if (auto* poses = world.resource<StepPoses>())
        poses->alpha = sceneSettings(world).def.render.interpolate ? float(tick.alpha) : 1.0f;
}

float drawnAlpha(ecs::World& world) {
    const auto* poses = world.resource<StepPoses>();
    return poses ? poses->alpha : 1.0f;
}

} // namespace ob::game
