// `oceanbox make-models` and scenes that name glTF models: the committed models are the
// generator's output byte for byte; a missing or corrupt model file is bad input (exit 2)
// named by scene file, line and key.
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using ob::test::runOceanbox;
using ob::test::tempPath;
using ob::test::writeFile;

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

const char* const MODELS[] = {"ship", "fish", "fish.lod1", "cannonball", "cannonball.lod1", "cannon"};

} // namespace

TEST_CASE("make-models writes the same bytes as the committed assets/models files", "[cli][models]") {
    const std::string out = tempPath("models");
    auto r = runOceanbox("make-models --out " + out);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    for (const char* name : MODELS) {
        INFO(name);
        const std::string made = readBytes(out + "/" + name + ".gltf");
        const std::string committed = readBytes(std::string(OCEANBOX_SOURCE_DIR) + "/assets/models/" + name + ".gltf");
        REQUIRE(made.size() > 1000);
        CHECK(made == committed);  // if not: run `oceanbox make-models` and commit assets/models
    }
    // A second run writes the same bytes again.
    REQUIRE(runOceanbox("make-models --out " + out + "/again").exitCode == 0);
    for (const char* name : MODELS)
        CHECK(readBytes(out + "/again/" + std::string(name) + ".gltf") == readBytes(out + "/" + name + ".gltf"));
}

TEST_CASE("make-models into a path that cannot be a folder exits 2 and --help exits 0", "[cli][models]") {
    auto help = runOceanbox("make-models --help");
    CHECK(help.exitCode == 0);
    CHECK(help.output.find("--out") != std::string::npos);
    const std::string file = writeFile(tempPath("plain_file"), "x");
    auto r = runOceanbox("make-models --out " + file + "/sub");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--out") != std::string::npos);
}

TEST_CASE("a scene whose object model file is missing exits 2 naming the scene, objects[0].model and the file", "[cli][models]") {
    const std::string scene = writeFile(tempPath("missing_model.toml"),
                                        "[[objects]]\ntype = \"sphere\"\nmodel = \"missing.gltf\"\n");
    auto r = runOceanbox("run " + scene + " --headless --frames 1 --size 32x32");
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(scene + ":3:9: objects[0].model: ") != std::string::npos);
    CHECK(r.output.find("missing.gltf") != std::string::npos);
}

TEST_CASE("a scene whose object model file is corrupt exits 2 naming objects[1].model and the glTF problem", "[cli][models]") {
    const std::string scene = tempPath("corrupt_model.toml");
    const std::string folder = std::filesystem::path(scene).parent_path().string();
    writeFile(folder + "/corrupt.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [");
    writeFile(scene, "[[objects]]\n\n[[objects]]\nmodel = \"corrupt.gltf\"\n");
    auto r = runOceanbox("run " + scene + " --headless --frames 1 --size 32x32");
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(scene + ":4:9: objects[1].model: " + folder + "/corrupt.gltf: ") != std::string::npos);
    CHECK(r.output.find("glTF") != std::string::npos);
}

TEST_CASE("a scene naming a committed model by its path in the source tree runs", "[cli][models]") {
    const std::string scene = writeFile(tempPath("ship_scene.toml"),
                                        "[[objects]]\ntype = \"box\"\nsize = [3, 1.5, 10]\nmodel = \"assets/models/ship.gltf\"\n");
    auto r = runOceanbox("run " + scene + " --headless --frames 2 --size 32x32");
    INFO(r.output);
    CHECK(r.exitCode == 0);
}
