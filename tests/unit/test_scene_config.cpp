// Scene files: defaults, overrides, and one clear message (file:line:column: key) for
// every class of bad input, all errors of a file at once.
#include "core/error.h"
#include "core/toml_reader.h"
#include "world/scene.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace ob;
using game::SceneDef;

namespace {

// Parses text as a scene and returns the InputError message ("" if it loaded).
std::string sceneError(const std::string& text, const std::vector<std::string>& sets = {}) {
    try {
        game::parseScene(text, "bad.toml", sets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// A Def with every field kind, for the reader's checks that no scene key exercises yet.
struct ProbeDef {
    int resolution = 64;
    float damping = 0.5f;
    glm::vec2 wind{1.0f, 0.0f};
    bool on = false;
};
template <class V> void describe(V& v, ProbeDef& d) {
    v.field("resolution", d.resolution, powerOfTwo(16, 2048), "cells");
    v.field("damping", d.damping, range(0, 1), "DF");
    v.field("wind", d.wind, direction(), "direction");
    v.field("on", d.on, "switch");
}
struct ProbeScene {
    ProbeDef probe;
};
template <class V> void describe(V& v, ProbeScene& s) { v.section("probe", s.probe); }

std::vector<std::string> probeErrors(const std::string& text, ProbeScene& out) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromString(text, "probe.toml", errors);
    TomlReader reader(doc, errors);
    describe(reader, out);
    reader.finish();
    return errors;
}

} // namespace

TEST_CASE("every shipped scene in config/scenes parses", "[config]") {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes")) {
        INFO(entry.path());
        REQUIRE_NOTHROW(game::loadScene(entry.path().string()));
    }
}

TEST_CASE("an empty or three-line scene is valid and defaults fill the rest", "[config]") {
    SceneDef defaults;
    SceneDef s = game::parseScene("[camera]\nfov_deg = 45\nmode = \"fixed\"\n", "short.toml");
    CHECK(s.camera.fov_deg == 45.0f);
    CHECK(s.camera.mode == game::CameraMode::Fixed);
    CHECK(s.window.width == defaults.window.width);
    CHECK(s.sim.step_hz == defaults.sim.step_hz);
    CHECK(game::parseScene("", "empty.toml").render.fresnel == gfx::Fresnel::Schlick);
}

TEST_CASE("overrides (--set) change any key with TOML values, a bare word is a string", "[config]") {
    SceneDef s = game::parseScene("[render]\nfresnel = \"schlick\"\n", "x.toml",
                                  {"render.fresnel=exact", "camera.position=[1, 2, 3]", "sim.step_hz=120", "window.vsync=false",
                                   "render.exposure=2"});
    CHECK(s.render.fresnel == gfx::Fresnel::Exact);
    CHECK(s.camera.position == glm::vec3(1, 2, 3));
    CHECK(s.sim.step_hz == 120.0f);
    CHECK_FALSE(s.window.vsync);
    CHECK(s.render.exposure == 2.0f);
    CHECK(game::parseScene("", "x.toml", {"render.fresnel=\"exact\""}).render.fresnel == gfx::Fresnel::Exact);
}

TEST_CASE("an unknown key names file, line, column and key path", "[config]") {
    std::string e = sceneError("[render]\nfresnel = \"exact\"\nfresnell = 1\n");
    CHECK(e == "bad.toml:3:1: render.fresnell: unknown key");
}

TEST_CASE("a key an object's type does not read is an error naming the type, in [[objects]] and spawn events", "[config]") {
    // A cannon has no density (its balls have ball_density), a ship no radius: each was once
    // read into the shared ObjectDef and silently ignored.
    std::string e = sceneError("[[objects]]\ntype = \"cannon\"\ndensity = 900.0\n\n[[objects]]\ntype = \"ship\"\nradius = 2.0\n");
    CHECK(e.find("bad.toml:3:11: objects[0].density: a cannon has no 'density'") != std::string::npos);
    CHECK(e.find("bad.toml:7:10: objects[1].radius: a ship has no 'radius'") != std::string::npos);
    CHECK(e.find("ball_density") != std::string::npos);  // says what a cannon reads
    e = sceneError("[[events]]\nat = 1.0\naction = \"spawn\"\n[events.object]\ntype = \"box\"\ncount = 3\n");
    CHECK(e.find("bad.toml:6:9: events[0].object.count: a box has no 'count'") != std::string::npos);
    // Every key a type reads is accepted, the bounding sphere's keys by every type.
    CHECK(sceneError("[[objects]]\ntype = \"fish_school\"\ncount = 3\nspheres = \"custom\"\nsphere_cells = 4.0\n") == "");
    CHECK(sceneError("[[objects]]\ntype = \"box\"\nsize = [1.0, 2.0, 1.0]\nvelocity = [0.0, 0.0, 1.0]\ndensity = 300.0\n") == "");
}

TEST_CASE("an unknown section is an error", "[config]") {
    CHECK(sceneError("[oceans]\nx = 1\n") == "bad.toml:1:2: oceans: unknown section");
}

TEST_CASE("a wrong type names the expected type", "[config]") {
    std::string e = sceneError("[window]\nwidth = \"wide\"\n");
    CHECK(e == "bad.toml:2:9: window.width: expected an integer, got a string");
    CHECK(sceneError("[camera]\nposition = [1, 2]\n") == "bad.toml:2:12: camera.position: expected an array of 3 numbers");
    CHECK(sceneError("render = 3\n") == "bad.toml:1:10: render: expected a section (table), got an integer");
}

TEST_CASE("an out-of-range value gives the range and the value", "[config]") {
    CHECK(sceneError("[camera]\nfov_deg = 170\n") == "bad.toml:2:11: camera.fov_deg: must be in [10, 120], got 170");
    CHECK(sceneError("[render]\nfresnel = \"fast\"\n") ==
          "bad.toml:2:11: render.fresnel: must be one of \"schlick\", \"exact\", got \"fast\"");
    CHECK(sceneError("[render]\nsun_direction = [0, 0, 0]\n") ==
          "bad.toml:2:17: render.sun_direction: must not be the zero vector (it is a direction)");
}

TEST_CASE("all errors of a file are reported, not only the first", "[config]") {
    std::string e = sceneError("[window]\nwidth = 1\nheight = \"x\"\n[camera]\nbogus = 2\n");
    CHECK(e.find("bad.toml:2:9: window.width: must be in [16, 8192], got 1") != std::string::npos);
    CHECK(e.find("bad.toml:3:10: window.height: expected an integer") != std::string::npos);
    CHECK(e.find("bad.toml:5:1: camera.bogus: unknown key") != std::string::npos);
}

TEST_CASE("a TOML syntax error names file, line and column", "[config]") {
    std::string e = sceneError("[window]\nwidth = = 3\n");
    CHECK(e.rfind("bad.toml:2:", 0) == 0);
    CHECK(e.find("TOML syntax error") != std::string::npos);
}

TEST_CASE("a missing scene file is one clear error", "[config]") {
    try {
        game::loadScene("/nonexistent/scene.toml");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()) == "/nonexistent/scene.toml: cannot open file (no such file)");
    }
}

TEST_CASE("override (--set) values are validated like file values and name the override", "[config]") {
    CHECK(sceneError("", {"camera.fov_deg=500"}) == "--set camera.fov_deg=500: camera.fov_deg: must be in [10, 120], got 500");
    CHECK(sceneError("", {"camera.nope=1"}) == "--set camera.nope=1: camera.nope: unknown key");
    CHECK(sceneError("", {"novalue"}) == "--set novalue: expected key.path=value");
    CHECK(sceneError("[render]\nfresnel = \"exact\"\n", {"render.fresnel.x=1"}) ==
          "--set render.fresnel.x=1: 'fresnel' is not a section");
    CHECK(sceneError("", {"render.fresnel.x=1"}) == "--set render.fresnel.x=1: render.fresnel: expected a string, got a table");
    CHECK(sceneError("", {"a b=1"}) == "--set a b=1: expected key.path=value");
}

TEST_CASE("integer keys can require a power of two in a range", "[config]") {
    ProbeScene s;
    CHECK(probeErrors("[probe]\nresolution = 256\n", s).empty());
    CHECK(s.probe.resolution == 256);
    auto errors = probeErrors("[probe]\nresolution = 100\n", s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0] == "probe.toml:2:14: probe.resolution: must be a power of two in [16, 2048], got 100");
    errors = probeErrors("[probe]\nresolution = 4096\n", s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0] == "probe.toml:2:14: probe.resolution: must be a power of two in [16, 2048], got 4096");
}

TEST_CASE("float keys accept integers, reject non-numbers, check [min, max]", "[config]") {
    ProbeScene s;
    CHECK(probeErrors("[probe]\ndamping = 1\n", s).empty());
    CHECK(s.probe.damping == 1.0f);
    auto errors = probeErrors("[probe]\ndamping = 1.5\nwind = [0, 0]\non = 1\n", s);
    REQUIRE(errors.size() == 3);
    CHECK(errors[0] == "probe.toml:2:11: probe.damping: must be in [0, 1], got 1.5");
    CHECK(errors[1] == "probe.toml:3:8: probe.wind: must not be the zero vector (it is a direction)");
    CHECK(errors[2] == "probe.toml:4:6: probe.on: expected true or false, got an integer");
    CHECK(s.probe.damping == 1.0f);  // a rejected value leaves the previous one
}

namespace {
struct WaveItem {
    float amplitude = 1.0f;
    float kx = 0.0f;
};
template <class V> void describe(V& v, WaveItem& d) {
    v.field("amplitude", d.amplitude, range(0, 10), "m");
    v.field("kx", d.kx, any(), "rad/m");
}
struct ListScene {
    std::vector<WaveItem> waves{WaveItem{}, WaveItem{}, WaveItem{}};
};
template <class V> void describe(V& v, ListScene& s) { v.list("waves", s.waves, "waves"); }

std::vector<std::string> listErrors(const std::string& text, ListScene& out) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromString(text, "list.toml", errors);
    TomlReader reader(doc, errors);
    describe(reader, out);
    reader.finish();
    return errors;
}
} // namespace

TEST_CASE("arrays of tables read each element by its schema, with indexed key paths", "[config]") {
    ListScene s;
    CHECK(listErrors("", s).empty());
    CHECK(s.waves.size() == 3);  // absent: the default list stays
    CHECK(listErrors("[[waves]]\namplitude = 2\n[[waves]]\nkx = 0.5\n", s).empty());
    REQUIRE(s.waves.size() == 2);
    CHECK(s.waves[0].amplitude == 2.0f);
    CHECK(s.waves[1].amplitude == 1.0f);  // element defaults fill missing keys
    CHECK(s.waves[1].kx == 0.5f);
    CHECK(listErrors("waves = [{ amplitude = 3 }]\n", s).empty());
    CHECK(s.waves.size() == 1);
    auto errors = listErrors("[[waves]]\namplitude = 20\n[[waves]]\nky = 1\n", s);
    REQUIRE(errors.size() == 2);
    CHECK(errors[0] == "list.toml:2:13: waves[0].amplitude: must be in [0, 10], got 20");
    CHECK(errors[1] == "list.toml:4:1: waves[1].ky: unknown key");
    errors = listErrors("waves = [1, 2]\n", s);
    REQUIRE(errors.size() == 2);
    CHECK(errors[0].find("waves[0]: expected a table, got an integer") != std::string::npos);
}

TEST_CASE("overrides (--set) reach into [[objects]] by index: objects[1].count=N", "[config]") {
    const std::string text = "[[objects]]\ntype = \"ship\"\n[[objects]]\ntype = \"fish_school\"\ncount = 3\n";
    SceneDef s = game::parseScene(text, "x.toml", {"objects[1].count=1000", "objects[0].speed=2.5", "objects[1].position=[1, 0, 2]"});
    REQUIRE(s.objects.size() == 2);
    CHECK(s.objects[1].school.count == 1000);
    CHECK(s.objects[0].ship.speed == 2.5f);
    CHECK(s.objects[1].position == glm::vec3(1, 0, 2));
    CHECK(sceneError(text, {"objects[2].count=1"}) == "--set objects[2].count=1: 'objects' has no element [2]");
    // An index beyond size_t (found by fuzz_scene: std::stoul threw out_of_range) is no element either.
    CHECK(sceneError(text, {"objects[99999999999999999999999].count=1"}) ==
          "--set objects[99999999999999999999999].count=1: 'objects' has no element [99999999999999999999999]");
    CHECK(sceneError(text, {"objects[1].count=0"}) == "--set objects[1].count=0: objects[1].count: must be in [1, 1000000], got 0");
    CHECK(sceneError(text, {"objects[1]=3"}).rfind("--set objects[1]=3: expected key.path=value", 0) == 0);
}

TEST_CASE("scene errors in objects and events name the key path, events are checked against the scene", "[config]") {
    CHECK(sceneError("[[objects]]\ntype = \"submarine\"\n") ==
          "bad.toml:2:8: objects[0].type: must be one of \"sphere\", \"box\", \"ship\", \"cannon\", \"fish_school\", got \"submarine\"");
    CHECK(sceneError("[[objects]]\ntype = \"ship\"\nwaypoints = [[1, 2], [3]]\n") ==
          "bad.toml:3:22: objects[0].waypoints: expected an array of [x, z] pairs");
    CHECK(sceneError("[[events]]\nat = 1\naction = \"explode\"\n") ==
          "bad.toml:3:10: events[0].action: must be one of \"fire\", \"spawn\", \"set_speed\", \"set\", \"camera\", \"screenshot\", got \"explode\"");
    CHECK(sceneError("[[events]]\naction = \"fire\"\ntarget = \"nobody\"\n") == "bad.toml: events[0].target: no object is named 'nobody'");
    CHECK(sceneError("[[events]]\naction = \"set\"\nkey = \"render.nope\"\n") ==
          "bad.toml: events[0].key: 'render.nope' is not a number or switch of the scene");
    CHECK(sceneError("[[events]]\naction = \"set\"\nkey = \"ocean.wind_speed\"\nvalue = 3\n").find("is read once at start") != std::string::npos);
    CHECK(sceneError("[[events]]\naction = \"set\"\nkey = \"ripples.damping\"\nvalue = 3\n").find("events[0].value: value out of") !=
          std::string::npos);
    CHECK(sceneError("[[events]]\naction = \"spawn\"\nobject = { type = \"ship\", speed = -1 }\n") ==
          "bad.toml:3:35: events[0].object.speed: must be in [0, 100], got -1");
    CHECK(sceneError("[[events]]\naction = \"set\"\nkey = \"ripples.damping\"\nvalue = 0.9\n[[events]]\naction = \"fire\"\ntarget = \"gun\"\n"
                     "[[objects]]\ntype = \"cannon\"\nname = \"gun\"\n")
              .empty());
}

TEST_CASE("[splash] and [foam] load with defaults, take every key, and reject unknown keys and bad values", "[config][splash][foam]") {
    SceneDef d = game::parseScene("", "empty.toml");
    CHECK(d.splash.enabled);
    CHECK(d.foam.enabled);
    SceneDef s = game::parseScene("[splash]\nenabled = false\nmax_particles = 5000\nemission_scale = 2.0\ndrag = 0.5\n"
                                  "drop_size = 0.002\nmin_speed = 0.5\nmax_life = 4.0\nbow_speed = 2.5\nripple_energy = 0.1\n"
                                  "[foam]\nenabled = false\nresolution = 512\ndecay_s = 3.0\nwhitecap_weight = 1.0\n"
                                  "whitecap_jacobian = 0.3\nripple_weight = 2.0\nripple_slope = 0.4\nsplash_weight = 0.5\n"
                                  "wake_weight = 0.6\nextent_m = 102.4\nflow_resolution = 64\n",
                                  "full.toml", {"foam.decay_s=9"});
    CHECK_FALSE(s.splash.enabled);
    CHECK(s.splash.max_particles == 5000);
    CHECK(s.splash.drag == 0.5f);
    CHECK(s.splash.ripple_energy == 0.1f);
    CHECK_FALSE(s.foam.enabled);
    CHECK(s.foam.resolution == 512);
    CHECK(s.foam.decay_s == 9.0f);
    CHECK(s.foam.wake_weight == 0.6f);
    CHECK(s.foam.extent_m == 102.4f);
    CHECK(s.foam.flow_resolution == 64);
    CHECK(d.foam.extent_m == 0.0f);  // the ripple patch's side
    CHECK(sceneError("[splash]\nspray = 1\n") == "bad.toml:2:1: splash.spray: unknown key");
    CHECK(sceneError("[foam]\ndecay = 1\n") == "bad.toml:2:1: foam.decay: unknown key");
    CHECK(sceneError("[foam]\nresolution = 300\n").find("foam.resolution") != std::string::npos);
    CHECK(sceneError("[foam]\nflow_resolution = 24\n").find("foam.flow_resolution") != std::string::npos);
    CHECK(sceneError("[foam]\nextent_m = -1\n").find("foam.extent_m") != std::string::npos);
    CHECK(sceneError("[foam]\ndecay_s = 0\n").find("foam.decay_s") != std::string::npos);
    CHECK(sceneError("[splash]\ndrag = -1\n").find("splash.drag") != std::string::npos);
}
