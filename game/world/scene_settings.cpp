// The scene resource, and the push of a changed section to the objects that keep a copy.
#include "world/scene_settings.h"

#include "currents/current_layer.h"
#include "interaction/ripple_patch.h"
#include "world/camera.h"
#include "world/tools.h"

#include <cassert>

namespace ob::game {

namespace {

// What the settings system last handed on.
struct SettingsSeen {
    SectionSeen camera;
    SectionSeen ripples;
    SectionSeen currents;
    SectionSeen tools;
    ToolsDef toolsTaken;  // [tools] as the palette last took it: a live set hands on the keys it changed
};

// The palette's live numbers ([tools] keys marked LIVE): the player's wheel changes some of them
// in the palette too, so a live set hands on only the keys it changed.
constexpr float ToolsDef::*LIVE_TOOL_KEYS[] = {&ToolsDef::ball_radius, &ToolsDef::ball_density, &ToolsDef::drop_height,
                                               &ToolsDef::stir_radius, &ToolsDef::stir_depth, &ToolsDef::grab_frequency_hz};

} // namespace

SceneSettings& sceneSettings(ecs::World& world) {
    SceneSettings* settings = world.resource<SceneSettings>();
    assert(settings && "the sandbox makes the scene resource first");
    return *settings;
}

SceneSettings& addSceneSettings(ecs::World& world, const SceneDef& scene) {
    world.setResource(std::make_unique<SettingsSeen>()).toolsTaken = scene.tools;
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
    if (seen->tools.moved(*settings, SceneSection::Tools)) {
        if (auto* tools = world.resource<PlayerTools>())
            for (float ToolsDef::*key : LIVE_TOOL_KEYS)
                if (settings->def.tools.*key != seen->toolsTaken.*key) tools->def.*key = settings->def.tools.*key;
        seen->toolsTaken = settings->def.tools;
    }
}

} // namespace ob::game
