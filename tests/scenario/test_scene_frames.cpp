// Every scene in config/scenes renders 30 headless frames with no GL error (a GL error
// during a run makes `run` exit 1).
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ob;

TEST_CASE("every scene in config/scenes renders 30 frames with no GL error", "[scenes][render]") {
    std::vector<std::string> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes"))
        if (entry.path().extension() == ".toml") scenes.push_back(entry.path().string());
    REQUIRE(scenes.size() >= 2);
    for (const std::string& scene : scenes) {
        DYNAMIC_SECTION(scene) {
            test::ProcessResult r = test::runOceanbox("run " + scene + " --headless --frames 30 --size 160x90");
            INFO(r.output);
            CHECK(r.exitCode == 0);
        }
    }
}
