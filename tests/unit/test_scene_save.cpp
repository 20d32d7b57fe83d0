// Saving a scene (the UI's "save scene as"): the TOML written through describe() reads back
// as the same scene, and holds only what differs from the defaults.
#include "core/toml_writer.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ob;

TEST_CASE("every shipped scene written back as TOML reads back as the same scene", "[config]") {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes")) {
        INFO(entry.path());
        game::SceneDef scene = game::loadScene(entry.path().string());
        const std::string text = writeToml(scene);
        game::SceneDef again = game::parseScene(text, "saved.toml");
        CHECK(writeToml(again) == text);  // a fixed point: nothing lost, nothing added
        REQUIRE(again.objects.size() == scene.objects.size());
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            CHECK(again.objects[i].type == scene.objects[i].type);
            CHECK(again.objects[i].position == scene.objects[i].position);
            CHECK(again.objects[i].ship.waypoints == scene.objects[i].ship.waypoints);
        }
        CHECK(again.events.size() == scene.events.size());
        CHECK(again.ripples.damping == scene.ripples.damping);
        CHECK(again.gerstner.waves.size() == scene.gerstner.waves.size());
    }
}

TEST_CASE("a saved scene holds only the keys that differ from the defaults, nested sections and lists included", "[config]") {
    game::SceneDef scene = game::parseScene("", "empty.toml");
    CHECK(writeToml(scene).empty());
    scene.ripples.reference.speed = 2.5f;
    scene.camera.fov_deg = 0.1f + 44.9f;  // not exactly representable: written in its shortest round-trip form
    game::EventDef spawn;
    spawn.action = game::EventAction::Spawn;
    spawn.object.type = game::ObjectType::Ship;
    spawn.object.ship.waypoints = {{1.0f, 2.0f}, {-3.5f, 4.0f}};
    scene.events.push_back(spawn);
    const std::string text = writeToml(scene);
    CHECK(text.find("[ripples.reference]\nspeed = 2.5\n") != std::string::npos);
    CHECK(text.find("[[events]]\naction = \"spawn\"\n\n[events.object]\ntype = \"ship\"\nwaypoints = [[1.0, 2.0], [-3.5, 4.0]]\n") !=
          std::string::npos);
    game::SceneDef again = game::parseScene(text, "saved.toml");
    CHECK(again.camera.fov_deg == scene.camera.fov_deg);
    CHECK(again.ripples.reference.speed == 2.5f);
    REQUIRE(again.events.size() == 1);
    CHECK(again.events[0].object.ship.waypoints == spawn.object.ship.waypoints);
    CHECK(again.render.exposure == scene.render.exposure);  // untouched keys keep their defaults
}
