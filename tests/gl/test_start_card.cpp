// The start card's way under water: every camera reaches fly mode with C and a flying camera
// dives with Q, so every scene's card says how, and doing what it says takes the camera under
// the surface and E brings it back (fixed, follow and fly cameras; the rest of the cycle is the
// same path). The card's keys are the view's text (ui/hud.h), read here without a context.
#include "ui/hud.h"
#include "world/camera.h"
#include "world/controls.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <string>
#include <vector>

using namespace ob;
using namespace ob::game;
using T = platform::InputEvent::Type;
using platform::Key;

namespace {

const std::string CALM = "[ocean]\nresolution = 32\namplitude = 0.0\n[gerstner]\ncount = 0\n[ripples]\nenabled = false\n";

platform::InputEvent key(T type, double time, Key k) {
    platform::InputEvent e;
    e.type = type;
    e.time = time;
    e.key = k;
    return e;
}

// Runs one step a frame to `until` s.
void runTo(Sandbox& sandbox, double until) {
    for (double t = sandbox.schedule().simTime() + 1.0 / 60.0; t <= until + 1e-9; t += 1.0 / 60.0) sandbox.frame(t);
}

CameraRig& rig(Sandbox& sandbox) { return sandbox.world().pool<CameraRig>().components()[0]; }

} // namespace

TEST_CASE("every camera's card says the way under water, and C, Q and E do what it says", "[ui][card][camera]") {
    const std::string ship = "[[objects]]\ntype = \"ship\"\nname = \"boat\"\nplayer = true\nposition = [0, 0.1, 0]\n";
    const std::vector<std::pair<std::string, std::string>> cameras = {
        {"fixed", "[camera]\nmode = \"fixed\"\nposition = [0, 30, -20]\ntarget = [0, 0, 0]\n"},
        {"follow", "[camera]\nmode = \"follow\"\n" + ship},
        {"fly", "[camera]\nmode = \"fly\"\nposition = [0, 8, -20]\n"},
    };
    for (const auto& [mode, camera] : cameras) {
        SECTION(mode) {
            Sandbox sandbox(parseScene(CALM + camera, mode + ".toml"));
            const std::string keys = startCardKeys(sandbox.world());
            INFO(mode << " camera's card keys: " << keys);
            CHECK(keys.find("hold Q: under water, E: up") != std::string::npos);
            CHECK((keys.find("C until fly") != std::string::npos) == (mode != "fly"));
            // C until the camera flies (a press at a time: at most one round of the cycle), then Q held.
            for (int press = 0; press < 4 && !cameraFlies(sandbox.world()); ++press) {
                const double now = sandbox.schedule().simTime();
                sandbox.setScriptedInput({key(T::KeyDown, now + 0.02, Key::C), key(T::KeyUp, now + 0.05, Key::C)});
                runTo(sandbox, now + 0.1);
            }
            REQUIRE(cameraFlies(sandbox.world()));
            CHECK_FALSE(rig(sandbox).underwater);
            // Q held until it dives (at most 6 s: from 30 m up at the fly speed, then the hold at the
            // surface), E held until it is back above (at most 6 s).
            const auto holdUntil = [&](Key k, bool underwater) {
                const double from = sandbox.schedule().simTime();
                sandbox.setScriptedInput({key(T::KeyDown, from + 0.02, k)});
                while (rig(sandbox).underwater != underwater && sandbox.schedule().simTime() < from + 6.0)
                    runTo(sandbox, sandbox.schedule().simTime() + 1.0 / 60.0);
                const double now = sandbox.schedule().simTime();
                sandbox.setScriptedInput({key(T::KeyUp, now + 0.01, k)});
                runTo(sandbox, now + 0.1);
            };
            const auto eyeY = [&] { return sandbox.world().get<ecs::Transform>(sandbox.world().pool<CameraRig>().entities()[0]).position.y; };
            holdUntil(Key::Q, true);
            CHECK(rig(sandbox).underwater);
            CHECK(eyeY() < 0.0f);
            holdUntil(Key::E, false);
            CHECK_FALSE(rig(sandbox).underwater);
            CHECK(eyeY() > 0.0f);
        }
    }
}
