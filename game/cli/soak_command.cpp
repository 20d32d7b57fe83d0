// oceanbox soak SCENE: a long headless simulation with its invariants checked (docs/reliability.md).
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "cli/scene_flags.h"
#include "tools/cmd_soak.h"

#include <memory>

namespace ob::game {

void addSoakCommand(CLI::App& app, CommandAction& action) {
    struct SoakArgs {
        SceneFlags scene;
        SoakOptions options;
    };
    auto a = std::make_shared<SoakArgs>();
    CLI::App* cmd = app.add_subcommand("soak", "simulate a scene headless (no rendering) for a long time, checking "
                                               "finite fields, bounded heights, floating bodies and flat memory");
    cmd->add_option("scene", a->scene.scene, "scene file")->required();
    cmd->add_option("--seconds", a->options.seconds, "simulated seconds (default 3600: one hour)")
        ->check(FINITE_NUMBER)
        ->check(CLI::Range(1e-3, 1e7));
    cmd->add_option("--check-every", a->options.checkEvery, "check the invariants every N steps (default 1)")
        ->check(CLI::Range(1, 1000000));
    cmd->add_option("--stats", a->options.stats, "write a JSON summary (steps/s, maxima, RSS, state hash)")->check(NON_EMPTY_PATH);
    cmd->add_option("--set", a->scene.sets, "override a scene key: key.path=value (repeatable)");
    cmd->add_option("--seed", a->scene.seed, "scene seed (same as --set sim.seed=N)")->check(SEED);
    cmd->callback([&action, a] {
        action = [a] {
            const SceneDef scene = a->scene.load();
            checkOutputsApart(sceneInputs(scene, a->scene.scene), {{"--stats", a->options.stats}});
            return soakCommand(scene, a->scene.scene, a->options);
        };
    });
}

} // namespace ob::game
