// The scene resource, and the push of a changed section to the objects that keep a copy.
#include "world/scene_settings.h"

#include "currents/current_layer.h"
#include "interaction/ripple_patch.h"
#include "world/camera.h"

#include <cassert>

namespace ob::game {

namespace {

// What the settings system last handed on.
struct SettingsSeen {
    SectionSeen camera;
    SectionSeen ripples;
    SectionSeen currents;
};

} // namespace

SceneSettings& sceneSettings(ecs::World& world) {
    SceneSettings* settings = world.resource<SceneSettings>();
    assert(settings && "the sandbox makes the scene resource first");
    return *settings;
}

SceneSettings& addSceneSettings(ecs::World& world, const SceneDef& scene) {
    world.setResource(std::make_unique<SettingsSeen>());
    return world.setResource(std::make_unique<SceneSettings>(SceneSettings{scene, {}}));
}

void settingsSystem(ecs::World& world, const ecs::Tick&) {
    auto* settings = world.resource<SceneSettings>();
    auto* seen = world.resource<SettingsSeen>();
    if (!settings || !seen) return;
    // A rig's Def is its working copy (camera events and C change its mode and target): a
    // live [camera] key gives it the scene's section again.
    if (seen->camera.moved(*settings, SceneSection::Camera)) {
        auto& rigs = world.pool<CameraRig>();
        for (size_t k = 0; k < rigs.size(); ++k) rigs.components()[k].def = settings->def.camera;
    }
    if (seen->ripples.moved(*settings, SceneSection::Ripples))
        if (auto* patch = world.resource<interaction::RipplePatch>()) patch->retune(settings->def.ripples);
    if (seen->currents.moved(*settings, SceneSection::Currents))
        if (auto* layer = world.resource<currents::CurrentLayer>()) layer->retune(settings->def.currents);
}

} // namespace ob::game
