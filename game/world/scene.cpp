// Scene loading: TOML document + overrides → SceneDef, all errors at once.
#include "world/scene.h"

#include "assets/model.h"
#include "core/error.h"
#include "core/file_identity.h"
#include "core/file_write.h"
#include "core/printable.h"
#include "core/toml_writer.h"
#include "core/toml_reader.h"
#include "goals/goals.h"
#include "world/scene_budget.h"

#include <filesystem>
#include <set>

namespace ob::game {

// An object's model file: an absolute path as it is; a relative one next to the scene file
// (`sceneDir`, "" for a scene from text), then in the current folder, then in the source
// tree; returned absolute, so it names the same file from any working folder. "" when none
// exists.
static std::string resolveModel(const std::string& model, const std::string& sceneDir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // A link counts as there even when it dangles or loops: the loader then says which.
    auto present = [&](const fs::path& p) { return fs::exists(fs::symlink_status(p, ec)); };
    if (fs::path(model).is_absolute()) return present(model) ? model : "";
    std::vector<fs::path> candidates;
    if (!sceneDir.empty()) candidates.push_back(fs::path(sceneDir) / model);
    candidates.push_back(fs::path(model));
    candidates.push_back(fs::path(OCEANBOX_SOURCE_DIR) / model);
    for (const fs::path& c : candidates)
        if (present(c)) return fs::absolute(c, ec).lexically_normal().string();
    return "";
}

// One model key (`key`, "objects[0].model"): the path resolved in place, and the file and
// its far twin (X.lod1.gltf, drawn at a distance) loaded once to check them (the renderer
// loads its own copy), so a bad file fails here with the scene's location, not when drawn.
static void checkModel(std::string& model, const std::string& key, const TomlDocument& doc, const std::string& source,
                       const std::string& sceneDir, std::vector<std::string>& errors) {
    if (model.empty()) return;
    const std::string at = doc.where(key, source) + ": " + key + ": ";
    const std::string path = resolveModel(model, sceneDir);
    if (path.empty()) {
        errors.push_back(at + "glTF file " + quotedValue(model) + " not found" +
                         (std::filesystem::path(model).is_absolute()
                              ? std::string()
                              : " (looked next to the scene, in the current folder and in the source tree)"));
        return;
    }
    try {
        assets::loadGltfModel(path);
        const std::string far = assets::lodTwinPath(path);
        std::error_code ec;
        if (std::filesystem::exists(far, ec)) assets::loadGltfModel(far);
        model = path;
    } catch (const InputError& e) {
        errors.push_back(at + e.what());
    }
}

// Every model of the scene: the objects' and those spawn events add.
static void checkModels(SceneDef& scene, const TomlDocument& doc, const std::string& source, const std::string& sceneDir,
                        std::vector<std::string>& errors) {
    for (size_t i = 0; i < scene.objects.size(); ++i)
        checkModel(scene.objects[i].model, "objects[" + std::to_string(i) + "].model", doc, source, sceneDir, errors);
    for (size_t k = 0; k < scene.events.size(); ++k)
        if (scene.events[k].action == EventAction::Spawn)
            checkModel(scene.events[k].object.model, "events[" + std::to_string(k) + "].object.model", doc, source, sceneDir, errors);
}

// A spawn event names the object it adds: without `object` it would add a default sphere
// nobody asked for.
static void checkSpawnObjects(const SceneDef& scene, const TomlDocument& doc, const std::string& source,
                              std::vector<std::string>& errors) {
    for (size_t k = 0; k < scene.events.size(); ++k) {
        const std::string key = "events[" + std::to_string(k) + "]";
        if (scene.events[k].action == EventAction::Spawn && doc.where(key + ".object", "").empty())
            errors.push_back(doc.where(key + ".action", source) + ": " + key +
                             ".object: a spawn event needs the object it adds (object = { type = \"sphere\", ... }, "
                             "the keys of an [[objects]] entry)");
    }
}

// Every name the scene can refer to: its objects' and those its spawn events add.
static std::set<std::string> objectNames(const SceneDef& scene) {
    std::set<std::string> names;
    for (const ObjectDef& o : scene.objects) names.insert(o.name);
    for (const EventDef& e : scene.events)
        if (e.action == EventAction::Spawn) names.insert(e.object.name);
    names.erase("");
    return names;
}

// The names keys refer to resolve now, not as a frozen camera later: camera.follow names an
// object; following "the player's ship, else the first" (follow = "") needs a ship.
static void checkNames(const SceneDef& scene, const TomlDocument& doc, const std::string& source, std::vector<std::string>& errors) {
    const std::set<std::string> names = objectNames(scene);
    bool ship = false;
    for (const ObjectDef& o : scene.objects) ship = ship || o.type == ObjectType::Ship;
    for (const EventDef& e : scene.events) ship = ship || (e.action == EventAction::Spawn && e.object.type == ObjectType::Ship);
    const std::string& follow = scene.camera.follow;
    if (!follow.empty() && !names.count(follow))
        errors.push_back(doc.where("camera.follow", source) + ": camera.follow: no object is named " + quotedValue(follow));
    const bool needsShip = follow.empty() && !ship;
    if (needsShip && scene.ripples.enabled && scene.ripples.follow == interaction::RippleFollow::Ship)
        errors.push_back(doc.where("ripples.follow", source) +
                         ": ripples.follow: \"ship\" keeps the patch under the ship camera.follow names (\"\": the player's "
                         "ship, else the first), and the scene has no ship (add one, or choose \"camera\" or \"fixed\")");
    if (needsShip && scene.camera.mode == CameraMode::Follow)
        errors.push_back(doc.where("camera.mode", source) +
                         ": camera.mode: \"follow\" follows the object camera.follow names (\"\": the player's ship, else "
                         "the first), and the scene has no ship (name an object in camera.follow, or choose another mode)");
}

// A screenshot event's file, from the scene file: a relative path that stays in the scene's
// folder or below once links are resolved, and not the scene itself (a shared scene must not
// write where its author likes). Stored absolute, as resolved. A file given by --set is the
// user's own choice, kept as typed.
static void confineEventFiles(SceneDef& scene, const TomlDocument& doc, const std::string& scenePath,
                              std::vector<std::string>& errors) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = fs::absolute(fs::path(scenePath), ec).parent_path();
    for (size_t k = 0; k < scene.events.size(); ++k) {
        EventDef& e = scene.events[k];
        const std::string key = "events[" + std::to_string(k) + "].file";
        // The default file ("event.png") is the scene's too: named at the event's action.
        const std::string at = doc.where(key, doc.where("events[" + std::to_string(k) + "].action", ""));
        if (e.action != EventAction::Screenshot || e.file.empty() || at.empty() || at.rfind("--set", 0) == 0) continue;
        const std::string head = at + ": " + key + ": " + quotedValue(e.file) + " ";
        const fs::path file(e.file);
        bool up = false;
        for (const fs::path& part : file) up = up || part == "..";
        if (file.is_absolute() || up) {
            errors.push_back(head + "must be a path relative to the scene's folder, without '..' (a scene writes only "
                                    "in its own folder or below; --screenshot writes anywhere)");
            continue;
        }
        const std::string path = (folder / file).lexically_normal().string();
        if (!isInsideFolder(path, folder.string()))
            errors.push_back(head + "leads outside the scene's folder " + quotedValue(folder.string()) +
                             " through a symbolic link (a scene writes only in its own folder or below)");
        else if (sameFile(path, scenePath))
            errors.push_back(head + "is the scene file itself (an output never replaces an input)");
        else
            e.file = path;
    }
}

void applyEnvironment(SceneDef& scene) {
    const environment::EnvironmentDef& env = scene.environment;
    scene.physics.gravity = env.gravity;
    scene.physics.water_density = env.water_density;
    scene.physics.air_density = env.air_density;
    scene.ocean.gravity = env.gravity;  // spectrum dispersion and Gerstner waves
    scene.ripples.environment = env;
    scene.splash.environment = env;
}

// `scenePath`: the scene's file ("" for a scene from text, whose outputs are as given).
static SceneDef readScene(TomlDocument& doc, const std::string& source, const std::string& sceneDir, const std::string& scenePath,
                          std::vector<std::string>& errors, const std::vector<std::string>& overrides) {
    for (const std::string& o : overrides) doc.applyOverride(o, errors);
    SceneDef scene;
    TomlReader reader(doc, errors);
    describe(reader, scene);
    reader.finish();
    applyEnvironment(scene);
    // Checks across keys and files, once every key is read and in range.
    if (errors.empty()) {
        for (const std::string& e : ocean::validate(scene.gerstner, &scene.ocean)) errors.push_back(source + ": " + e);
        for (const std::string& e : validateEvents(scene, source, &doc)) errors.push_back(e);
        for (const std::string& e : validateGame(scene.game, scene.objects, [&](const std::string& key) { return doc.where(key, source); }))
            errors.push_back(e);
        for (const interaction::RippleDefError& e : interaction::validate(scene.ripples))
            errors.push_back(doc.where("ripples." + e.key, source) + ": ripples." + e.key + ": " + e.message);
        checkSpawnObjects(scene, doc, source, errors);
        checkNames(scene, doc, source, errors);
        checkModels(scene, doc, source, sceneDir, errors);
        if (!scenePath.empty()) confineEventFiles(scene, doc, scenePath, errors);
        // Before anything is allocated: a scene whose grids cannot fit is bad input, not bad_alloc.
        if (std::string m = checkSceneMemory(scene, processMemoryLimit()); !m.empty()) errors.push_back(source + ": " + m);
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
    const std::string sceneDir = std::filesystem::path(path).parent_path().string();
    if (!errors.empty()) return readScene(doc, path, sceneDir, path, errors, {});  // throws: an unreadable file has no keys to check
    return readScene(doc, path, sceneDir.empty() ? "." : sceneDir, path, errors, overrides);
}

SceneDef parseScene(const std::string& text, const std::string& sourceName, const std::vector<std::string>& overrides) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromString(text, sourceName, errors);
    if (!errors.empty()) return readScene(doc, sourceName, "", "", errors, {});
    return readScene(doc, sourceName, "", "", errors, overrides);
}

std::vector<NamedPath> sceneInputs(const SceneDef& scene, const std::string& scenePath) {
    std::vector<NamedPath> inputs{{"the scene file", scenePath}};
    auto model = [&](const std::string& path, const std::string& key) {
        if (path.empty()) return;
        inputs.push_back({key + "'s model", path});
        inputs.push_back({key + "'s far model", assets::lodTwinPath(path)});
    };
    for (size_t i = 0; i < scene.objects.size(); ++i) model(scene.objects[i].model, "objects[" + std::to_string(i) + "]");
    for (size_t k = 0; k < scene.events.size(); ++k)
        if (scene.events[k].action == EventAction::Spawn) model(scene.events[k].object.model, "events[" + std::to_string(k) + "].object");
    return inputs;
}

std::vector<NamedPath> sceneOutputs(const SceneDef& scene) {
    std::vector<NamedPath> outputs;
    for (size_t k = 0; k < scene.events.size(); ++k)
        if (scene.events[k].action == EventAction::Screenshot)
            outputs.push_back({"events[" + std::to_string(k) + "].file", scene.events[k].file});
    return outputs;
}

ObjectDef droppedShip(const SceneDef& scene) {
    ObjectDef ship;
    ship.type = ObjectType::Ship;
    ship.model = resolveModel("assets/models/ship.gltf", "");
    ship.color = {0.6f, 0.15f, 0.1f};
    for (const ObjectDef& o : scene.objects)
        if (o.type == ObjectType::Ship) {
            ship = o;
            break;
        }
    ship.ship.player = false;
    ship.ship.waypoints.clear();
    ship.ship.speed = 3.0f;
    ship.ship.velocity = glm::vec3(0.0f);
    return ship;
}

std::string defaultScenePath() {
    const char* relative = "config/scenes/default.toml";
    if (std::filesystem::exists(relative)) return relative;
    return std::string(OCEANBOX_SOURCE_DIR) + "/" + relative;
}

std::string saveScene(SceneDef scene, const std::string& path) {
    // Model paths are absolute once loaded; the file names them relative to itself, so the
    // scene and its models move together.
    namespace fs = std::filesystem;
    const fs::path folder = fs::absolute(fs::path(path)).parent_path();
    auto relative = [&](ObjectDef& o) {
        if (!o.model.empty() && fs::path(o.model).is_absolute()) o.model = fs::path(o.model).lexically_relative(folder).string();
    };
    for (ObjectDef& o : scene.objects) relative(o);
    for (EventDef& e : scene.events)
        if (e.action == EventAction::Spawn) relative(e.object);
    // A screenshot event's file, absolute once loaded, is written relative too; one that would
    // leave the new folder goes beside the saved scene (a scene writes only in its folder).
    for (EventDef& e : scene.events) {
        if (e.action != EventAction::Screenshot || !fs::path(e.file).is_absolute()) continue;
        const fs::path rel = fs::path(e.file).lexically_relative(folder);
        const bool up = rel.empty() || *rel.begin() == "..";
        e.file = up ? fs::path(e.file).filename().string() : rel.string();
    }
    try {
        writeFileWhole(path, "scene", [&](std::ostream& out) {
            out << "# Saved from oceanbox: the keys that differ from the defaults.\n" << writeToml(scene);
        });
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string checkEditedScene(SceneDef& scene) {
    try {
        parseScene(writeToml(scene), "edited scene");
        return "";
    } catch (const InputError& e) {
        return e.what();
    }
}

} // namespace ob::game
