// Weather presets of the Sea panel: calm, breeze, storm, each a list of live `set`s applied
// together (one cross-fade of the sea, ocean/sea_fade.h).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ob::ecs {
class World;
}

namespace ob::game {

/// A weather the Sea panel offers in one click.
enum class SeaPreset : uint8_t {
    Calm,    ///< 3 m/s: wavelets, hardly a swell
    Breeze,  ///< 8 m/s: moderate sea, some whitecaps
    Storm,   ///< 20 m/s: high, choppy sea on a long swell, foam everywhere
};
constexpr std::array<const char*, 3> names(SeaPreset) { return {"calm", "breeze", "storm"}; }

/// One key and value of a preset.
struct PresetSet {
    const char* key;
    float value;
};

/// The keys a preset sets: ocean.wind_speed, ocean.amplitude, ocean.choppiness,
/// gerstner.count (8: a scene without Gerstner waves gains the swell), gerstner.amplitude_scale,
/// sky.cloud_cover (calm 0, breeze 0.3, storm 1).
std::vector<PresetSet> presetSets(SeaPreset preset);

/// Requests every key of `preset` (requestLiveSet): applied together at the next step.
/// Returns "" or the first refusal.
std::string requestPreset(ecs::World& world, SeaPreset preset);

} // namespace ob::game
