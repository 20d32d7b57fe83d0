// oceanbox play [SCENE]: a scene in a window, in real time (headless with a screenshot where
// there is no display).
#include "cli/commands.h"
#include "cli/scene_flags.h"
#include "core/log.h"
#include "platform/platform.h"

#include <memory>

namespace ob::game {

namespace {

// `play --help`: every key and mouse action (the overlay shows those of the scene).
const char* const PLAY_KEYS = R"(Keys and mouse (H shows and hides the overlay, which lists those this scene uses):
  right drag    orbit the camera about what it looks at (fly mode: look around)
  wheel         zoom: follow distance, orbit radius (fly mode: move forward)
  C             camera mode: follow (a ship) -> orbit -> fly
  W/S  A/D      ship: throttle, rudder (fly mode: move the camera)
  Q/E  Shift    fly mode: down, up; Shift x4 speed; hold Q at the surface to dive
  arrows        cannon: aim (yaw, elevation)
  Space         cannon: fire one ball per press
  1-5           the left button's tool: 1 grab (drag a body, release throws; wheel: distance),
                2 stir (hold on the water; wheel: radius, Shift+wheel: depth), 3 drop (click on
                the water; 3 again: next object), 4 erase (click a body), 5 cannon (click on the
                water: aim there and fire)
  F             a school of fish where the camera looks
  P  N          pause and resume; one step while paused
  R             restart the scene (the goal's result panel: R again, Esc quits)
  F12           screenshot (oceanbox_shot_NNN.png)
  H             show or hide the overlay
  Esc           quit)";

} // namespace

void addPlayCommand(CLI::App& app, CommandAction& action) {
    auto play = std::make_shared<SceneFlags>();
    play->scene = defaultScenePath();
    CLI::App* cmd = app.add_subcommand("play", "open a scene in a window (headless with a screenshot where there is no display)");
    cmd->add_option("scene", play->scene, "scene file (default: config/scenes/default.toml)");
    play->addTo(cmd, 0);
    cmd->add_option("--record", play->record, "write every input the simulation consumed to this TOML file (run --input replays it)")
        ->check(NON_EMPTY_PATH);
    cmd->footer(PLAY_KEYS);
    cmd->callback([&action, play] {
        action = [play] {
            SceneDef scene = play->load();
            if (scene.info.purpose == ScenePurpose::Benchmark)
                logInfo("%s is a benchmark scene: %s", printable(play->scene).c_str(),
                        scene.info.note.empty() ? "it measures, it is not meant to look like the sea" : scene.info.note.c_str());
            else if (!scene.info.note.empty())
                logInfo("%s", scene.info.note.c_str());
            RunOptions o = play->options();
            o.record = play->record;
            o.realTime = true;
            o.overlay = true;  // what the player sees, in its pictures too (headless as well)
            o.dynamicResolution = true;
            o.autoExposure = true;
            if (o.frames == 0) o.frames = -1;
            if (!platform::displayAvailable() || play->headless) {
                // No window to look at: run a fixed number of frames and keep a picture.
                o.window = false;
                o.realTime = false;
                o.dynamicResolution = play->options().dynamicResolution;  // reproducible unless asked
                o.autoExposure = false;
                if (o.frames < 0) o.frames = 600;
                if (o.screenshot.empty()) o.screenshot = "oceanbox.png";
            }
            if (!play->headless && !platform::displayAvailable())
                logInfo("no display found: running headless for %ld frames, screenshot %s", o.frames, o.screenshot.c_str());
            return runScene(scene, play->scene, o);
        };
    });
}

} // namespace ob::game
