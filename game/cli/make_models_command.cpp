// oceanbox make-models: the project's own glTF models (game/tools/model_shapes.cpp).
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "tools/cmd_make_models.h"

#include <CLI/CLI.hpp>
#include <memory>

namespace ob::game {

void addMakeModelsCommand(CLI::App& app, CommandAction& action) {
    auto out = std::make_shared<std::string>("assets/models");
    CLI::App* cmd = app.add_subcommand("make-models", "write the project's own glTF models (ship, fish, cannonball, cannon and the props: crate, barrel, raft, target, ball, buoy, pillar, wall)");
    cmd->add_option("--out", *out, "output folder (default: assets/models; made if its parent exists)")->check(NON_EMPTY_PATH);
    cmd->callback([&action, out] { action = [out] { return makeModels(*out); }; });
}

} // namespace ob::game
