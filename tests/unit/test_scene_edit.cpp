// The UI's scene editor checks an edited scene as the loader checks a file.
#include "world/scene.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

using namespace ob;

TEST_CASE("an edited scene is accepted when a file with the same keys would be, and rejected with the loader's message", "[scene]") {
    game::SceneDef scene = game::loadScene(game::defaultScenePath());
    CHECK(game::checkEditedScene(scene).empty());
    scene.ocean.wind_speed = 22.0f;
    scene.ripples.damping = 0.9f;
    CHECK(game::checkEditedScene(scene).empty());
    scene.ocean.resolution = 300;  // not a power of two
    std::string problem = game::checkEditedScene(scene);
    CHECK(problem.find("ocean.resolution") != std::string::npos);
    scene.ocean.resolution = 128;
    scene.ripples.cell_size = -1.0f;  // out of range
    CHECK(game::checkEditedScene(scene).find("ripples.cell_size") != std::string::npos);
}
