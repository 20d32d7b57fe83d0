// Fuzz target: the --set key path and value (engine/core/toml_reader.cpp: the hand-written
// key-path scanner, the element lookup, the value's TOML parse and the merge), applied to a
// small scene and read by every Def. Each input is one assignment "key.path=value"; it must
// load or throw ob::InputError with a message of bounded length; a crash, another exception,
// a sanitizer report or a hang is a finding.
#include "core/error.h"
#include "world/scene.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// Objects and events to index into, sections to descend.
const char* const SCENE = R"([ocean]
resolution = 16
[ripples]
resolution = 16
[[objects]]
type = "sphere"
name = "a"
[[objects]]
type = "ship"
waypoints = [[0.0, 1.0], [2.0, 3.0]]
[[events]]
at = 1.0
action = "spawn"
object = { type = "box", size = [1.0, 2.0, 3.0] }
)";

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 131072) return -1;
    const std::string assignment(reinterpret_cast<const char*>(data), size);
    try {
        ob::game::parseScene(SCENE, "fuzz.toml", {assignment});
    } catch (const ob::InputError& e) {
        const std::string what = e.what();
        // A message names the assignment by its start only: it stays short for any input.
        if (what.empty() || what.size() > 4096 + 2 * size) {
            std::fprintf(stderr, "fuzz_keypath: InputError of %zu characters\n", what.size());
            std::abort();
        }
    }
    return 0;
}
