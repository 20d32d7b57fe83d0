// Hostile input, unit by unit: what a careless user or an attacker may hand the loaders and
// writers (devices, named pipes, symlinks, huge keys, numbers beyond a float) gives one clear
// InputError, never a crash, a hang, a write through a link or a replaced device.
#include "core/error.h"
#include "core/file_read.h"
#include "core/file_write.h"
#include "core/npy.h"
#include "core/toml_reader.h"
#include "world/input_script.h"
#include "world/scene.h"
#include "support/test_support.h"

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace ob;
using ob::test::tempPath;
using ob::test::writeFile;
namespace fs = std::filesystem;

namespace {

// The InputError message of `load()`, or "" when it returns; fails the test (instead of
// blocking it) when `load` takes more than 5 s: a read that waits on a pipe is a finding.
std::string errorWithin5s(std::function<void()> load) {
    const std::optional<std::string> e = ob::test::inputErrorWithin(5.0, std::move(load));
    if (!e) FAIL("the load did not return within 5 s (it hangs)");
    return e.value_or("");
}

std::string sceneError(const std::string& text, const std::vector<std::string>& sets = {}) {
    try {
        game::parseScene(text, "hostile.toml", sets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A character device like /dev/null (1, 3) in a temporary folder; "" where mknod is not
// permitted (not root): the caller skips its section.
std::string makeNullDevice(const std::string& name) {
    const std::string path = tempPath(name);
    return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0 ? path : "";
}

bool isCharDevice(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

// Temporaries of the output `name` left in `folder` (the writer's pattern).
std::vector<std::string> temporaries(const std::string& folder, const std::string& name) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename().string().rfind("." + name + TEMPORARY_MARK, 0) == 0) found.push_back(entry.path().string());
    return found;
}

} // namespace

// --- readers -------------------------------------------------------------------------------

TEST_CASE("readers refuse a named pipe, a device and a folder before reading, at once and by name", "[hostile][files]") {
    const std::string fifo = tempPath("pipe.npy");
    REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
    const auto start = std::chrono::steady_clock::now();
    std::string e = errorWithin5s([&] { readNpy(fifo); });
    CHECK(e == fifo + ": is not a regular file (a named pipe (FIFO)); give a file");
    e = errorWithin5s([&] { game::loadScene(fifo, {}); });
    CHECK(e.find(fifo + ": is not a regular file (a named pipe (FIFO))") != std::string::npos);
    e = errorWithin5s([&] { game::loadInputScript(fifo); });
    CHECK(e.find("named pipe") != std::string::npos);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));

    const std::string folder = tempPath("folder.npy");
    fs::create_directories(folder);
    CHECK(errorWithin5s([&] { readNpy(folder); }) == folder + ": is a folder, not a file");

    if (const std::string device = makeNullDevice("device.npy"); !device.empty()) {
        e = errorWithin5s([&] { readNpy(device); });
        CHECK(e == device + ": is not a regular file (a character device); give a file");
        CHECK(isCharDevice(device));
    } else {
        SUCCEED("mknod is not permitted here: the device section is skipped");
    }
}

TEST_CASE("a symlink loop is reported as one, not as a missing file", "[hostile][files]") {
    const std::string a = tempPath("loop_a.toml"), b = tempPath("loop_b.toml");
    fs::create_symlink(b, a);
    fs::create_symlink(a, b);
    CHECK(errorWithin5s([&] { readRegularFile(a); }) == a + ": cannot open file (symlink loop)");
    CHECK(errorWithin5s([&] { game::loadScene(a, {}); }) == a + ": cannot open file (symlink loop)");
    CHECK(errorWithin5s([&] { readNpy(a); }).find("symlink loop") != std::string::npos);
    // A model that is a loop is found, then named as one (not "not found").
    const std::string folder = tempPath("loop_models");
    fs::create_directories(folder);
    fs::create_symlink(folder + "/b.gltf", folder + "/a.gltf");
    fs::create_symlink(folder + "/a.gltf", folder + "/b.gltf");
    const std::string scene = writeFile(folder + "/s.toml", "[[objects]]\ntype = \"sphere\"\nmodel = \"a.gltf\"\n");
    CHECK(errorWithin5s([&] { game::loadScene(scene, {}); }) ==
          scene + ":3:9: objects[0].model: " + folder + "/a.gltf: cannot open file (symlink loop)");
}

// --- writers -------------------------------------------------------------------------------

TEST_CASE("an output that is a device, a pipe, a folder or a symlink is refused and left as it is", "[hostile][files]") {
    const std::string victim = writeFile(tempPath("victim.txt"), "precious");
    const std::string link = tempPath("link.json");
    fs::create_symlink(victim, link);
    auto refusal = [](const std::string& path) {
        try {
            writeTextFile(path, "{}", "stats");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::string e = refusal(link);
    CHECK(e.find("cannot write stats '" + link + "': it is a symbolic link to '" + victim + "'") == 0);
    CHECK(readText(victim) == "precious");
    CHECK(fs::is_symlink(link));
    CHECK(refusal("/dev/stdout").find("it is a symbolic link") != std::string::npos);

    const std::string fifo = tempPath("stats_pipe.json");
    REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
    CHECK(refusal(fifo).find("it is a named pipe (FIFO), not a regular file") != std::string::npos);
    CHECK(fs::is_fifo(fifo));
    CHECK(refusal("").find("the path is empty") != std::string::npos);
    CHECK_THROWS_AS(checkWritable(tempPath("no_folder") + "/x.json", "stats"), InputError);

    if (const std::string device = makeNullDevice("null"); !device.empty()) {
        e = refusal(device);
        CHECK(e == "cannot write stats '" + device + "': it is a character device, not a regular file; oceanbox replaces regular "
                   "files only (choose another path)");
        CHECK(isCharDevice(device));
        CHECK_THROWS_AS(checkWritable(device, "stats"), InputError);
    } else {
        SUCCEED("mknod is not permitted here: the device section is skipped");
    }
}

TEST_CASE("the temporary is unique and never followed: a planted link and a user's X.tmp stay untouched", "[hostile][files]") {
    const std::string folder = tempPath("outputs");
    fs::create_directories(folder);
    const std::string out = folder + "/s.json";
    const std::string victim = writeFile(tempPath("victim.txt"), "precious");
    fs::create_symlink(victim, out + ".tmp");              // the old fixed temporary name
    writeFile(folder + "/other.json.tmp", "user's file");  // a file of the user's that happens to be named so
    writeTextFile(out, "{\"a\": 1}\n", "stats");
    CHECK(readText(out) == "{\"a\": 1}\n");
    CHECK(fs::is_regular_file(fs::symlink_status(out)));
    CHECK(readText(victim) == "precious");
    CHECK(fs::is_symlink(out + ".tmp"));
    CHECK(readText(folder + "/other.json.tmp") == "user's file");
    CHECK(temporaries(folder, "s.json").empty());
}

TEST_CASE("the output keeps the old file's mode, and a new one gets 0666 less the umask", "[hostile][files]") {
    const std::string out = writeFile(tempPath("mode.json"), "old");
    fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write);
    writeTextFile(out, "new", "stats");
    CHECK(readText(out) == "new");
    CHECK((fs::status(out).permissions() & fs::perms::all) == (fs::perms::owner_read | fs::perms::owner_write));
    const mode_t mask = ::umask(022);
    ::umask(mask);
    const std::string fresh = tempPath("fresh.json");
    writeTextFile(fresh, "x", "stats");
    CHECK(mode_t(fs::status(fresh).permissions() & fs::perms::all) == (0666 & ~mask));
}

TEST_CASE("two writers of one output never share a temporary: every write succeeds whole", "[hostile][files]") {
    const std::string folder = tempPath("concurrent");
    fs::create_directories(folder);
    const std::string out = folder + "/both.json";
    const std::string a(100000, 'a'), b(100000, 'b');
    std::atomic<int> failures{0};
    auto writer = [&](const std::string& text) {
        for (int i = 0; i < 40; ++i) {
            try {
                writeTextFile(out, text, "stats");
            } catch (const std::exception&) {
                ++failures;
            }
        }
    };
    std::thread first(writer, a), second(writer, b);
    first.join();
    second.join();
    CHECK(failures == 0);
    const std::string last = readText(out);
    CHECK((last == a || last == b));
    CHECK(temporaries(folder, "both.json").empty());
}

TEST_CASE("a killed run's temporaries are removed by the next write to the folder, a live writer's are kept", "[hostile][files]") {
    const std::string folder = tempPath("stale");
    fs::create_directories(folder);
    // A pid that is gone: a child that has exited and been reaped.
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    const std::string stale = writeFile(folder + "/.shot.png" + std::string(TEMPORARY_MARK) + std::to_string(child) + "-Ab12Cd", "half");
    const std::string live = writeFile(folder + "/.shot.png" + std::string(TEMPORARY_MARK) + std::to_string(::getppid()) + "-Zz99Yy", "running");
    const std::string unrelated = writeFile(folder + "/.notes.oceanbox-keep", "mine");
    const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
    for (const std::string& p : {stale, live, unrelated}) fs::last_write_time(p, old);
    writeTextFile(folder + "/stats.json", "{}", "stats");
    CHECK(!fs::exists(stale));
    CHECK(fs::exists(live));
    CHECK(fs::exists(unrelated));
}

// --- the key path of --set -----------------------------------------------------------------

TEST_CASE("a --set key of 50,000 characters or 20,000 segments is one clear error, not a crash", "[hostile][toml]") {
    std::string e = sceneError("[sim]\nseed = 1\n", {std::string(50000, 'a') + "=1"});
    CHECK(e.find("the key path has 50000 characters (at most 256)") != std::string::npos);
    CHECK(e.size() < 1000);
    std::string dotted;
    for (int i = 0; i < 20000; ++i) dotted += "a.";
    e = sceneError("[sim]\nseed = 1\n", {dotted + "b=1"});
    CHECK(e.find("(at most 256)") != std::string::npos);
    e = sceneError("[sim]\nseed = 1\n", {"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q=1"});
    CHECK(e.find("the key path has more than 16 segments") != std::string::npos);
    // What the scanner must still take.
    CHECK(sceneError("[[objects]]\ntype = \"sphere\"\n", {"objects[0].radius=0.7", "ocean.wind_speed=3"}).empty());
    CHECK(sceneError("[sim]\nseed = 1\n", {"objects[0]=1"}).find("a key inside the element") != std::string::npos);
    CHECK(sceneError("[sim]\nseed = 1\n", {"a..b=1"}).find("expected key.path=value") != std::string::npos);
    CHECK(sceneError("[sim]\nseed = 1\n", {"a[x].b=1"}).find("expected key.path=value") != std::string::npos);
    CHECK(sceneError("[sim]\nseed = 1\n", {"a[1"}).find("expected key.path=value") != std::string::npos);
}

// --- numbers -------------------------------------------------------------------------------

TEST_CASE("a finite double beyond a float's range is an error naming file, line and key", "[hostile][toml]") {
    const std::string e = sceneError(R"([[objects]]
type = "sphere"
velocity = [1e308, 1, 1]
[camera]
position = [0, 3e38, 1e39]
[ripples]
center = [-1e300, 0]
[gerstner]
waves = [{ kx = 0.1, kz = 0.0, amplitude = 0.1, phase = 1e40 }]
[[events]]
at = 1.0
action = "camera"
look_at = [0, 0, 5e38]
)");
    INFO(e);
    CHECK(e.find("hostile.toml:3:13: objects[0].velocity: must be a finite number within a 32-bit float's range") !=
          std::string::npos);
    CHECK(e.find("camera.position") != std::string::npos);
    CHECK(e.find("got 1e+39") != std::string::npos);
    CHECK(e.find("ripples.center") != std::string::npos);
    CHECK(e.find("phase") != std::string::npos);
    CHECK(e.find("events[0].look_at") != std::string::npos);
    CHECK(e.find("3e+38") == std::string::npos);  // 3e38 fits a float
}

TEST_CASE("an out-of-range integer is printed as the integer it is", "[hostile][toml]") {
    const std::string e = sceneError("[ocean]\nresolution = 4294967296\n[sim]\nmax_steps_per_frame = -9000000000\n");
    INFO(e);
    CHECK(e.find("got 4294967296") != std::string::npos);
    CHECK(e.find("got -9000000000") != std::string::npos);
    CHECK(e.find("e+09") == std::string::npos);
}

// --- events --------------------------------------------------------------------------------

TEST_CASE("a spawn event's model is loaded with the scene, and a spawn without object or an unknown camera target is an error",
          "[hostile][events]") {
    std::string e = sceneError(R"([[events]]
at = 100.0
action = "spawn"
object = { type = "sphere", model = "nowhere/none.gltf" }
)");
    CHECK(e.find("hostile.toml:4:37: events[0].object.model: glTF file 'nowhere/none.gltf' not found") != std::string::npos);
    e = sceneError("[[events]]\nat = 1.0\naction = \"spawn\"\n");
    CHECK(e.find("hostile.toml:3:10: events[0].object: a spawn event needs the object it adds") != std::string::npos);
    e = sceneError("[[events]]\nat = 1.0\naction = \"camera\"\nmode = \"orbit\"\ntarget = \"ghost\"\n");
    CHECK(e.find("events[0].target: no object is named 'ghost'") != std::string::npos);
    // The same spawn with a model that exists loads, its path resolved.
    const game::SceneDef scene = game::parseScene(
        "[[events]]\nat = 1.0\naction = \"spawn\"\nobject = { type = \"sphere\", model = \"assets/models/cannonball.gltf\" }\n", "ok.toml");
    CHECK(fs::path(scene.events[0].object.model).is_absolute());
}

TEST_CASE("a corrupt far twin (X.lod1.gltf) fails when the scene loads, at the model's key", "[hostile][events]") {
    const std::string folder = tempPath("lod_models");
    fs::create_directories(folder);
    fs::copy_file(fs::path(OCEANBOX_SOURCE_DIR) / "assets/models/cannonball.gltf", folder + "/ball.gltf");
    writeFile(folder + "/ball.lod1.gltf", "{ \"asset\": ");
    const std::string scene = writeFile(folder + "/s.toml", "[[objects]]\ntype = \"sphere\"\nmodel = \"ball.gltf\"\n");
    const std::string e = errorWithin5s([&] { game::loadScene(scene, {}); });
    CHECK(e.find(scene + ":3:9: objects[0].model: " + folder + "/ball.lod1.gltf: not a valid glTF 2.0 file") == 0);
}
