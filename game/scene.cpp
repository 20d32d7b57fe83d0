// Scene loading: TOML document + overrides → SceneDef, all errors at once.
#include "scene.h"

#include "core/error.h"
#include "core/toml_reader.h"

#include <filesystem>

namespace ob::game {

static SceneDef readScene(TomlDocument& doc, const std::string& source, std::vector<std::string>& errors,
                          const std::vector<std::string>& overrides) {
    for (const std::string& o : overrides) doc.applyOverride(o, errors);
    SceneDef scene;
    TomlReader reader(doc, errors);
    describe(reader, scene);
    reader.finish();
    // Checks across keys, once every key is read and in range.
    if (errors.empty()) {
        for (const std::string& e : ocean::validate(scene.gerstner, &scene.ocean)) errors.push_back(source + ": " + e);
        for (const std::string& e : validateEvents(scene, source)) errors.push_back(e);
    }
    if (!errors.empty()) {
        std::string message;
        for (const std::string& e : errors) message += (message.empty() ? "" : "\n") + e;
        throw InputError(message);
    }
    return scene;
}

SceneDef loadScene(const std::string& path, const std::vector<std::string>& overrides) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromFile(path, errors);
    if (!errors.empty()) return readScene(doc, path, errors, {});  // throws: an unreadable file has no keys to check
    return readScene(doc, path, errors, overrides);
}

SceneDef parseScene(const std::string& text, const std::string& sourceName, const std::vector<std::string>& overrides) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromString(text, sourceName, errors);
    if (!errors.empty()) return readScene(doc, sourceName, errors, {});
    return readScene(doc, sourceName, errors, overrides);
}

std::string defaultScenePath() {
    const char* relative = "config/scenes/default.toml";
    if (std::filesystem::exists(relative)) return relative;
    return std::string(OCEANBOX_SOURCE_DIR) + "/" + relative;
}

} // namespace ob::game
