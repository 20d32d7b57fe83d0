// oceanbox run SCENE: a scene for a number of frames, exactly one simulation step per frame.
#include "cli/commands.h"
#include "cli/scene_flags.h"

#include <memory>

namespace ob::game {

void addRunCommand(CLI::App& app, CommandAction& action) {
    auto run = std::make_shared<SceneFlags>();
    CLI::App* cmd = app.add_subcommand("run", "run a scene for a number of frames at exactly one simulation step per frame");
    cmd->add_option("scene", run->scene, "scene file")->required();
    run->addTo(cmd, 600);
    cmd->callback([&action, run, cmd] {
        action = [run, framesGiven = cmd->count("--frames") > 0] {
            SceneDef scene = run->load();
            RunOptions o = run->options();
            if (!framesGiven && scene.sim.end_time > 0.0f) {
                o.frames = -1;  // the scene says how long it lasts
                o.endTime = scene.sim.end_time;
            }
            o.fallbackNote = "no display found: running headless";
            return runScene(scene, run->scene, o);
        };
    });
}

} // namespace ob::game
