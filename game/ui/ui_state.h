// What the overlay keeps between frames, per world (a resource the view adds): the scene
// editor's copy, the save box, the Sea panel's dragged values, the picker's list. A new world
// (R, a scene switch, "restart with these settings") starts with its own.
#pragma once
#include "world/scene.h"

#include <map>
#include <string>
#include <vector>

namespace ob::game {

/// A value dragged on a live slider but not yet seen back in the scene (ui/sea_panel.cpp).
struct SliderDraft {
    float value = 0.0f;
    int framesLeft = 0;
};

/// A scene file the picker lists: its name and its opening comment (every line of it).
struct SceneEntry {
    std::string path, name, description;
};

/// The overlay's state (a resource).
struct UiState {
    SceneDef edited;             ///< the scene editor's copy of this world's scene (applied by restarting)
    std::string editProblem;     ///< why "restart with these settings" refused the copy
    std::string savePath = "saved_scene.toml";  ///< the save box's file
    std::string saveStatus;      ///< what the last save said
    std::map<std::string, SliderDraft> drafts;  ///< the Sea panel's dragged values, by key
    std::string seaStatus;       ///< what the Sea panel's last request said
    std::vector<SceneEntry> scenes;  ///< the picker's list (read when it first opens)
    std::string pickProblem;     ///< why the chosen scene did not load
};

/// The world's overlay state, made from its scene at the first call.
UiState& uiState(ecs::World& world);
/// The scene "save scene as" writes: the editor's copy of this world's scene, with the live
/// [render] keys.
SceneDef sceneToSave(ecs::World& world);

} // namespace ob::game
