// Every body of every shipped scene is drawn with a model, not a built-in placeholder: the
// scene's objects, the cannon's pillar and balls, fish schools and whatever the drop tool drops.
#include "assets/model.h"
#include "behaviours/cannon.h"
#include "behaviours/fish.h"
#include "behaviours/spawning.h"
#include "sim/objects.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/tools.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ob;

namespace {

// The models of what the world draws: every Renderable's and every fish school's.
std::vector<std::string> drawnModels(ecs::World& world) {
    std::vector<std::string> models;
    for (const game::Renderable& r : world.pool<game::Renderable>().components()) models.push_back(r.model);
    for (const game::FishSchool& s : world.pool<game::FishSchool>().components()) models.push_back(s.model);
    return models;
}

} // namespace

TEST_CASE("every body of every shipped scene is drawn with a model: objects, pillars, balls, schools and drops", "[models][scenes]") {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes")) {
        if (entry.path().extension() != ".toml") continue;
        ++scenes;
        INFO(entry.path().filename().string());
        game::Sandbox sandbox(game::loadScene(entry.path().string()));
        ecs::World& world = sandbox.world();
        // A shot from every cannon, and one of each thing the drop tool makes.
        for (game::Cannon& c : world.pool<game::Cannon>().components()) c.fireRequested = true;
        if (auto* tools = world.resource<game::PlayerTools>())
            for (game::DropKind kind : {game::DropKind::Ball, game::DropKind::Crate, game::DropKind::Barrel, game::DropKind::Buoy,
                                        game::DropKind::Raft, game::DropKind::FishSchool, game::DropKind::Ship}) {
                tools->def.drop = kind;
                game::spawnObject(world, game::dropDef(*tools, glm::vec3(40.0f, 0.0f, 40.0f), 0.0f), 1);
            }
        for (int k = 0; k < 10; ++k) sandbox.step();
        if (!world.pool<game::Cannon>().components().empty()) CHECK(!world.pool<game::Cannonball>().components().empty());
        const std::vector<std::string> models = drawnModels(world);
        CHECK(models.size() >= 7);  // the drops at least
        for (const std::string& model : models) {
            INFO("a body drawn with '" << model << "'");
            CHECK(!model.empty());
            CHECK(std::filesystem::is_regular_file(model));
        }
    }
    CHECK(scenes >= 13);
}
