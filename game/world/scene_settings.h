// The world's one SceneDef (a resource) and a version per live section. Systems read the
// scene here; what keeps its own parameters (the ripple patch, the camera rigs, the renderer)
// takes its section again when the section's version has moved since it last looked.
#pragma once
#include "ecs/schedule.h"
#include "world/scene.h"

#include <array>
#include <cstdint>

namespace ob::game {

/// The sections with live keys (core/schema.h: LIVE), the unit a version counts changes of.
enum class SceneSection : uint8_t { Camera, Render, Sky, Ocean, Gerstner, Ripples, Physics, Currents, Tools };
constexpr std::array<const char*, 9> names(SceneSection) {
    return {"camera", "render", "sky", "ocean", "gerstner", "ripples", "physics", "currents", "tools"};
}

/// The scene as the world runs it (a resource, made first by the sandbox).
struct SceneSettings {
    SceneDef def;  ///< the scene; live changes (a `set`, the UI) edit it in place
    std::array<uint64_t, enumNames<SceneSection>.size()> versions{};  ///< per section: changes so far
    /// How many times `section` changed since the world was built.
    uint64_t version(SceneSection section) const { return versions[size_t(section)]; }
    /// Says that a key of `section` changed (whoever edits `def` calls it).
    void changed(SceneSection section) { ++versions[size_t(section)]; }
};

/// What one reader last saw of a section: `if (seen.moved(settings, SceneSection::Render)) ...`.
struct SectionSeen {
    uint64_t version = 0;  ///< the section's version when last taken (0: as built)
    /// True once per change of `section` since the last call.
    bool moved(const SceneSettings& settings, SceneSection section) {
        const uint64_t now = settings.version(section);
        if (now == version) return false;
        version = now;
        return true;
    }
};

/// The world's scene; asserts that the world has one.
SceneSettings& sceneSettings(ecs::World& world);
/// Makes the scene resource (before anything that reads it).
SceneSettings& addSceneSettings(ecs::World& world, const SceneDef& scene);
/// Script phase, after the timeline: hands the sections that changed in this step to what
/// keeps its own copy (the camera rigs, the ripple patch's damping). Physics reads [physics]
/// in place; the sea's changes cross-fade (changeSea); the view takes [render] per frame.
void settingsSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
