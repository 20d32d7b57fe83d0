// The scene's keys as a live change sees them, from the schema: a key is live where its Def's
// describe() marks it LIVE (core/schema.h). `set` events, input scripts' [[set]], the UI and
// requestLiveSet all ask here.
#pragma once
#include "core/schema.h"
#include "world/scene_settings.h"

#include <optional>
#include <string>
#include <vector>

namespace ob::game {

/// A number or switch of the scene, as a `set` reaches it.
struct SceneKey {
    std::string path;                ///< "render.exposure"
    Limits limits;                   ///< its range (switches: none)
    bool integer = false;            ///< takes whole numbers
    bool switch_ = false;            ///< a bool: 0 or 1
    Change change = Change::AtStart; ///< whether it may change while the world runs
};

/// A live key that no Def field holds: the wind's heading in degrees, counter-clockwise from
/// +x toward +z (a `set` carries one number; ocean.wind_direction is a vector). It writes
/// ocean.wind_direction = [cos, sin].
constexpr const char* WIND_DIRECTION_DEG = "ocean.wind_direction_deg";
/// Two more: the uniform current's speed (m/s, [0, 10]) and heading (degrees as the wind's);
/// they write currents.uniform = speed·[cos, sin].
constexpr const char* CURRENT_SPEED = "currents.speed";
constexpr const char* CURRENT_DIRECTION_DEG = "currents.direction_deg";

/// Every number and switch of the scene's sections, in describe() order.
std::vector<SceneKey> sceneKeys();
/// The keys a `set` may change while the world runs (the LIVE ones, WIND_DIRECTION_DEG and the current's two).
std::vector<std::string> liveKeys();
/// The live keys as one line for messages and help.
std::string liveKeyHelp();
/// "" when `key` is a live key of the scene and `value` fits its range, else why not
/// ("key: ..." or "value: ...").
std::string checkLiveSet(const std::string& key, float value);
/// The value of a number or switch of `scene` (a switch: 0 or 1); none for a key no Def field holds.
std::optional<float> keyValue(const SceneDef& scene, const std::string& key);
/// Writes a checked live change into `scene`; returns the section it changed.
SceneSection setLiveKey(SceneDef& scene, const std::string& key, float value);

} // namespace ob::game
