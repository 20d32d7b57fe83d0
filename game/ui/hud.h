// The folded overlay: the compact HUD (fps, the tool, the goal's state), the start card, the
// goal's result panel and the cues the goal's events leave on the water. What a newcomer sees.
#pragma once
#include "ecs/schedule.h"
#include "ecs/world.h"
#include "world/scene.h"

#include <string>
#include <vector>

namespace ob::game {

/// The overlay's size for a framebuffer of `size` px on a display of `contentScale` (DPI /
/// 96): [window] ui_scale when set, else contentScale × height / 720 within [0.75, 3].
float overlayScale(const platform::WindowDef& window, glm::ivec2 size, float contentScale);
/// The start card's text for a scene from `path`: [game] intro, else the first sentence of
/// the file's opening comment.
std::string startCardText(const SceneDef& scene, const std::string& path);
/// The card's keys: the few that matter in this world (its ship, its cannon, its tools, the
/// way under water and back: C to fly where the camera does not, Q down, E up), then H for the rest.
std::string startCardKeys(ecs::World& world);

/// Top right: fps, the tool (and why a key was refused), the goal's count and clock, "H panels".
void compactHud(ecs::World& world, const ecs::FrameTimer& timer);
/// Bottom centre while it shows: the card's text and keys; any input dismisses it.
void startCard(ecs::World& world);
/// Over the sky once the run is over (a goal decided, or [sim] end_time): what ended it.
void resultPanel(ecs::World& world);
/// A ring on the water where each of the goal's latest events happened, fading over 1.5 s.
void goalCues(ecs::World& world);

} // namespace ob::game
