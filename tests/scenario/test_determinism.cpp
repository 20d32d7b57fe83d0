// Determinism: the same scene and seed give the same state hash (every transform, velocity,
// ripple level and ocean map) across runs, worker counts, ocean thread counts and processes
// that plan their FFTs at the same time; a different scene does not.
#include "core/parallel.h"
#include "core/thread_choice.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "ocean/ocean_fft_cpu.h"
#include "world/sandbox.h"
#include "support/test_support.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace ob;

namespace {

uint64_t hashAfterSteps(const game::SceneDef& scene, int steps) {
    game::Sandbox sandbox(scene);
    for (int i = 0; i < steps; ++i) sandbox.step();
    return sandbox.stateHash();
}

// The state hash of a headless run of the default scene; `log` receives what it printed.
std::string cliHash(const std::string& extra, int frames = 120, std::string* log = nullptr) {
    std::string json = test::tempPath("det.json");
    auto r = test::runOceanbox("run config/scenes/default.toml --headless --frames " + std::to_string(frames) + " --size 32x32 --stats " + json + " " + extra);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    if (log) *log = r.output;
    return nlohmann::json::parse(std::ifstream(json))["state_hash"].get<std::string>();
}

std::string statsHash(const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in);
    return nlohmann::json::parse(in)["state_hash"].get<std::string>();
}

// Restores the default worker count and thread measuring however a test ends.
struct WorkerCountGuard {
    ~WorkerCountGuard() {
        setWorkerCount(0);
        setThreadMeasuring(true);
    }
};

} // namespace

TEST_CASE("the default scene stepped twice for 120 steps gives the same state hash", "[determinism][threads][long]") {
    const int steps = test::THREAD_SANITIZER ? 30 : 120;
    game::SceneDef scene = game::loadScene(game::defaultScenePath());
    uint64_t a = hashAfterSteps(scene, steps);
    CHECK(a == hashAfterSteps(scene, steps));
    // The hash sees the state: another drag on the bodies (their poses, their ripples) changes it.
    game::SceneDef other = game::loadScene(game::defaultScenePath(), {"physics.linear_drag=900"});
    CHECK(a != hashAfterSteps(other, steps));
    CHECK(a != hashAfterSteps(scene, steps - 1));
}

TEST_CASE("two headless runs of 120 frames report the same state hash", "[determinism][long]") {
    std::string a = cliHash("");
    CHECK(a == cliHash(""));
    CHECK(a != cliHash("--set camera.follow_height_m=8"));
}

TEST_CASE("the GPU ocean backend (whose query maps are computed a step ahead on another thread) gives the CPU backend's state hash", "[determinism][threads][long]") {
    // 40 frames: the GPU transforms on a software rasteriser are slow, and every frame's
    // maps enter the hash (the ships and the crate float on them from the first step).
    const int frames = test::THREAD_SANITIZER ? 10 : 40;
    std::string gpuLog, cpuLog;
    CHECK(cliHash("--set ocean.backend=gpu", frames, &gpuLog) == cliHash("--set ocean.backend=cpu", frames, &cpuLog));
    // Each ran the backend it was asked for (a GPU run that fell back to the CPU maps would pass the hash).
    CHECK(gpuLog.find("ocean: gpu (compute shaders) backend") != std::string::npos);
    CHECK(cpuLog.find("ocean: cpu (FFTW) backend") != std::string::npos);
}

TEST_CASE("the state hash is the same with 1, 2, 3 and 8 workers (ripple rows and ocean threads split)", "[determinism][parallel][threads][long]") {
    // A 1024² patch splits its 1022 interior rows into chunks of 32 (MIN_CELLS_PER_CHUNK /
    // 1024), so every worker count here really splits it; the 256² ocean runs on 2 threads
    // once 2 workers are set (measuring off: whatever this machine measured, the split runs).
    // The bodies fall in within the 150 steps and ring the patch.
    // Under ThreadSanitizer a 512² patch of the same size: 510 rows in chunks of 64, still 8.
    WorkerCountGuard guard;
    setThreadMeasuring(false);
    const std::string grid = test::THREAD_SANITIZER ? "ripples.resolution=512" : "ripples.resolution=1024";
    const std::string cell = test::THREAD_SANITIZER ? "ripples.cell_size=0.1" : "ripples.cell_size=0.05";
    game::SceneDef scene = game::loadScene(game::defaultScenePath(), {"ripples.model=kang2008", "ripples.levels=1", grid, cell});
    std::vector<uint64_t> hashes;
    for (int workers : {1, 2, 3, 8}) {
        setWorkerCount(workers);
        game::Sandbox sandbox(scene);
        CHECK(sandbox.world().resource<game::OceanState>()->cpu->threadCount() == std::min(workers, 4));
        for (int i = 0; i < 150; ++i) sandbox.step();
        auto field = sandbox.world().resource<interaction::RipplePatch>()->solverAs<ob::interaction::Kang2008Solver>()->field().current();
        CHECK(*std::max_element(field.begin(), field.end()) > 1e-3f);  // the stamps reached the patch
        hashes.push_back(sandbox.stateHash());
    }
    for (size_t i = 1; i < hashes.size(); ++i) CHECK(hashes[i] == hashes[0]);
}

TEST_CASE("the state hash of the ewave default scene is the same on 1, 2 and 3 workers, and with thread counts measured", "[determinism][parallel][threads][long]") {
    // Measuring off: the ewave step's two transforms and the ocean split over the workers (the
    // sources' row bands too, for a step with enough footprint: tests_unit "many sources");
    // measuring on: whatever this machine chose.
    WorkerCountGuard guard;
    const int steps = test::THREAD_SANITIZER ? 16 : 40;
    game::SceneDef scene = game::loadScene(game::defaultScenePath());
    std::vector<uint64_t> hashes;
    setThreadMeasuring(false);
    for (int workers : {1, 2, 3}) {
        setWorkerCount(workers);
        hashes.push_back(hashAfterSteps(scene, steps));
    }
    setThreadMeasuring(true);
    hashes.push_back(hashAfterSteps(scene, steps));
    for (size_t i = 1; i < hashes.size(); ++i) CHECK(hashes[i] == hashes[0]);
}

TEST_CASE("ocean maps are bit-identical on 1, 2, 3 and 8 threads at any time", "[determinism][ocean][threads]") {
    game::SceneDef scene = game::loadScene(game::defaultScenePath());
    ocean::OceanDef def = scene.ocean;
    def.cascades = 3;
    ocean::OceanFftCpu one(def, 1);
    const size_t bytes = size_t(def.resolution) * size_t(def.resolution) * sizeof(float);
    for (int threads : {2, 3, 8}) {
        ocean::OceanFftCpu many(def, threads);
        for (double t : {0.0, 17.25, 3600.0}) {
            one.update(t);
            many.update(t);
            for (int c = 0; c < def.cascades; ++c)
                for (int ch = 0; ch < ocean::OCEAN_CHANNEL_COUNT; ++ch) {
                    INFO("threads " << threads << ", t " << t << ", cascade " << c << ", channel " << ch);
                    CHECK(std::memcmp(one.channel(c, ocean::OceanChannel(ch)), many.channel(c, ocean::OceanChannel(ch)), bytes) == 0);
                }
        }
    }
}

TEST_CASE("processes that plan their FFTs at the same time with an empty wisdom cache agree bit for bit", "[determinism][ocean]") {
    // FFTW_MEASURE picks a plan by timing and different plans round differently: without the
    // wisdom file's lock, two processes measuring at once could disagree.
    const std::string cache = test::tempPath("wisdom_cache");
    std::filesystem::create_directories(cache);
    std::vector<std::string> stats;
    std::string command;
    for (int k = 0; k < 3; ++k) {
        stats.push_back(test::tempPath("plan_" + std::to_string(k) + ".json"));
        command += "XDG_CACHE_HOME='" + cache + "' \"$OCEANBOX\" soak config/scenes/default.toml --seconds 1 --stats " +
                   stats.back() + " > /dev/null & ";
    }
    auto r = test::runShell(command + "wait");
    INFO(r.output);
    CHECK(std::filesystem::exists(cache + "/oceanbox/fftw_wisdom_f"));
    const std::string first = statsHash(stats[0]);
    for (const std::string& s : stats) CHECK(statsHash(s) == first);
    // A later run reads the plan the first one measured.
    const std::string later = test::tempPath("plan_later.json");
    r = test::runShell("XDG_CACHE_HOME='" + cache + "' \"$OCEANBOX\" soak config/scenes/default.toml --seconds 1 --stats " + later);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(statsHash(later) == first);
}

TEST_CASE("without a writable wisdom cache the estimated FFT plans give the same hash in every run", "[determinism][ocean]") {
    std::vector<std::string> hashes;
    for (int k = 0; k < 2; ++k) {
        const std::string json = test::tempPath("estimate.json");
        auto r = test::runShell("XDG_CACHE_HOME=/proc/oceanbox-no-cache \"$OCEANBOX\" soak config/scenes/default.toml "
                                "--seconds 1 --stats " + json);
        INFO(r.output);
        REQUIRE(r.exitCode == 0);
        CHECK(r.output.find("cannot be written: using estimated FFT plans") != std::string::npos);
        hashes.push_back(statsHash(json));
    }
    CHECK(hashes[0] == hashes[1]);
}
