// oceanbox run SCENE: a scene for a number of frames, exactly one simulation step per frame.
#include "cli/commands.h"
#include "cli/scene_flags.h"

#include "world/input_script.h"

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
            // A recording (play --record) says how many steps it ran and in what framebuffer.
            if (!run->input.empty()) {
                const InputScriptDef recording = loadInputScript(run->input);
                if (!framesGiven && recording.steps > 0) {
                    o.steps = recording.steps;
                    o.frames = long((recording.steps + uint64_t(o.stepsPerFrame) - 1) / uint64_t(o.stepsPerFrame));
                    o.endTime = 0.0;
                }
                if (run->size.empty() && recording.size.x >= 16.0f && recording.size.y >= 16.0f) o.size = glm::ivec2(recording.size);
            }
            o.fallbackNote = "no display found: running headless";
            return runScene(scene, run->scene, o);
        };
    });
}

} // namespace ob::game
