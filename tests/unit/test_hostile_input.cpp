// Hostile input, unit by unit: what a careless user or an attacker may hand the loaders and
// writers (devices, named pipes, symlinks, huge keys, numbers beyond a float) gives one clear
// InputError, never a crash, a hang, a write through a link or a replaced device.
#include "core/error.h"
#include "core/file_read.h"
#include "core/file_write.h"
#include "core/file_identity.h"
#include "core/npy.h"
#include "core/printable.h"
#include "core/toml_reader.h"
#include "ecs/schedule.h"
#include "tools/cmd_dump_surface.h"
#include "world/input_script.h"
#include "world/scene.h"
#include "world/scene_budget.h"
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

// === Second round (docs/reliability.md#hostile-input) ======================================

// --- text from files is inert --------------------------------------------------------------

TEST_CASE("control characters become printable escapes, other text, UTF-8 included, is left as it is", "[hostile][text]") {
    // ESC [2J clears the screen, OSC 52 sets the clipboard, U+009B is the one-character CSI,
    // U+202E reverses what follows; 0xff is no UTF-8 at all.
    const std::string hostile = "a\x1b[2J\x1b]52;c;ZXZpbA==\x07" "b\x7f\xc2\x9b" "c\xe2\x80\xae" "d\xff\n";
    const std::string shown = printable(hostile);
    CHECK(shown == "a\\x1b[2J\\x1b]52;c;ZXZpbA==\\x07b\\x7f\\u009bc\\u202ed\\xff\\x0a");
    CHECK(isPrintable(shown));
    CHECK(!isPrintable(hostile));
    CHECK(printable(shown) == shown);  // read twice, the same
    const std::string plain = "ship 2 — 12 m² × 3, é, \\x1b as text";
    CHECK(printable(plain) == plain);
    // A value repeated in a message: cut, its size said, still one line.
    const std::string big(1 << 20, 'v');
    const std::string q = quotedValue(big);
    CHECK(q.size() < 2 * MESSAGE_VALUE_CHARS);
    CHECK(q.find("(1048576 characters)") != std::string::npos);
    CHECK(quotedValue("x\x1by") == "'x\\x1by'");
    const std::string message = printableMessage("one\n" + std::string(5000, 'w') + "\x1b" + "\nthree");
    CHECK(message.find("one\n") == 0);
    CHECK(message.find("(a line of 5001 characters, cut)\nthree") != std::string::npos);
    CHECK(message.find('\x1b') == std::string::npos);
}

TEST_CASE("a scene's strings are read inert: a note with terminal escapes holds their printable form", "[hostile][text]") {
    const game::SceneDef scene = game::parseScene(
        "[scene]\nnote = \"\\u001b[2J\\u001b]52;c;ZXZpbA==\\u0007 hello\\u009b\"\n"
        "[[objects]]\ntype = \"sphere\"\nname = \"ball\\u001b[31m\"\n"
        "[[events]]\nat = 1.0\naction = \"camera\"\nmode = \"follow\"\ntarget = \"ball\\u001b[31m\"\n",
        "inert.toml");
    CHECK(scene.info.note == "\\x1b[2J\\x1b]52;c;ZXZpbA==\\x07 hello\\u009b");
    CHECK(isPrintable(scene.objects[0].name));
    CHECK(scene.events[0].target == scene.objects[0].name);  // names still match one another
    // A bad value of a megabyte is named by its start and its size, in a short line.
    const std::string e = sceneError("[render]\nfresnel = \"" + std::string(1 << 20, 'f') + "\"\n");
    CHECK(e.find("render.fresnel: must be one of") != std::string::npos);
    CHECK(e.find("(1048576 characters)") != std::string::npos);
    CHECK(e.size() < 400);
    const std::string key = sceneError("[sim]\n\"" + std::string(100000, 'k') + "\\u001b\" = 1\n");
    CHECK(key.find("(100001 characters): unknown key") != std::string::npos);
    CHECK(key.size() < 400);
}

// --- names resolve at load -----------------------------------------------------------------

TEST_CASE("camera.follow, ripples.follow's ship and a follow camera resolve at load, or fail naming file, line and key",
          "[hostile][names]") {
    std::string e = sceneError("[camera]\nfollow = \"ghost\"\n");
    CHECK(e.find("hostile.toml:2:10: camera.follow: no object is named 'ghost'") != std::string::npos);
    e = sceneError("[ripples]\nfollow = \"ship\"\n");
    CHECK(e.find("hostile.toml:2:10: ripples.follow: \"ship\"") != std::string::npos);
    CHECK(e.find("the scene has no ship") != std::string::npos);
    e = sceneError("[camera]\nmode = \"follow\"\n");
    CHECK(e.find("hostile.toml:2:8: camera.mode: \"follow\"") != std::string::npos);
    // What resolves loads: a named object, a ship, a ship an event spawns.
    CHECK(sceneError("[camera]\nmode = \"follow\"\nfollow = \"b\"\n[[objects]]\ntype = \"sphere\"\nname = \"b\"\n").empty());
    CHECK(sceneError("[ripples]\nfollow = \"ship\"\n[[objects]]\ntype = \"ship\"\n").empty());
    CHECK(sceneError("[camera]\nmode = \"follow\"\n[[events]]\nat = 1.0\naction = \"spawn\"\nobject = { type = \"ship\" }\n").empty());
    // Every shipped scene still loads.
    for (const auto& entry : fs::directory_iterator(fs::path(OCEANBOX_SOURCE_DIR) / "config/scenes")) {
        INFO(entry.path().string());
        CHECK(errorWithin5s([&] { game::loadScene(entry.path().string()); }).empty());
    }
}

// --- a scene writes only beside itself -----------------------------------------------------

TEST_CASE("a screenshot event's file stays in the scene's folder: absolute, '..', a link out or the scene itself fail at load",
          "[hostile][outputs]") {
    const std::string folder = tempPath("confined");
    fs::create_directories(folder + "/shots");
    const std::string outside = tempPath("outside");
    fs::create_directories(outside);
    fs::create_directory_symlink(outside, folder + "/out");
    auto load = [&](const std::string& file, const std::vector<std::string>& sets = {}) {
        const std::string scene = writeFile(folder + "/s.toml", "[[events]]\nat = 1.0\naction = \"screenshot\"\nfile = \"" + file + "\"\n");
        return errorWithin5s([&] { game::loadScene(scene, sets); });
    };
    const std::string where = folder + "/s.toml:4:8: events[0].file: ";
    CHECK(load("/tmp/victim.png").find(where + "'/tmp/victim.png' must be a path relative to the scene's folder") == 0);
    CHECK(load("shots/../../x.png").find(where + "'shots/../../x.png' must be a path relative") == 0);
    CHECK(load("out/x.png").find(where + "'out/x.png' leads outside the scene's folder") == 0);
    CHECK(load("s.toml").find(where + "'s.toml' is the scene file itself") == 0);
    CHECK(load("./shots/../s.toml").find("must be a path relative") != std::string::npos);
    // Inside: stored absolute, in the scene's folder, whatever the current folder.
    CHECK(load("shots/a.png").empty());
    const game::SceneDef scene = game::loadScene(folder + "/s.toml");
    CHECK(scene.events[0].file == (fs::absolute(folder) / "shots/a.png").lexically_normal().string());
    // The default file, event.png, goes there too.
    writeFile(folder + "/d.toml", "[[events]]\nat = 1.0\naction = \"screenshot\"\n");
    CHECK(game::loadScene(folder + "/d.toml").events[0].file == (fs::absolute(folder) / "event.png").lexically_normal().string());
    // A file given on the command line (--set) is the user's own: kept as typed.
    const game::SceneDef typed = game::loadScene(folder + "/s.toml", {"events[0].file=\"/tmp/typed.png\""});
    CHECK(typed.events[0].file == "/tmp/typed.png");
}

TEST_CASE("outputs are compared with inputs and with each other by identity: links, hard links, other spellings",
          "[hostile][outputs]") {
    const std::string folder = tempPath("identity");
    fs::create_directories(folder + "/sub");
    const std::string scene = writeFile(folder + "/s.toml", "[sim]\nseed = 1\n");
    fs::create_hard_link(scene, folder + "/hard.toml");
    fs::create_symlink(scene, folder + "/soft.toml");
    CHECK(sameFile(scene, folder + "/hard.toml"));
    CHECK(sameFile(scene, folder + "/soft.toml"));
    CHECK(sameFile(scene, folder + "/sub/../s.toml"));
    CHECK(sameFile(folder + "/new.json", folder + "/sub/../new.json"));  // neither exists yet
    CHECK(!sameFile(folder + "/new.json", folder + "/other.json"));
    CHECK(!sameFile(scene, folder + "/s.toml.json"));
    CHECK(isInsideFolder(folder + "/sub/x.png", folder));
    CHECK(!isInsideFolder(folder + "/../x.png", folder));
    CHECK(!isInsideFolder(folder + "x/y.png", folder));  // a sibling sharing the prefix
    auto refused = [](const std::vector<NamedPath>& in, const std::vector<NamedPath>& out) {
        try {
            checkOutputsApart(in, out);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    CHECK(refused({{"the scene file", scene}}, {{"--stats", folder + "/hard.toml"}})
              .find("--stats '" + folder + "/hard.toml' is the scene file '" + scene + "'") == 0);
    CHECK(refused({}, {{"--stats", folder + "/x"}, {"--screenshot", folder + "/sub/../x"}})
              .find("--screenshot '" + folder + "/sub/../x' and --stats '" + folder + "/x' name one file") == 0);
    CHECK(refused({{"the scene file", scene}}, {{"--stats", folder + "/a.json"}, {"--screenshot", folder + "/b.png"}, {"--record", ""}}).empty());
}

TEST_CASE("an output name whose temporary would pass the folder's name limit is refused before any write", "[hostile][outputs]") {
    const std::string folder = tempPath("names");
    fs::create_directories(folder);
    const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    REQUIRE(limit > 40);
    // The temporary: "." + name + ".oceanbox-" + pid + "-" + 6 characters.
    const size_t overhead = 1 + std::string(TEMPORARY_MARK).size() + std::to_string(::getpid()).size() + 1 + 6;
    const std::string longest = folder + "/" + std::string(size_t(limit) - overhead, 'n');
    CHECK_NOTHROW(checkWritable(longest, "stats"));
    writeTextFile(longest, "whole", "stats");
    CHECK(readText(longest) == "whole");
    const std::string over = longest + "n";
    std::string e;
    try {
        checkWritable(over, "stats");
    } catch (const InputError& error) {
        e = error.what();
    }
    CHECK(e.find("and the temporary written beside it first") != std::string::npos);
    CHECK(e.find("give a name of at most " + std::to_string(size_t(limit) - overhead) + " characters") != std::string::npos);
    CHECK(!fs::exists(over));
}

// --- bounded runaway inputs ----------------------------------------------------------------

TEST_CASE("an input file's steps stop at a day of play at the fastest step rate, its size at --size's range", "[hostile][input]") {
    auto error = [](const std::string& text) {
        const std::string path = writeFile(tempPath("steps.toml"), text);
        return errorWithin5s([&] { game::loadInputScript(path); });
    };
    CHECK(game::MAX_RECORDED_STEPS == uint64_t(24 * 3600) * 1000u);
    CHECK(error("steps = 86400000\n").empty());
    std::string e = error("steps = 86400001\n");
    CHECK(e.find(":1:9: steps: at most 86400000 (a day of play at the fastest step rate, 1000 Hz), got 86400001") != std::string::npos);
    CHECK(!error("steps = 9223372036854775807\n").empty());
    CHECK(error("size = [8192.0, 16.0]\n").empty());
    e = error("size = [16384.0, 720.0]\n");
    CHECK(e.find("size: must be 0 (auto) or in [16, 8192], got 16384") != std::string::npos);
}

TEST_CASE("a scene's grids are weighed at load: more than the process may hold is named grid by grid", "[hostile][memory]") {
    game::SceneDef big = game::parseScene("[ocean]\nresolution = 2048\ncascades = 4\n[ripples]\nresolution = 4096\nlevels = 4\n"
                                          "[foam]\nresolution = 4096\nflow_resolution = 4096\n[currents]\nresolution = 1024\n",
                                          "big.toml");
    const std::string e = game::checkSceneMemory(big, double(1ull << 30));
    INFO(e);
    CHECK(e.find("the scene's grids need at least") == 0);
    CHECK(e.find("ripples.resolution 4096² × ripples.levels 4: ") != std::string::npos);
    CHECK(e.find("ocean.resolution 2048² × ocean.cascades 4: ") != std::string::npos);
    CHECK(e.find("foam.resolution 4096²") != std::string::npos);
    CHECK(e.find("currents.resolution 1024²") != std::string::npos);
    CHECK(e.find("may hold 1.0 GiB") != std::string::npos);
    // The kang2008 field is two float levels, Vh(t) and Vh(t-1): 8 bytes a cell.
    game::SceneDef kang = game::parseScene("[ripples]\nmodel = \"kang2008\"\nresolution = 2048\n", "kang.toml");
    bool found = false;
    for (const game::MemoryNeed& n : game::sceneMemory(kang))
        if (n.what == "ripples.resolution 2048²") {
            found = true;
            CHECK(n.bytes == 2.0 * 4.0 * 2048.0 * 2048.0);
        }
    CHECK(found);
    // Every shipped scene fits in a gigabyte, and says nothing of its cost.
    for (const auto& entry : fs::directory_iterator(fs::path(OCEANBOX_SOURCE_DIR) / "config/scenes")) {
        const game::SceneDef scene = game::loadScene(entry.path().string());
        INFO(entry.path().string());
        CHECK(game::checkSceneMemory(scene, double(1ull << 30)).empty());
        CHECK(game::costWarnings(scene).empty());
    }
    CHECK(game::processMemoryLimit() > 0.0);
}

TEST_CASE("legal-but-huge splash maxima warn with their cost, and a frame over 10 s names its largest phase", "[hostile][cost]") {
    game::SceneDef scene = game::parseScene("[splash]\nmax_particles = 10000000\nspray_per_step = 100000\n", "splash.toml");
    const std::vector<std::string> warnings = game::costWarnings(scene);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("splash.max_particles = 10000000: ") == 0);
    CHECK(warnings[0].find("90-fold") != std::string::npos);  // 10⁷ × 150 ns = 1.5 s against 1/60 s
    scene.splash.max_particles = 100000;  // the default keeps up: 15 ms a step of 16.7
    CHECK(game::costWarnings(scene).empty());

    ecs::FrameTimer timer;
    timer.beginFrame();
    timer.addCpu(ecs::Phase::Physics, 2000.0);
    timer.addCpu(ecs::Phase::Interaction, 9500.0);
    timer.endFrame(11600.0);
    const std::string note = game::slowFrameNote(timer, game::SLOW_FRAME_MS);
    CHECK(note.find("a frame took 11.6 s (more than 10 s), 9.5 s of it in the interaction phase") == 0);
    timer.beginFrame();
    timer.addCpu(ecs::Phase::Render, 9000.0);
    timer.endFrame(9900.0);
    CHECK(game::slowFrameNote(timer, game::SLOW_FRAME_MS).empty());
}

TEST_CASE("dumps refuse coordinates where a float no longer holds the shortest wave's phase", "[hostile][dump]") {
    // k = 2π rad/m (a 1 m wave): 0.01 rad / (2π · 2^-24) = 26.7 km.
    CHECK(game::largestExactCoordinate(2.0 * std::numbers::pi) == Approx(0.01 * 16777216.0 / (2.0 * std::numbers::pi)));
    CHECK(std::isinf(game::largestExactCoordinate(0.0)));
    ocean::GerstnerDef def;
    def.waves = {{0.5f, 0.0f, 0.2f, 0.0f}};  // k = 0.5 rad/m: 335 km
    const std::string out = tempPath("far.npy");
    std::string e;
    try {
        game::dumpGerstner(def, 9.81f, 0.0, 4, 1e12f, out);
    } catch (const InputError& error) {
        e = error.what();
    }
    CHECK(e.find("--extent 1e+12: the rest points reach |x| = 1e+12 m, and at most 3.36e+05 m") == 0);
    CHECK(!fs::exists(out));
    CHECK_NOTHROW(game::dumpGerstner(def, 9.81f, 0.0, 4, 3e5f, out));
}
