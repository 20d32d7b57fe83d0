// Live keys from the schema: one walk of SceneDef's describe() finds a key, its range and its
// LIVE mark.
#include "world/live_keys.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace ob::game {

namespace {

constexpr double WIND_DIRECTION_LIMIT = 3600.0;  // degrees either way
constexpr float CURRENT_SPEED_LIMIT = 10.0f;     // m/s: the uniform current's components' range

// Visits the scene's numbers and switches with their full path: `found(key, slot)` is called
// for each with a SceneKey and the address of its value.
template <class Found> struct KeyWalk {
    Found found;
    std::string prefix;

    void field(const char* key, bool& v, const char*, Change c = {}) { found(SceneKey{prefix + key, any(), false, true, c}, &v); }
    void field(const char* key, int& v, Limits l, const char*, Change c = {}) { found(SceneKey{prefix + key, l, true, false, c}, &v); }
    void field(const char* key, float& v, Limits l, const char*, Change c = {}) { found(SceneKey{prefix + key, l, false, false, c}, &v); }
    void field(const char*, uint64_t&, const char*, Change = {}) {}
    void field(const char*, glm::vec2&, Limits, const char*, Change = {}) {}
    void field(const char*, glm::vec3&, Limits, const char*, Change = {}) {}
    void field(const char*, std::string&, const char*, Change = {}) {}
    template <NamedEnum E> void field(const char*, E&, const char*, Change = {}) {}
    template <NamedEnum E> void field(const char*, std::vector<E>&, const char*, Change = {}) {}
    void field(const char*, std::vector<glm::vec2>&, Limits, const char*, Change = {}) {}
    template <class Def> void section(const char* key, Def& def) {
        const std::string saved = prefix;
        prefix += std::string(key) + ".";
        describe(*this, def);
        prefix = saved;
    }
    template <class Item> void list(const char*, std::vector<Item>&, const char*) {}
    template <class Def> void fields(Def&) {}
};

template <class Found> void walkKeys(SceneDef& scene, Found found) {
    KeyWalk<Found> walk{std::move(found), {}};
    describe(walk, scene);
}

// The key `path` of `scene` and where its value is (null when the scene has no such number).
struct Slot {
    SceneKey key;
    void* value = nullptr;
};
Slot findKey(SceneDef& scene, const std::string& path) {
    Slot slot;
    walkKeys(scene, [&](const SceneKey& k, void* v) {
        if (k.path == path) slot = {k, v};
    });
    return slot;
}

// "" when `value` fits the key.
std::string checkValue(const SceneKey& key, float value) {
    if (key.switch_) return value == 0.0f || value == 1.0f ? "" : "a switch takes 0 or 1";
    if (key.integer && value != std::floor(value)) return "this key takes an integer";
    if (!inRange(key.limits, value)) return "value out of the key's range: " + rangeText(key.limits);
    return "";
}

} // namespace

std::vector<SceneKey> sceneKeys() {
    SceneDef scene;
    std::vector<SceneKey> keys;
    walkKeys(scene, [&](const SceneKey& k, void*) { keys.push_back(k); });
    return keys;
}

std::vector<std::string> liveKeys() {
    std::vector<std::string> keys;
    for (const SceneKey& k : sceneKeys())
        if (k.change == Change::Live) keys.push_back(k.path);
    keys.push_back(WIND_DIRECTION_DEG);
    keys.push_back(CURRENT_SPEED);
    keys.push_back(CURRENT_DIRECTION_DEG);
    return keys;
}

std::string liveKeyHelp() {
    std::string line;
    for (const std::string& k : liveKeys()) line += (line.empty() ? "" : ", ") + k;
    return line;
}

std::string checkLiveSet(const std::string& key, float value) {
    if (key == WIND_DIRECTION_DEG || key == CURRENT_DIRECTION_DEG)
        return std::abs(value) <= WIND_DIRECTION_LIMIT
                   ? ""
                   : "value: " + key + " takes degrees in [-3600, 3600], got " + std::to_string(value);
    if (key == CURRENT_SPEED)
        return value >= 0.0f && value <= CURRENT_SPEED_LIMIT
                   ? ""
                   : "value: " + key + " takes m/s in [0, 10], got " + std::to_string(value);
    SceneDef scene;
    const Slot slot = findKey(scene, key);
    if (!slot.value) return "key: '" + key + "' is not a number or switch of the scene";
    if (slot.key.change != Change::Live) return "key: '" + key + "' is read once at start; live keys: " + liveKeyHelp();
    if (std::string m = checkValue(slot.key, value); !m.empty()) return "value: " + m + " (" + key + ")";
    return "";
}

std::optional<float> keyValue(const SceneDef& scene, const std::string& key) {
    SceneDef copy = scene;  // the walk takes its slots writable
    const Slot slot = findKey(copy, key);
    if (!slot.value) return std::nullopt;
    if (slot.key.switch_) return *static_cast<const bool*>(slot.value) ? 1.0f : 0.0f;
    if (slot.key.integer) return float(*static_cast<const int*>(slot.value));
    return *static_cast<const float*>(slot.value);
}

SceneSection setLiveKey(SceneDef& scene, const std::string& key, float value) {
    if (key == WIND_DIRECTION_DEG) {
        const double rad = double(value) * std::numbers::pi / 180.0;
        scene.ocean.wind_direction = {float(std::cos(rad)), float(std::sin(rad))};
        return SceneSection::Ocean;
    }
    if (key == CURRENT_SPEED || key == CURRENT_DIRECTION_DEG) {
        glm::vec2& u = scene.currents.uniform;
        const float speed = key == CURRENT_SPEED ? value : std::hypot(u.x, u.y);
        const double rad = key == CURRENT_DIRECTION_DEG ? double(value) * std::numbers::pi / 180.0 : std::atan2(u.y, u.x);
        u = speed * glm::vec2(float(std::cos(rad)), float(std::sin(rad)));
        return SceneSection::Currents;
    }
    const Slot slot = findKey(scene, key);
    assert(slot.value && slot.key.change == Change::Live && "checkLiveSet first");
    if (slot.key.switch_) *static_cast<bool*>(slot.value) = value != 0.0f;
    else if (slot.key.integer) *static_cast<int*>(slot.value) = int(value);
    else *static_cast<float*>(slot.value) = value;
    SceneSection section{};
    [[maybe_unused]] const bool known = enumFromName(key.substr(0, key.find('.')), section);
    assert(known && "a live key's section has a version");
    return section;
}

} // namespace ob::game
