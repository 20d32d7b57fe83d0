// Failure paths end to end: each gives one clear message that says what to do, exit code 1
// for a runtime failure and 2 for bad input, and leaves no output written half (every
// writer goes through a temporary file and a rename).
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using ob::test::runOceanbox;
using ob::test::runShell;
using ob::test::tempPath;
using ob::test::writeFile;

namespace fs = std::filesystem;

namespace {

// A copy of shaders/ that a test may break.
std::string copyShaders() {
    const std::string dir = tempPath("shaders");
    fs::copy(fs::path(OCEANBOX_SOURCE_DIR) / "shaders", dir, fs::copy_options::recursive);
    return dir;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// No temporary of the output is left in its folder (".NAME.oceanbox-PID-XXXXXX").
bool noTemporary(const std::string& path) {
    const fs::path p(path);
    if (!fs::is_directory(p.parent_path())) return true;
    for (const auto& entry : fs::directory_iterator(p.parent_path()))
        if (entry.path().filename().string().rfind("." + p.filename().string() + ".oceanbox-", 0) == 0) return false;
    return true;
}

// Neither the file nor a temporary of it exists.
bool nothingWritten(const std::string& path) { return !fs::exists(path) && noTemporary(path); }

// The output line that holds `text` (empty when none does).
std::string lineWith(const std::string& output, const std::string& text) {
    const size_t at = output.find(text);
    if (at == std::string::npos) return "";
    const size_t begin = output.rfind('\n', at) == std::string::npos ? 0 : output.rfind('\n', at) + 1;
    return output.substr(begin, output.find('\n', at) - begin);
}

const std::string RUN = " run config/scenes/default.toml --headless --frames 2 --size 32x32";

} // namespace

TEST_CASE("a missing shader file exits 1 naming the file and OCEANBOX_SHADER_DIR, and writes nothing", "[failures]") {
    const std::string dir = copyShaders();
    fs::remove(dir + "/water_surface.frag");
    const std::string png = tempPath("missing_shader.png"), json = tempPath("missing_shader.json");
    auto r = runShell("OCEANBOX_SHADER_DIR='" + dir + "' \"$OCEANBOX\"" + RUN + " --screenshot " + png + " --stats " + json);
    INFO(r.output);
    CHECK(r.exitCode == 1);
    const std::string line = lineWith(r.output, "shader file not found");
    CHECK(line.find(dir + "/water_surface.frag") != std::string::npos);
    CHECK(line.find("set OCEANBOX_SHADER_DIR to a complete copy of the shaders/ folder") != std::string::npos);
    CHECK(nothingWritten(png));
    CHECK(nothingWritten(json));
}

TEST_CASE("a shader that fails to compile exits 1 naming the included file and line, and keeps old outputs whole", "[failures]") {
    const std::string dir = copyShaders();
    // A line that is no GLSL, as line 3 of a file the water and sky programs include.
    std::string fresnel = readText(dir + "/common_fresnel.glsl");
    const size_t third = fresnel.find('\n', fresnel.find('\n') + 1) + 1;
    writeFile(dir + "/common_fresnel.glsl", fresnel.substr(0, third) + "this line is not GLSL;\n" + fresnel.substr(third));
    // Outputs of an earlier run stay as they were.
    const std::string png = writeFile(tempPath("old.png"), "old picture"), json = writeFile(tempPath("old.json"), "old stats");
    auto r = runShell("OCEANBOX_SHADER_DIR='" + dir + "' \"$OCEANBOX\"" + RUN + " --screenshot " + png + " --stats " + json);
    INFO(r.output);
    CHECK(r.exitCode == 1);
    // The first program built that includes it fails: the line names that program's source.
    const std::string line = lineWith(r.output, "failed to compile");
    CHECK(line.find("shader " + dir + "/") != std::string::npos);
    CHECK(line.find(".frag failed to compile (fix the lines below") != std::string::npos);
    CHECK(r.output.find(dir + "/common_fresnel.glsl:3:") != std::string::npos);
    CHECK(readText(png) == "old picture");
    CHECK(readText(json) == "old stats");
    CHECK(noTemporary(png));
    CHECK(noTemporary(json));
}

TEST_CASE("no OpenGL 4.5 context exits 1 in one line that says why and what to do", "[failures]") {
    const std::string json = tempPath("no_gl.json");
    auto r = runShell("MESA_GL_VERSION_OVERRIDE=3.3 \"$OCEANBOX\"" + RUN + " --stats " + json);
    INFO(r.output);
    CHECK(r.exitCode == 1);
    CHECK(lineWith(r.output, "oceanbox: failed:").find("could not create an OSMesa OpenGL 4.5 core context: "
                                                      "MESA_GL_VERSION_OVERRIDE=3.3 caps Mesa below it (unset it") !=
          std::string::npos);
    CHECK(nothingWritten(json));
}

TEST_CASE("play and run without a display fall back to headless and say so in one line", "[failures]") {
    const std::string png = tempPath("no_display.png");
    auto r = runShell("env -u DISPLAY -u WAYLAND_DISPLAY \"$OCEANBOX\" play --frames 2 --size 32x32 --screenshot " + png);
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(lineWith(r.output, "no display found").find("running headless for 2 frames, screenshot " + png) != std::string::npos);
    CHECK(fs::exists(png));
    r = runShell("env -u DISPLAY -u WAYLAND_DISPLAY \"$OCEANBOX\" run config/scenes/default.toml --frames 2 --size 32x32");
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(r.output.find("no display found: running headless") != std::string::npos);
}

TEST_CASE("every output path that cannot be written exits 2 in one line and leaves no file or temporary behind", "[failures]") {
    // Two ways to fail, both refused before the run: a folder that does not exist, and a path
    // that is a folder. (The temporary's name is unique, so nothing at a fixed name can block
    // it any more: tests/scenario/test_hostile_cli.cpp.)
    const std::string folder = tempPath("a_folder");
    fs::create_directories(folder);
    for (const std::string& base : {std::string("/no/such/dir/out"), folder}) {
        const std::vector<std::pair<std::string, std::string>> commands = {
            {RUN + " --screenshot ", ".png"},
            {RUN + " --stats ", ".json"},
            {" dump ocean config/scenes/default.toml --set ocean.resolution=16 --out ", ".npy"},
            {" dump ripples config/scenes/default.toml --frames 1 --set ripples.resolution=16 --out ", ".npy"},
            {" soak config/scenes/default.toml --seconds 0.1 --stats ", ".json"},
        };
        for (const auto& [args, ext] : commands) {
            const std::string out = base == folder ? folder : base + ext;
            auto r = runShell("\"$OCEANBOX\"" + args + out);
            INFO(args << out << "\n" << r.output);
            CHECK(r.exitCode == 2);
            const std::string line = lineWith(r.output, "cannot write");
            CHECK(line.find("'" + out + "': ") != std::string::npos);
            CHECK((line.find("(choose another path)") != std::string::npos || line.find("(give a file name)") != std::string::npos ||
                   line.find("(create it or choose another path)") != std::string::npos));
            if (base == folder) continue;
            CHECK(nothingWritten(out));
        }
    }
    auto r = runOceanbox("make-models --out /proc/self/models");
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("--out '/proc/self/models'") != std::string::npos);
}

TEST_CASE("a bad live set in a scene's timeline exits 2 before the run with the file, line and key", "[failures][sea_live]") {
    const std::string head = "[[events]]\nat = 1.0\naction = \"set\"\n";
    const std::string unknown = writeFile(tempPath("set_unknown.toml"), head + "key = \"ocean.gale\"\nvalue = 3.0\n");
    const std::string fixed = writeFile(tempPath("set_fixed.toml"), head + "key = \"ocean.resolution\"\nvalue = 128\n");
    const std::string range = writeFile(tempPath("set_range.toml"), head + "key = \"ocean.wind_speed\"\nvalue = 80.0\n");
    for (const auto& [file, expected] : {std::pair{unknown, unknown + ":4:7: events[0].key: 'ocean.gale'"},
                                         std::pair{fixed, fixed + ":4:7: events[0].key: 'ocean.resolution' is read once"},
                                         std::pair{range, range + ":5:9: events[0].value: value out of the key's range"}}) {
        auto r = runOceanbox("run " + file + " --headless --frames 2 --size 32x32");
        INFO(r.output);
        CHECK(r.exitCode == 2);
        CHECK(r.output.find(expected) != std::string::npos);
    }
}
