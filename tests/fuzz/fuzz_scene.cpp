// Fuzz target: the scene loader (TOML text, every Def's validation, --set overrides). An
// input is a scene file; its lines that start with "#set " are also applied as --set
// overrides (TOML comments, so a seed stays a valid scene). Every input must load or throw
// ob::InputError with a message; anything else (another exception, a crash, a sanitizer
// report, a hang) is a finding.
#include "core/error.h"
#include "world/scene.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

// The "#set " lines of the text, in order.
std::vector<std::string> overrides(const std::string& text) {
    std::vector<std::string> out;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        if (text.compare(pos, 5, "#set ") == 0) out.push_back(text.substr(pos + 5, end - pos - 5));
        pos = end + 1;
    }
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 65536) return -1;  // scenes are a few KB; longer inputs only slow the search
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        ob::game::SceneDef scene = ob::game::parseScene(text, "fuzz.toml", overrides(text));
        // A scene that loads is within every range its describe() states.
        if (!(scene.sim.step_hz >= 1.0f && scene.sim.step_hz <= 1000.0f) || scene.ocean.resolution < 16 ||
            (scene.ocean.resolution & (scene.ocean.resolution - 1)) != 0 || scene.ripples.resolution < 16) {
            std::fprintf(stderr, "fuzz_scene: a scene out of range loaded\n");
            std::abort();
        }
    } catch (const ob::InputError& e) {
        if (std::string(e.what()).empty()) {
            std::fprintf(stderr, "fuzz_scene: InputError without a message\n");
            std::abort();
        }
    }
    return 0;
}
