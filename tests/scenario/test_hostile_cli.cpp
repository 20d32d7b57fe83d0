// Hostile input end to end: each reproducer of the hostile-input campaign (docs/reliability.md)
// given to the executable exits 2 (or succeeds where that is the documented intent) with a
// message naming the problem, in under 5 s (a hang is killed at 20 s and fails), and leaves
// the victim file or device as it was.
#include "core/file_write.h"
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/sysmacros.h>

using ob::test::ProcessResult;
using ob::test::tempPath;
using ob::test::writeFile;
namespace fs = std::filesystem;

namespace {

// The executable with `args`, killed after 20 s: a hang ends as exit 124 and fails the test.
ProcessResult oceanbox(const std::string& args) { return ob::test::runShell("timeout -k 2 20 \"$OCEANBOX\" " + args); }

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A scene small enough that loading it takes a moment.
std::string tinyScene(const std::string& name, const std::string& extra = "") {
    return writeFile(tempPath(name), "[ocean]\nresolution = 16\n[gerstner]\ncount = 0\n[ripples]\nresolution = 32\n" + extra);
}

// A character device like /dev/null in a temporary folder ("" where mknod is not permitted).
std::string makeNullDevice(const std::string& name) {
    const std::string path = tempPath(name);
    return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0 ? path : "";
}

bool isCharDevice(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

// Exit 2 with `text` in the output, quickly.
void expectRefused(const ProcessResult& r, const std::string& text) {
    INFO(r.output);
    CHECK(r.exitCode == 2);
    CHECK(r.output.find(text) != std::string::npos);
    CHECK(r.wallSeconds < 5.0);
}

const std::string RUN_FLAGS = " --headless --frames 2 --size 32x32";

} // namespace

TEST_CASE("an output path that is a device is refused before the run and the device stays a device", "[hostile][cli]") {
    const std::string device = makeNullDevice("null");
    if (device.empty()) {
        SUCCEED("mknod is not permitted here: skipped");
        return;
    }
    const std::string scene = tinyScene("device_scene.toml");
    const std::string in = tempPath("in.npy");
    const std::vector<float> h(16, 0.5f);
    ob::writeNpy(in, {4, 4}, h.data());
    for (const std::string& args :
         {"run " + scene + RUN_FLAGS + " --stats " + device, "run " + scene + RUN_FLAGS + " --screenshot " + device,
          "dump ocean " + scene + " --out " + device, "soak " + scene + " --seconds 0.1 --stats " + device,
          "ripple --in " + in + " --steps 1 --damping 0.9 --out " + device}) {
        const ProcessResult r = oceanbox(args);
        expectRefused(r, "'" + device + "': it is a character device, not a regular file");
        CHECK(isCharDevice(device));
    }
}

TEST_CASE("an output of /dev/stdout (a symbolic link) is refused: no output is written through a link", "[hostile][cli]") {
    const ProcessResult r = oceanbox("run " + tinyScene("stdout.toml") + RUN_FLAGS + " --stats /dev/stdout");
    expectRefused(r, "cannot write stats '/dev/stdout': it is a symbolic link to '/proc/self/fd/1'");
    CHECK(fs::is_symlink("/dev/stdout"));
}

TEST_CASE("a planted link at the old temporary name is not followed and the output becomes a regular file", "[hostile][cli]") {
    const std::string folder = tempPath("shared");
    fs::create_directories(folder);
    const std::string victim = writeFile(tempPath("victim.txt"), "precious");
    fs::create_symlink(victim, folder + "/s.json.tmp");
    const ProcessResult r = oceanbox("run " + tinyScene("planted.toml") + RUN_FLAGS + " --stats " + folder + "/s.json");
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(readText(victim) == "precious");
    CHECK(fs::is_regular_file(fs::symlink_status(folder + "/s.json")));
    CHECK(readText(folder + "/s.json").find("\"state_hash\"") != std::string::npos);
}

TEST_CASE("a --set key of 50,000 characters or 'a.' 20,000 times exits 2 in one line, in run and soak", "[hostile][cli]") {
    const std::string scene = tinyScene("long_key.toml");
    std::string dotted;
    for (int i = 0; i < 20000; ++i) dotted += "a.";
    for (const std::string& key : {std::string(50000, 'k'), dotted + "b"}) {
        for (const std::string& command : {"run " + scene + RUN_FLAGS, "soak " + scene + " --seconds 0.1"}) {
            const ProcessResult r = oceanbox(command + " --set " + key + "=1");
            expectRefused(r, "characters (at most 256)");
            CHECK(r.output.size() < 2000);
        }
    }
}

TEST_CASE("a named pipe as ripple --in or --prev, or as a model's buffer, exits 2 at once", "[hostile][cli]") {
    const std::string folder = tempPath("pipes");
    fs::create_directories(folder);
    const std::string fifo = folder + "/field.npy";
    REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
    const std::string in = folder + "/in.npy", out = folder + "/out.npy";
    const std::vector<float> h(16, 0.5f);
    ob::writeNpy(in, {4, 4}, h.data());
    expectRefused(oceanbox("ripple --in " + fifo + " --steps 1 --damping 0.9 --out " + out),
                  fifo + ": is not a regular file (a named pipe (FIFO))");
    expectRefused(oceanbox("ripple --in " + in + " --prev " + fifo + " --steps 1 --damping 0.9 --out " + out), "named pipe");
    CHECK(!fs::exists(out));

    REQUIRE(::mkfifo((folder + "/buffer.bin").c_str(), 0644) == 0);
    writeFile(folder + "/piped.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 48, "uri": "buffer.bin"}]})");
    const std::string scene = writeFile(folder + "/s.toml", "[[objects]]\ntype = \"sphere\"\nmodel = \"piped.gltf\"\n");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS), "external file uri 'buffer.bin': ");
}

TEST_CASE("a model whose buffer uri leaves its folder exits 2 naming the scene's line, the model and the uri", "[hostile][cli]") {
    const std::string root = tempPath("escape");
    fs::create_directories(root + "/models");
    const std::string victim = writeFile(root + "/secret.bin", std::string(48, 'x'));
    const std::string model = writeFile(root + "/models/evil.gltf",
                                        R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 48, "uri": "%2E%2E/secret.bin"}]})");
    const std::string scene = writeFile(root + "/s.toml", "[[objects]]\ntype = \"sphere\"\nmodel = \"models/evil.gltf\"\n");
    const ProcessResult r = oceanbox("run " + scene + RUN_FLAGS);
    expectRefused(r, scene + ":3:9: objects[0].model: " + model + ": external file uri '../secret.bin': leads outside the model's folder");
}

TEST_CASE("soak counts bodies spawned by events in its ripple bound: the same sphere passes as an object and as an event",
          "[hostile][cli][soak]") {
    const std::string sphere = "{ type = \"sphere\", position = [0.0, 0.6, 0.0], radius = 0.3 }";
    // A warm-up of 12 steps (a tenth of the run), the spawn well after it.
    const std::string spawned = tinyScene("spawned.toml", "[[events]]\nat = 1.0\naction = \"spawn\"\nobject = " + sphere + "\n");
    const std::string present = tinyScene("present.toml", "[[objects]]\ntype = \"sphere\"\nposition = [0.0, 0.6, 0.0]\nradius = 0.3\n");
    for (const std::string& scene : {present, spawned}) {
        const ProcessResult r = oceanbox("soak " + scene + " --seconds 2");
        INFO(r.output);
        CHECK(r.exitCode == 0);
        CHECK(r.output.find("beyond the bound") == std::string::npos);
    }
}

TEST_CASE("numbers that are no finite float exit 2: a scene's 1e308, dump --time nan, NaN or 3e38 in ripple, --cell-size 1e-30",
          "[hostile][cli]") {
    const std::string scene = tinyScene("huge.toml", "[[objects]]\ntype = \"sphere\"\nvelocity = [1e308, 1, 1]\n");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS), scene + ":9:13: objects[0].velocity: must be a finite number within");

    const std::string out = tempPath("nan_out.npy");
    expectRefused(oceanbox("dump ocean " + tinyScene("t.toml") + " --time nan --out " + out), "--time: must be a finite number");
    expectRefused(oceanbox("dump ocean " + tinyScene("t2.toml") + " --time inf --out " + out), "must be a finite number");
    CHECK(!fs::exists(out));

    const std::string nanField = tempPath("nan.npy"), hugeField = tempPath("huge.npy"), plain = tempPath("plain.npy");
    std::vector<float> h(64);
    for (size_t i = 0; i < h.size(); ++i) h[i] = float((i * 37) % 11) / 10.0f - 0.5f;  // every Fourier mode present
    ob::writeNpy(plain, {8, 8}, h.data());
    h[9] = std::numeric_limits<float>::quiet_NaN();
    ob::writeNpy(nanField, {8, 8}, h.data());
    std::fill(h.begin(), h.end(), 3e38f);
    ob::writeNpy(hugeField, {8, 8}, h.data());
    expectRefused(oceanbox("ripple --in " + nanField + " --steps 1 --damping 0.9 --out " + out),
                  nanField + ": the value at (row 1, column 1) is nan, not a finite number");
    expectRefused(oceanbox("ripple --in " + hugeField + " --steps 2 --damping 1 --out " + out), "make the step overflow");
    expectRefused(oceanbox("ripple --model ewave --in " + plain + " --steps 2 --damping 0 --cell-size 1e-30 --out " + out),
                  "make the step overflow");
    expectRefused(oceanbox("ripple --model ewave --in " + plain + " --steps 2 --damping 0 --cell-size nan --out " + out),
                  "--cell-size: must be a finite number");
    expectRefused(oceanbox("ripple --model ewave --in " + plain + " --steps 2 --damping 0 --dt 1e39 --out " + out),
                  "--dt: must be a finite number");
    CHECK(!fs::exists(out));
}

TEST_CASE("a spawn event's missing model fails at load with file and line, before any step and without output", "[hostile][cli]") {
    const std::string scene =
        tinyScene("spawn_model.toml", "[[events]]\nat = 100.0\naction = \"spawn\"\nobject = { type = \"sphere\", model = \"none.gltf\" }\n");
    const std::string stats = tempPath("spawn_stats.json");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --stats " + stats), scene + ":10:37: events[0].object.model: glTF file 'none.gltf' not found");
    CHECK(!fs::exists(stats));
    expectRefused(oceanbox("soak " + scene + " --seconds 0.1"), "events[0].object.model");
    expectRefused(oceanbox("run " + tinyScene("no_object.toml", "[[events]]\nat = 1.0\naction = \"spawn\"\n") + RUN_FLAGS),
                  "events[0].object: a spawn event needs the object it adds");
    expectRefused(oceanbox("run " + tinyScene("camera.toml", "[[events]]\nat = 1.0\naction = \"camera\"\ntarget = \"ghost\"\n") + RUN_FLAGS),
                  "events[0].target: no object is named 'ghost'");
}

TEST_CASE("empty output and input paths are errors everywhere, and make-models makes no parent folders", "[hostile][cli]") {
    const std::string scene = tinyScene("empty_paths.toml");
    for (const std::string& args : {"run " + scene + RUN_FLAGS + " --stats ''", "run " + scene + RUN_FLAGS + " --screenshot ''",
                                    "run " + scene + RUN_FLAGS + " --input ''", "dump ocean " + scene + " --out ''",
                                    "soak " + scene + " --seconds 0.1 --stats ''", std::string("make-models --out ''")})
        expectRefused(oceanbox(args), "the path is empty");
    const std::string missing = tempPath("no_parent") + "/deeper/models";
    expectRefused(oceanbox("make-models --out " + missing), "folder '" + fs::path(missing).parent_path().string() + "' does not exist");
    CHECK(!fs::exists(fs::path(missing).parent_path().parent_path()));
}

TEST_CASE("an unknown subcommand is named with the valid ones, --seed -1 and a huge integer read as written", "[hostile][cli]") {
    ProcessResult r = oceanbox("frobnicate");
    expectRefused(r, "unknown subcommand 'frobnicate' (the subcommands: play, run, bench, dump, ripple, soak, make-models)");
    r = oceanbox("run " + tinyScene("seed.toml") + RUN_FLAGS + " --seed -1");
    expectRefused(r, "--seed: must be >= 0, got -1");
    CHECK(r.output.size() < 300);
    r = oceanbox("run " + tinyScene("int.toml", "[sim]\nmax_steps_per_frame = 4294967296\n") + RUN_FLAGS);
    expectRefused(r, "sim.max_steps_per_frame: must be in [1, 64], got 4294967296");
}

TEST_CASE("a scene that is a symlink loop says so", "[hostile][cli]") {
    const std::string a = tempPath("loop_a.toml"), b = tempPath("loop_b.toml");
    fs::create_symlink(b, a);
    fs::create_symlink(a, b);
    expectRefused(oceanbox("run " + a + RUN_FLAGS), a + ": cannot open file (symlink loop)");
}

// === Second round (docs/reliability.md#hostile-input) ======================================

namespace {

// A file's bytes, to show a victim is left as it was.
std::string bytesOf(const std::string& path) { return readText(path); }

const std::string PLAY_FLAGS = " --headless --frames 1 --size 32x32";

} // namespace

TEST_CASE("an output never replaces an input: the scene, the input script, and two outputs at one path exit 2 untouched",
          "[hostile][cli][outputs]") {
    const std::string scene = tinyScene("victim_scene.toml");
    const std::string input = writeFile(tempPath("victim_input.toml"), "[[press]]\nat = 0.0\nkey = \"space\"\n");
    const std::string sceneBytes = bytesOf(scene), inputBytes = bytesOf(input);
    fs::create_hard_link(scene, scene + ".link");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --stats " + scene), "--stats '" + scene + "' is the scene file '" + scene + "'");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --screenshot " + scene + ".link"), "is the scene file");
    expectRefused(oceanbox("dump ocean " + scene + " --out " + scene), "--out '" + scene + "' is the scene file");
    expectRefused(oceanbox("soak " + scene + " --seconds 0.1 --stats " + scene), "--stats '" + scene + "' is the scene file");
    expectRefused(oceanbox("play " + scene + PLAY_FLAGS + " --input " + input + " --record " + input),
                  "--record '" + input + "' is --input '" + input + "'");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --input " + input + " --screenshot " + input), "is --input");
    const std::string field = tempPath("field.npy");
    const std::vector<float> h(16, 0.5f);
    ob::writeNpy(field, {4, 4}, h.data());
    const std::string fieldBytes = bytesOf(field);
    expectRefused(oceanbox("ripple --in " + field + " --steps 1 --damping 0.9 --out " + field), "--out '" + field + "' is --in");
    expectRefused(oceanbox("bench fields --scenes " + scene + " --out " + scene), "--out '" + scene + "' is the scene file");
    const std::string twice = tempPath("twice.out");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --stats " + twice + " --screenshot " + twice), "name one file");
    CHECK(!fs::exists(twice));
    CHECK(bytesOf(scene) == sceneBytes);
    CHECK(bytesOf(input) == inputBytes);
    CHECK(bytesOf(field) == fieldBytes);
}

TEST_CASE("a scene's screenshot event writes only in its folder: an absolute path or the scene itself exit 2 at load",
          "[hostile][cli][outputs]") {
    const std::string victim = writeFile(tempPath("victim.rc"), "precious");
    const std::string folder = tempPath("shared_scene");
    fs::create_directories(folder);
    auto scene = [&](const std::string& file) {
        return writeFile(folder + "/s.toml", "[ocean]\nresolution = 16\n[gerstner]\ncount = 0\n[ripples]\nresolution = 32\n"
                                             "[[events]]\nat = 0.0\naction = \"screenshot\"\nfile = \"" + file + "\"\n");
    };
    expectRefused(oceanbox("run " + scene(victim) + RUN_FLAGS), folder + "/s.toml:10:8: events[0].file: '" + victim + "' must be a path relative");
    expectRefused(oceanbox("run " + scene("../" + fs::path(victim).filename().string()) + RUN_FLAGS), "without '..'");
    const std::string self = scene("s.toml"), selfBytes = bytesOf(self);
    expectRefused(oceanbox("soak " + self + " --seconds 0.1"), "events[0].file: 's.toml' is the scene file itself");
    CHECK(bytesOf(self) == selfBytes);
    CHECK(bytesOf(victim) == "precious");
    // Inside its folder it writes there, wherever the program runs from.
    const ProcessResult r = oceanbox("run " + scene("shot.png") + RUN_FLAGS);
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(fs::is_regular_file(folder + "/shot.png"));
}

TEST_CASE("a scene's text reaches the terminal inert and a megabyte value is cut in its message", "[hostile][cli][text]") {
    const std::string scene = tinyScene("note.toml", "[scene]\nnote = \"\\u001b[2J\\u001b]52;c;ZXZpbA==\\u0007 boo\"\n");
    ProcessResult r = ob::test::runShell(ob::test::withoutLeakCheck() + "timeout -k 2 20 \"$OCEANBOX\" play " + scene + PLAY_FLAGS);
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(r.output.find('\x1b') == std::string::npos);
    CHECK(r.output.find("\\x1b[2J\\x1b]52;c;ZXZpbA==\\x07 boo") != std::string::npos);
    const std::string big = tinyScene("big_value.toml", "[render]\nfresnel = \"" + std::string(1 << 20, 'x') + "\"\n");
    r = oceanbox("run " + big + RUN_FLAGS);
    expectRefused(r, "(1048576 characters)");
    CHECK(r.output.size() < 1000);
}

TEST_CASE("names resolve at load: a camera following a ghost, ripples under a ship that is not there", "[hostile][cli][names]") {
    expectRefused(oceanbox("run " + tinyScene("ghost.toml", "[camera]\nfollow = \"ghost\"\n") + RUN_FLAGS),
                  "camera.follow: no object is named 'ghost'");
    expectRefused(oceanbox("soak " + tinyScene("noship.toml", "follow = \"ship\"\n") + " --seconds 0.1"),
                  ":7:10: ripples.follow: \"ship\"");
}

TEST_CASE("runaway inputs are bounded before the run: a recording's steps and size, --record '', a 23-digit seed, a long name",
          "[hostile][cli][runaway]") {
    const std::string scene = tinyScene("runaway.toml");
    const std::string steps = writeFile(tempPath("steps.toml"), "steps = 9223372036854775807\n");
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --input " + steps), "steps: at most 86400000 (a day of play");
    const std::string size = writeFile(tempPath("size.toml"), "size = [16384.0, 16384.0]\n");
    expectRefused(oceanbox("run " + scene + " --headless --frames 1 --input " + size), "size: must be 0 (auto) or in [16, 8192]");
    expectRefused(oceanbox("play " + scene + PLAY_FLAGS + " --record ''"), "--record: the path is empty");
    for (const char* command : {"run ", "soak ", "dump ocean "}) {
        const std::string tail = std::string(command) == "soak " ? " --seconds 0.1" : std::string(command) == "run " ? RUN_FLAGS : " --out x.npy";
        expectRefused(oceanbox(command + scene + tail + " --seed 11111111111111111111111"),
                      "--seed: must be an integer >= 0, got 11111111111111111111111 (beyond a 64-bit integer)");
    }
    // A 250-character name: the file itself would do, its temporary beside it would not.
    const std::string folder = tempPath("long_names");
    fs::create_directories(folder);
    const std::string stats = folder + "/" + std::string(250, 's');
    expectRefused(oceanbox("run " + scene + RUN_FLAGS + " --stats " + stats), "(give a name of at most");
    CHECK(fs::is_empty(folder));
}

TEST_CASE("a scene whose grids cannot fit exits 2 naming them in run, soak and dump alike", "[hostile][cli][memory]") {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    SUCCEED("a sanitizer's shadow memory needs more address space than the limit: skipped");
    return;
#endif
    // Every grid near its maximum (9 GiB) under a 2 GB address-space limit (ulimit -v).
    const std::string scene = tinyScene("huge_grids.toml", "levels = 4\n");
    const std::string big = "--set ocean.resolution=2048 --set ocean.cascades=4 --set ripples.resolution=4096";
    for (const std::string& command : {"run " + scene + RUN_FLAGS, "soak " + scene + " --seconds 0.1",
                                       "dump ocean " + scene + " --out " + tempPath("huge.npy")}) {
        const ProcessResult r = ob::test::runShell("ulimit -v 2000000 && timeout -k 2 20 \"$OCEANBOX\" " + command + " " + big);
        expectRefused(r, "the scene's grids need at least 9.1 GiB (ripples.resolution 4096² × ripples.levels 4: 7.0 GiB; "
                         "ocean.resolution 2048² × ocean.cascades 4: 2.0 GiB");
        CHECK(r.output.find("bad_alloc") == std::string::npos);
    }
}

TEST_CASE("dumps refuse points where a float loses the answer, and huge splash maxima warn of their cost", "[hostile][cli][dump]") {
    const std::string scene = tinyScene("far.toml", "[[gerstner.waves]]\nkx = 0.5\nkz = 0.0\namplitude = 0.2\n");
    const std::string out = tempPath("far_out.npy");
    expectRefused(oceanbox("dump gerstner " + scene + " --grid 4 --extent 1e12 --out " + out), "--extent 1e+12: the rest points reach");
    const std::string points = tempPath("far_points.npy");
    const std::vector<float> xz = {0.0f, 0.0f, 1e12f, 5.0f};
    ob::writeNpy(points, {2, 2}, xz.data());
    expectRefused(oceanbox("dump surface " + scene + " --points " + points + " --out " + out), "point 1 (1e+12, 5) lies beyond |x|, |z| <= ");
    CHECK(!fs::exists(out));
    const ProcessResult r = oceanbox("soak " + tinyScene("splash.toml", "[splash]\nmax_particles = 10000000\n") + " --seconds 0.05");
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK(r.output.find("warning: ") != std::string::npos);
    CHECK(r.output.find("splash.max_particles = 10000000: at that many live drops a step takes about 1.5 s") != std::string::npos);
}
