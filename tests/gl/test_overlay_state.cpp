// The overlay's state belongs to its world: "save scene as" writes the scene of the world that
// runs now, never an earlier world's edited copy (a restart or a scene switch makes a new world
// whose editor starts from its own scene).
#include "core/toml_writer.h"
#include "ui/ui_state.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <memory>
#include <sstream>

using namespace ob;
using namespace ob::game;

namespace {
const std::string CALM = "[ocean]\nresolution = 32\namplitude = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n";
}

TEST_CASE("edit, restart, switch, save: the file is the scene that runs now", "[ui][save]") {
    const SceneDef first = parseScene(CALM + "[sim]\nseed = 11\n", "first.toml");
    const SceneDef second = parseScene(CALM + "[sim]\nseed = 22\n", "second.toml");
    auto sandbox = std::make_unique<Sandbox>(first);
    uiState(sandbox->world()).edited.sim.seed = 99;  // edited in the panel, not applied
    CHECK(sceneToSave(sandbox->world()).sim.seed == 99);
    // R: a new world from the scene as it started; the edit is gone with the old world.
    sandbox = std::make_unique<Sandbox>(first);
    CHECK(sceneToSave(sandbox->world()).sim.seed == 11);
    uiState(sandbox->world()).edited.sim.seed = 98;
    // The picker: another scene, maybe at the same address as the last world's.
    sandbox.reset();
    sandbox = std::make_unique<Sandbox>(second);
    const SceneDef saved = sceneToSave(sandbox->world());
    CHECK(saved.sim.seed == 22);
    SceneDef running = sandbox->scene();
    SceneDef written = saved;
    CHECK(writeToml(written) == writeToml(running));
}
