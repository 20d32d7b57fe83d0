// The weather presets' values (wind speeds on the Beaufort scale: 3 m/s force 2, 8 m/s force 5,
// 20 m/s force 8–9).
#include "world/sea_presets.h"

#include "world/script.h"

namespace ob::game {

std::vector<PresetSet> presetSets(SeaPreset preset) {
    switch (preset) {
    case SeaPreset::Calm:
        return {{"ocean.wind_speed", 3.0f}, {"ocean.choppiness", 0.5f}, {"gerstner.count", 8.0f}, {"gerstner.amplitude_scale", 0.3f}};
    case SeaPreset::Breeze:
        return {{"ocean.wind_speed", 8.0f}, {"ocean.choppiness", 1.0f}, {"gerstner.count", 8.0f}, {"gerstner.amplitude_scale", 1.0f}};
    case SeaPreset::Storm:
        return {{"ocean.wind_speed", 20.0f}, {"ocean.choppiness", 1.8f}, {"gerstner.count", 8.0f}, {"gerstner.amplitude_scale", 1.5f}};
    }
    return {};
}

std::string requestPreset(ecs::World& world, SeaPreset preset) {
    for (const PresetSet& s : presetSets(preset))
        if (std::string m = requestLiveSet(world, s.key, s.value); !m.empty()) return m;
    return "";
}

} // namespace ob::game
