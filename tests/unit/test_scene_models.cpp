// Scene objects' model paths: resolved next to the scene first, then in the current folder,
// then in the source tree; stored back absolute; a bad file is one error at its key.
#include "core/error.h"
#include "world/scene.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>

using ob::InputError;
using ob::test::tempPath;
using ob::test::writeFile;
namespace fs = std::filesystem;

namespace {

const std::string SOURCE_BALL = std::string(OCEANBOX_SOURCE_DIR) + "/assets/models/cannonball.gltf";

std::string sceneError(const std::string& path) {
    try {
        ob::game::loadScene(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("a relative model path is found next to the scene before the current folder and the source tree", "[scene][models]") {
    // The scene's folder holds its own assets/models/cannonball.gltf, shadowing the source tree's.
    const fs::path folder = fs::path(tempPath("scene_folder"));
    fs::create_directories(folder / "assets/models");
    fs::copy_file(SOURCE_BALL, folder / "assets/models/cannonball.gltf");
    const std::string scene = writeFile((folder / "s.toml").string(), "[[objects]]\nmodel = \"assets/models/cannonball.gltf\"\n[[objects]]\n");
    ob::game::SceneDef def = ob::game::loadScene(scene);
    REQUIRE(def.objects.size() == 2);
    CHECK(fs::path(def.objects[0].model).is_absolute());
    CHECK(fs::equivalent(def.objects[0].model, folder / "assets/models/cannonball.gltf"));
    CHECK(def.objects[1].model.empty());  // no model: the built-in mesh
}

TEST_CASE("a relative model path absent next to the scene resolves in the source tree and an absolute one stays", "[scene][models]") {
    const std::string scene = writeFile(tempPath("elsewhere.toml"), "[[objects]]\nmodel = \"assets/models/cannonball.gltf\"\n"
                                                                    "[[objects]]\nmodel = \"" + SOURCE_BALL + "\"\n");
    // From a working folder that has no assets/: only the source tree holds the file.
    struct Cwd {
        fs::path saved = fs::current_path();
        ~Cwd() { fs::current_path(saved); }
    } restore;
    fs::current_path(fs::path(scene).parent_path());
    ob::game::SceneDef def = ob::game::loadScene(scene);
    CHECK(fs::equivalent(def.objects[0].model, SOURCE_BALL));
    CHECK(def.objects[1].model == SOURCE_BALL);
}

TEST_CASE("missing and corrupt model files are each reported at their key, with the other scene errors' format", "[scene][models]") {
    const std::string scene = tempPath("two_bad.toml");
    const std::string bad = (fs::path(scene).parent_path() / "lines_only.gltf").string();
    writeFile(bad, R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {}, "mode": 1}]}],
                       "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})");
    writeFile(scene, "[[objects]]\nmodel = \"nowhere/none.glb\"\n[[objects]]\nmodel = \"lines_only.gltf\"\n");
    const std::string e = sceneError(scene);
    INFO(e);
    CHECK(e.find(scene + ":2:9: objects[0].model: glTF file 'nowhere/none.glb' not found") != std::string::npos);
    CHECK(e.find(scene + ":4:9: objects[1].model: " + bad + ": no triangles") != std::string::npos);
    CHECK(std::count(e.begin(), e.end(), '\n') == 1);  // two problems, two lines
}
