// Memory per grid cell, measured: the peak RSS of `oceanbox soak S.toml --seconds 0.02` (one
// step, no GL) at two sizes of one grid, the rest at their smallest, the difference over the
// cells added (docs/reliability.md#hostile-input). Rounded down: the estimate is a lower bound.
#include "world/scene_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sys/resource.h>
#include <unistd.h>

namespace ob::game {

namespace {

// Ocean, per spectrum point and cascade: 137 B measured (1024²: 140 MB, 2 cascades 278 MB):
// the packed FFT buffers (complex), the initial spectra and the unpacked maps.
constexpr double OCEAN_BYTES_PER_POINT = 130.0;
// ewave, per cell: 96 B for one level (1024²: 101 MB; 2048²: 386 MB): the field, its
// spectrum and per-mode coefficients; each coarser level 126 B more (2048², 2 levels:
// 934 MB): its two frames' (h, v, ξ, u) and the shown height.
constexpr double EWAVE_BYTES_PER_CELL = 90.0;
constexpr double EWAVE_LEVEL_BYTES_PER_CELL = 120.0;
// kang2008, per cell: its two float levels Vh(t), Vh(t-1) (8 B; 2048²: 33 MB measured).
constexpr double KANG2008_BYTES_PER_CELL = 8.0;
// Foam, per map cell 12 B (2048²: 50 MB) and per point of the surface-velocity grid 68 B
// (flow_resolution 2048: 286 MB).
constexpr double FOAM_BYTES_PER_CELL = 12.0;
constexpr double FOAM_FLOW_BYTES_PER_POINT = 64.0;
// Currents, per cell: 64 B (1024²: 65 MB): velocity, pressure and the advection's copies.
constexpr double CURRENT_BYTES_PER_CELL = 60.0;
// A fish: 50 B (10⁵ fish: 4.9 MB): position, velocity, jump state.
constexpr double FISH_BYTES = 48.0;

std::string memoryGridText(const char* key, int n) { return std::string(key) + " " + std::to_string(n) + "²"; }

} // namespace

std::vector<MemoryNeed> sceneMemory(const SceneDef& scene) {
    std::vector<MemoryNeed> needs;
    const double oceanPoints = double(scene.ocean.resolution) * double(scene.ocean.resolution);
    needs.push_back({memoryGridText("ocean.resolution", scene.ocean.resolution) + " × ocean.cascades " +
                         std::to_string(scene.ocean.cascades),
                     OCEAN_BYTES_PER_POINT * oceanPoints * scene.ocean.cascades});
    const interaction::RippleDef& ripples = scene.ripples;
    const double cells = double(ripples.resolution) * double(ripples.resolution);
    if (ripples.enabled && ripples.model == interaction::rippleModel("ewave"))
        needs.push_back({memoryGridText("ripples.resolution", ripples.resolution) + " × ripples.levels " + std::to_string(ripples.levels),
                         cells * (EWAVE_BYTES_PER_CELL + EWAVE_LEVEL_BYTES_PER_CELL * (ripples.levels - 1))});
    else if (ripples.enabled)
        needs.push_back({memoryGridText("ripples.resolution", ripples.resolution), cells * KANG2008_BYTES_PER_CELL});
    // The foam map lives on the ripple patch.
    if (scene.foam.enabled && ripples.enabled) {
        const double flow = double(std::min(scene.foam.flow_resolution, scene.foam.resolution)) + 1.0;
        needs.push_back({memoryGridText("foam.resolution", scene.foam.resolution) + " with " +
                             memoryGridText("foam.flow_resolution", scene.foam.flow_resolution),
                         FOAM_BYTES_PER_CELL * double(scene.foam.resolution) * double(scene.foam.resolution) +
                             FOAM_FLOW_BYTES_PER_POINT * flow * flow});
    }
    if (scene.currents.enabled)
        needs.push_back({memoryGridText("currents.resolution", scene.currents.resolution),
                         CURRENT_BYTES_PER_CELL * double(scene.currents.resolution) * double(scene.currents.resolution)});
    double fish = 0.0;
    for (const ObjectDef& o : scene.objects)
        if (o.type == ObjectType::FishSchool) fish += double(o.school.count);
    if (fish > 0.0) needs.push_back({"objects' fish_school counts " + std::to_string(long(fish)) + " fish", FISH_BYTES * fish});
    std::stable_sort(needs.begin(), needs.end(), [](const MemoryNeed& a, const MemoryNeed& b) { return a.bytes > b.bytes; });
    return needs;
}

double processMemoryLimit() {
    double limit = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
    for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
        struct rlimit r {};
        if (::getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY) limit = std::min(limit, double(r.rlim_cur));
    }
    return limit;
}

std::vector<std::string> costWarnings(const SceneDef& scene) {
    std::vector<std::string> warnings;
    const double stepSeconds = 1.0 / double(scene.sim.step_hz);
    const double dropsSeconds = double(scene.splash.max_particles) * SPLASH_DROP_STEP_SECONDS;
    if (scene.splash.enabled && dropsSeconds > stepSeconds) {
        char line[400];
        std::snprintf(line, sizeof line,
                      "splash.max_particles = %d: at that many live drops a step takes about %.2g s (%.0f ns a drop) where "
                      "it lasts %.3g s, so the run falls behind real time %.0f-fold, more in software rendering (about "
                      "1 us a drop drawn); %.0f drops keep up",
                      scene.splash.max_particles, dropsSeconds, SPLASH_DROP_STEP_SECONDS * 1e9, stepSeconds,
                      dropsSeconds / stepSeconds, stepSeconds / SPLASH_DROP_STEP_SECONDS);
        warnings.push_back(line);
    }
    return warnings;
}

std::string slowFrameNote(const ecs::FrameTimer& timer, double thresholdMs) {
    if (timer.frameSamples().empty() || timer.frameSamples().back() <= thresholdMs) return "";
    auto worst = ecs::Phase::Input;
    for (int p = 0; p < ecs::PHASE_COUNT; ++p)
        if (timer.lastCpu(ecs::Phase(p)) > timer.lastCpu(worst)) worst = ecs::Phase(p);
    char line[400];
    std::snprintf(line, sizeof line,
                  "a frame took %.1f s (more than %.0f s), %.1f s of it in the %s phase: the scene asks more of that "
                  "phase than this machine does in real time (lower the sizes it works on: docs/reliability.md#hostile-input)",
                  timer.frameSamples().back() / 1000.0, thresholdMs / 1000.0, timer.lastCpu(worst) / 1000.0, ecs::phaseName(worst));
    return line;
}

std::string byteText(double bytes) {
    char buf[32];
    if (bytes >= double(1ull << 30)) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / double(1ull << 30));
    else std::snprintf(buf, sizeof buf, "%.0f MiB", std::ceil(bytes / double(1ull << 20)));
    return buf;
}

std::string checkSceneMemory(const SceneDef& scene, double limitBytes) {
    const std::vector<MemoryNeed> needs = sceneMemory(scene);
    double total = 0.0;
    for (const MemoryNeed& n : needs) total += n.bytes;
    if (total <= limitBytes) return "";
    std::string list;
    for (const MemoryNeed& n : needs) list += (list.empty() ? "" : "; ") + n.what + ": " + byteText(n.bytes);
    return "the scene's grids need at least " + byteText(total) + " (" + list + ") and this process may hold " +
           byteText(limitBytes) + " (the least of physical memory, ulimit -v and ulimit -d): lower their resolutions";
}

} // namespace ob::game
