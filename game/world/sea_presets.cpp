// The weather presets' values (wind speeds on the Beaufort scale: 3 m/s force 2, 8 m/s force 5,
// 20 m/s force 8–9). Calm and breeze keep the Pierson–Moskowitz level A = 0.0009 (a fully
// developed sea). The storm's A = 0.002 is a young, fetch-limited sea: JONSWAP's
// α = 0.076·(V²/(F·g))^0.22 is 2.2× Pierson–Moskowitz's for 20 m/s over 30 km. Phillips' tail
// does not grow with V (only waves longer than V²/g do, and at 20 m/s those are longer than the
// 250 m tile: the Gerstner swell's), so without it a storm's short waves look like a breeze's.
// The storm's choppiness stays at 1.4: with 1.8 on this steeper spectrum the surface folds so
// often that a ship's buoyancy and drag (against the water's vertical velocity, undefined on a
// fold) can throw it out of the water. The sky goes with the sea: calm under a clear sky, a
// breeze with fair-weather cumulus, a storm under an overcast (docs/look.md#weather).
#include "world/sea_presets.h"

#include "world/script.h"

namespace ob::game {

std::vector<PresetSet> presetSets(SeaPreset preset) {
    switch (preset) {
    case SeaPreset::Calm:
        return {{"ocean.wind_speed", 3.0f}, {"ocean.amplitude", 0.0009f}, {"ocean.choppiness", 0.5f}, {"gerstner.count", 8.0f}, {"gerstner.amplitude_scale", 0.3f}, {"sky.cloud_cover", 0.0f}};
    case SeaPreset::Breeze:
        return {{"ocean.wind_speed", 8.0f}, {"ocean.amplitude", 0.0009f}, {"ocean.choppiness", 1.0f}, {"gerstner.count", 8.0f}, {"gerstner.amplitude_scale", 1.0f}, {"sky.cloud_cover", 0.3f}};
    case SeaPreset::Storm:
        return {{"ocean.wind_speed", 20.0f}, {"ocean.amplitude", 0.002f}, {"ocean.choppiness", 1.4f}, {"gerstner.count", 8.0f}, {"gerstner.amplitude_scale", 1.5f}, {"sky.cloud_cover", 1.0f}};
    }
    return {};
}

std::string requestPreset(ecs::World& world, SeaPreset preset) {
    for (const PresetSet& s : presetSets(preset))
        if (std::string m = requestLiveSet(world, s.key, s.value); !m.empty()) return m;
    return "";
}

} // namespace ob::game
