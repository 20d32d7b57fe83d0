// `oceanbox soak`: long headless simulation with invariants checked as it runs. The bounds
// come from the scene's physics: the spectrum's own spread, the Gerstner amplitudes, the
// stamps' size (docs/reliability.md gives the figures of every scene).
#include "tools/cmd_soak.h"
#include "behaviours/spawning.h"

#include "tools/app.h"
#include "core/error.h"
#include "core/log.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/stamp_sources.h"
#include "sim/objects.h"
#include "ocean/ocean_fft_cpu.h"
#include "physics/physics_def.h"
#include "world/sandbox.h"
#include "world/script.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <unistd.h>

namespace ob::game {

namespace {

// An FFT height map is a sum of many modes with random phases: close to Gaussian, so 8 σ
// (twice the significant wave height) is met about once in 10^15 samples; a soak of an hour
// looks at about 10^10. A map beyond it has gone wrong, not met a rogue wave.
constexpr float CASCADE_SIGMAS = 8.0f;
// A stamp sets a cell at most radius · SHR away from its base (eq. 5); the linear step with
// DF <= 1 does not amplify (eq. 1–2: the 8 weights of 1/4 sum to 2, and the leapfrog with
// DF <= 1 keeps energy from growing), so overlapping rings reach a few stamps' height at most.
constexpr float RIPPLE_STAMPS = 4.0f;
// A floating body that is deeper (centre below the surface) than twice its extent plus the
// sea's Hs has sunk; rising as far above its start height means it was thrown out.
constexpr float BODY_EXTENTS = 2.0f;
// Memory: what the run may add after its warm-up (MiB, or this fraction of the warm RSS).
constexpr double RSS_GROWTH_MIB = 16.0;
constexpr double RSS_GROWTH_FRACTION = 0.05;
constexpr double WARMUP_SECONDS = 60.0;
constexpr int RSS_EVERY_STEPS = 600;

// Under AddressSanitizer freed memory waits in a quarantine (256 MiB) and ThreadSanitizer
// keeps shadow memory, so the RSS grows without a leak: there LeakSanitizer checks leaks at
// exit instead, and the soak only reports the RSS.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool RSS_MEANINGFUL = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool RSS_MEANINGFUL = false;
#else
constexpr bool RSS_MEANINGFUL = true;
#endif
#else
constexpr bool RSS_MEANINGFUL = true;
#endif

// Max |v| over the span and whether every value is finite; the loop stays branch-free.
struct Scan {
    float maxAbs = 0.0f;
    bool finite = true;
};

Scan scan(std::span<const float> v) {
    float m = 0.0f;
    int bad = 0;
    for (float x : v) {
        const float a = std::fabs(x);
        bad |= !(a <= 3.402823466e38f);  // NaN and ±inf fail
        m = a > m ? a : m;
    }
    return {m, bad == 0};
}

// First index holding a non-finite value (scan() said there is one).
size_t firstNonFiniteIndex(std::span<const float> v) {
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i])) return i;
    return v.size();
}

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

[[noreturn]] void fail(Sandbox& sandbox, const std::string& what) {
    throw RuntimeError("soak: step " + std::to_string(sandbox.schedule().steps()) + " (" +
                       fmt(sandbox.schedule().simTime()) + " s simulated): " + what);
}

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Body i's density (kg/m³) and extent (m: the farthest probe surface from its centre).
float bodyDensity(ecs::World& world, size_t i) {
    auto& bodies = world.pool<Body>();
    const Body& b = bodies.components()[i];
    const ecs::Motion* m = world.find<ecs::Motion>(bodies.entities()[i]);
    return m && b.volume > 0.0f ? m->mass / b.volume : 0.0f;
}

float bodyExtent(const Body& b) {
    float e = 0.0f;
    for (const Probe& p : b.probes) e = std::max(e, glm::length(p.offset) + p.radius);
    return e;
}

} // namespace

double residentMiB() {
    std::ifstream in("/proc/self/statm");
    long pages = 0, resident = 0;
    if (!(in >> pages >> resident)) return 0.0;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

SoakBounds soakBounds(Sandbox& sandbox) {
    SoakBounds b;
    ecs::World& world = sandbox.world();
    if (const OceanState* ocean = world.resource<OceanState>()) {
        const ocean::OceanFftCpu& fft = *ocean->cpu;
        const size_t count = size_t(fft.resolution()) * size_t(fft.resolution());
        double seaVariance = 0.0;
        for (int c = 0; c < fft.cascadeCount(); ++c) {
            const float* h = fft.channel(c, ocean::OceanChannel::Height);
            double sum = 0.0, sum2 = 0.0;
            for (size_t i = 0; i < count; ++i) {
                sum += h[i];
                sum2 += double(h[i]) * h[i];
            }
            const double mean = sum / double(count);
            const double variance = std::max(0.0, sum2 / double(count) - mean * mean);
            seaVariance += variance;
            // A calm sea (wind 0) has σ = 0: any height but 0 would be wrong, so allow a mm.
            b.cascadeHeight.push_back(std::max(1e-3f, CASCADE_SIGMAS * float(std::sqrt(variance))));
        }
        b.seaHs = 4.0f * float(std::sqrt(seaVariance));
        for (const ocean::GerstnerWave& w : ocean->waves) b.gerstnerAmplitude += std::fabs(w.amplitude);
    }
    // The tallest stamp any source can make (an object's overlapping spheres chain through
    // eq. 5's base; a cannon's balls count from the start).
    b.ripple = std::max(1e-3f, RIPPLE_STAMPS * largestStamp(world));
    b.surface = b.gerstnerAmplitude + b.ripple;
    for (float h : b.cascadeHeight) b.surface += h;
    return b;
}

// The ripple patch: kang2008 both levels finite, ewave h finite (a non-finite v reaches h
// in the next step), and the height bounded by the stamps' scale
static void checkRipples(Sandbox& sandbox, const SoakBounds& bounds, SoakReport& report) {
    ecs::World& world = sandbox.world();
    if (const auto* patch = world.resource<interaction::RipplePatch>()) {
        for (const auto& [name, level] : patch->solver().levels()) {
            Scan s = scan(level);
            if (!s.finite) {
                size_t i = firstNonFiniteIndex(level);
                fail(sandbox, std::string("ripple field ") + name + " cell (row " + std::to_string(i / size_t(patch->cols())) +
                                  ", column " + std::to_string(i % size_t(patch->cols())) + ") = " + fmt(level[i]) +
                                  ": not a finite number");
            }
            if (s.maxAbs > bounds.ripple)
                fail(sandbox, std::string("ripple field ") + name + " reaches |Vh| = " + fmt(s.maxAbs) +
                                  " m, beyond the bound " + fmt(bounds.ripple) + " m (4 × the largest stamp source)");
            report.maxRipple = std::max(report.maxRipple, s.maxAbs);
        }
    }
}

// The ocean maps: every channel of every cascade finite, heights within 8 σ
static void checkOceanMaps(Sandbox& sandbox, const SoakBounds& bounds, SoakReport& report) {
    ecs::World& world = sandbox.world();
    if (const OceanState* ocean = world.resource<OceanState>()) {
        const ocean::OceanFftCpu& fft = *ocean->cpu;
        const size_t count = size_t(fft.resolution()) * size_t(fft.resolution());
        report.maxCascadeHeight.resize(size_t(fft.cascadeCount()), 0.0f);
        for (int c = 0; c < fft.cascadeCount(); ++c) {
            for (int ch = 0; ch < ocean::OCEAN_CHANNEL_COUNT; ++ch) {
                std::span<const float> map(fft.channel(c, ocean::OceanChannel(ch)), count);
                Scan s = scan(map);
                if (!s.finite) {
                    size_t i = firstNonFiniteIndex(map);
                    fail(sandbox, "ocean cascade " + std::to_string(c) + " channel " + std::to_string(ch) + " point (" +
                                      std::to_string(i % size_t(fft.resolution())) + ", " +
                                      std::to_string(i / size_t(fft.resolution())) + ") = " + fmt(map[i]) +
                                      ": not a finite number");
                }
                if (ch != int(ocean::OceanChannel::Height)) continue;
                if (s.maxAbs > bounds.cascadeHeight[size_t(c)])
                    fail(sandbox, "ocean cascade " + std::to_string(c) + " height reaches " + fmt(s.maxAbs) +
                                      " m, beyond 8 sigma of its spectrum (" + fmt(bounds.cascadeHeight[size_t(c)]) + " m)");
                report.maxCascadeHeight[size_t(c)] = std::max(report.maxCascadeHeight[size_t(c)], s.maxAbs);
            }
        }
    }
}

// Every transform and velocity finite, rotations unit.
static void checkTransforms(Sandbox& sandbox) {
    ecs::World& world = sandbox.world();
    auto& transforms = world.pool<ecs::Transform>();
    for (size_t i = 0; i < transforms.size(); ++i) {
        const ecs::Transform& t = transforms.components()[i];
        const glm::quat& q = t.rotation;
        const float norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
        if (!finite3(t.position) || !(std::fabs(norm - 1.0f) < 1e-3f))
            fail(sandbox, "entity " + std::to_string(uint32_t(transforms.entities()[i])) + ": position (" +
                              fmt(t.position.x) + ", " + fmt(t.position.y) + ", " + fmt(t.position.z) +
                              ") or rotation (|q| = " + fmt(norm) + ") is not finite and unit");
    }
    auto& motions = world.pool<ecs::Motion>();
    for (size_t i = 0; i < motions.size(); ++i)
        if (!finite3(motions.components()[i].velocity))
            fail(sandbox, "entity " + std::to_string(uint32_t(motions.entities()[i])) + ": velocity is not finite");
}

// The bodies: the surface under each bounded, floating ones afloat (sinking ones may sink)
static void checkBodies(Sandbox& sandbox, const SoakBounds& bounds, SoakReport& report) {
    ecs::World& world = sandbox.world();
    const OceanState* ocean = world.resource<OceanState>();
    const auto* physics = findPhysicsDef(world);
    auto& bodies = world.pool<Body>();
    for (size_t i = 0; i < bodies.size() && ocean && physics; ++i) {
        const Body& body = bodies.components()[i];
        const glm::vec3 p = world.get<ecs::Transform>(bodies.entities()[i]).position;
        const float surface = ocean->water->sample(p.x, p.z).height;
        if (!std::isfinite(surface) || std::fabs(surface) > bounds.surface)
            fail(sandbox, "the water surface under body " + std::to_string(i) + " (" + objectTypeName(world, bodies.entities()[i]) + ") is at " + fmt(surface) +
                              " m, beyond the layers' bound " + fmt(bounds.surface) + " m");
        report.maxSurface = std::max(report.maxSurface, std::fabs(surface));
        if (body.probes.empty()) continue;                                // fixed (a wall, a pillar): it does not float
        if (bodyDensity(world, i) >= physics->water_density) continue;  // meant to sink (a cannonball)
        const float depth = p.y - surface;
        // A body near the water's density dives the deeper the less it floats: falling in from its
        // own size it stops after ρ_b/(ρ − ρ_b) sizes (its entry energy over its net buoyancy).
        const float density = bodyDensity(world, i);
        const float limit = (BODY_EXTENTS + density / (physics->water_density - density)) * bodyExtent(body) + bounds.seaHs;
        if (depth < -limit)
            fail(sandbox, "body " + std::to_string(i) + " (" + objectTypeName(world, bodies.entities()[i]) + ", lighter than water) has sunk: its centre is " +
                              fmt(-depth) + " m under the surface, more than " + fmt(limit) + " m ((2 + ρ_b/(ρ − ρ_b)) extents + Hs)");
        report.minFloatingDepth = std::min(report.minFloatingDepth, depth);
    }
}

void checkSoakInvariants(Sandbox& sandbox, const SoakBounds& bounds, SoakReport& report) {
    checkRipples(sandbox, bounds, report);
    checkOceanMaps(sandbox, bounds, report);
    checkTransforms(sandbox);
    checkBodies(sandbox, bounds, report);
}

// The soak's summary on stdout, and as JSON in options.stats when asked.
static void reportSoak(Sandbox& sandbox, const std::string& scenePath, const SoakOptions& options, const SoakBounds& bounds,
                       const SoakReport& report, double growth, double allowed) {
    std::string cascades;
    for (size_t c = 0; c < report.maxCascadeHeight.size(); ++c)
        cascades += (c ? ", " : "") + fmt(report.maxCascadeHeight[c]) + " (bound " + fmt(bounds.cascadeHeight[c]) + ")";
    std::printf("soak: %s: %llu steps, %.0f s simulated in %.1f s (%.0f steps/s)\n", scenePath.c_str(),
                static_cast<unsigned long long>(report.steps), report.simulatedSeconds, report.wallSeconds,
                double(report.steps) / std::max(report.wallSeconds, 1e-9));
    std::printf("soak: max |h| per cascade %s m; sea Hs %.3g m; max |ripple| %.3g m (%.3g in the warm-up; bound %.3g); max |surface| under "
                "bodies %.3g m (bound %.3g); lowest floating body centre %s\n",
                cascades.c_str(), double(bounds.seaHs), double(report.maxRipple), double(report.warmupRipple), double(bounds.ripple),
                double(report.maxSurface), double(bounds.surface),
                std::isfinite(report.minFloatingDepth) ? (fmt(report.minFloatingDepth) + " m from the surface").c_str() : "(none)");
    std::printf("soak: RSS start %.1f MiB, after warm-up %.1f MiB, end %.1f MiB, max %.1f MiB (growth %.2f MiB, "
                "allowed %.1f%s)\n",
                report.rssStartMiB, report.rssWarmMiB, report.rssEndMiB, report.rssMaxMiB, growth, allowed,
                RSS_MEANINGFUL ? "" : "; not checked in a sanitizer build");
    std::fflush(stdout);

    if (!options.stats.empty()) {
        nlohmann::json j;
        j["scene"] = scenePath;
        j["steps"] = report.steps;
        j["simulated_seconds"] = report.simulatedSeconds;
        j["wall_seconds"] = report.wallSeconds;
        j["steps_per_second"] = double(report.steps) / std::max(report.wallSeconds, 1e-9);
        j["check_every"] = options.checkEvery;
        j["max_cascade_height_m"] = report.maxCascadeHeight;
        j["cascade_height_bound_m"] = bounds.cascadeHeight;
        j["sea_hs_m"] = bounds.seaHs;
        j["max_ripple_m"] = report.maxRipple;
        j["warmup_ripple_m"] = report.warmupRipple;
        j["ripple_bound_m"] = bounds.ripple;
        j["max_surface_m"] = report.maxSurface;
        j["surface_bound_m"] = bounds.surface;
        if (std::isfinite(report.minFloatingDepth)) j["min_floating_depth_m"] = report.minFloatingDepth;
        j["rss_mib"] = {{"start", report.rssStartMiB}, {"warm", report.rssWarmMiB}, {"end", report.rssEndMiB},
                        {"max", report.rssMaxMiB}, {"growth", growth}, {"allowed", allowed}};
        char hash[32];
        std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(sandbox.stateHash()));
        j["state_hash"] = hash;
        writeTextFile(options.stats, j.dump(2) + "\n", "stats");
    }
}

namespace {

// The soak's bounds as they stand: the scene's (its stamps and sea) and those in force. The
// ripple bound holds from the end of the warm-up: a dense swarm's stamps chain through eq. 5's
// base (each fish stamps over the field the others left) to several stamps' height, a damped
// random walk with no a-priori bound. Until then only finiteness is checked; after it, the
// larger of the stamp bound and 4 × the warm-up's maximum, which a blow-up (growth without
// bound) crosses and the stationary walk does not.
struct SoakLimits {
    SoakBounds scene;
    SoakBounds now;

    explicit SoakLimits(Sandbox& sandbox) : scene(soakBounds(sandbox)), now(scene) {
        now.ripple = now.surface = std::numeric_limits<float>::infinity();
    }
    // The ripple bound in force becomes `ripple`; the surface's follows it.
    void holdRipple(float ripple) {
        now.ripple = ripple;
        now.surface = scene.surface - scene.ripple + ripple;
    }
};

// Bodies may start above the water (dropped in): each one's ceiling is the higher of its start
// and the sea, plus its extents.
std::vector<float> bodyCeilings(Sandbox& sandbox, const SoakBounds& scene) {
    auto& bodies = sandbox.world().pool<Body>();
    std::vector<float> ceiling;
    for (size_t i = 0; i < bodies.size(); ++i) {
        const float start = sandbox.world().get<ecs::Transform>(bodies.entities()[i]).position.y;
        ceiling.push_back(std::max(start, 0.0f) + scene.surface + BODY_EXTENTS * bodyExtent(bodies.components()[i]));
    }
    return ceiling;
}

// A body an [[events]] entry spawns stamps too: once one enters, the stamp bound counts it
// (the scene's objects, cannon balls and fish count from the start).
void countEventStamps(Sandbox& sandbox, int& eventsRun, SoakLimits& limits) {
    const auto* script = sandbox.world().resource<ScriptState>();
    if (!script || script->fired == eventsRun) return;
    eventsRun = script->fired;
    const float stamps = std::max(1e-3f, RIPPLE_STAMPS * largestStamp(sandbox.world()));
    if (stamps <= limits.scene.ripple) return;
    limits.scene.surface += stamps - limits.scene.ripple;
    limits.scene.ripple = stamps;
    if (std::isfinite(limits.now.ripple)) limits.holdRipple(std::max(limits.now.ripple, stamps));
}

// No body thrown above its ceiling.
void checkCeilings(Sandbox& sandbox, const std::vector<float>& ceiling) {
    auto& bodies = sandbox.world().pool<Body>();
    for (size_t i = 0; i < bodies.size() && i < ceiling.size(); ++i) {
        const float y = sandbox.world().get<ecs::Transform>(bodies.entities()[i]).position.y;
        if (y > ceiling[i])
            fail(sandbox, "body " + std::to_string(i) + " (" + objectTypeName(sandbox.world(), bodies.entities()[i]) + ") was thrown to y = " +
                              fmt(y) + " m, above its start and the sea (" + fmt(ceiling[i]) + " m)");
    }
}

// The memory at step s; at the warm-up's end the ripple bound comes into force.
void sampleMemory(uint64_t s, uint64_t steps, uint64_t warmup, SoakReport& report, SoakLimits& limits) {
    if (s % RSS_EVERY_STEPS != 0 && s != steps && s != warmup) return;
    const double rss = residentMiB();
    report.rssMaxMiB = std::max(report.rssMaxMiB, rss);
    if (s == warmup) {
        report.rssWarmMiB = rss;
        report.warmupRipple = report.maxRipple;
        limits.holdRipple(std::max(limits.scene.ripple, RIPPLE_STAMPS * report.maxRipple));
    }
    if (s == steps) report.rssEndMiB = rss;
}

// Where the run is: a line that rewrites itself on a terminal, else one line every 10 s.
struct SoakProgress {
    bool terminal = isatty(STDERR_FILENO);
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(), last = start;

    void show(uint64_t s, uint64_t steps) {
        if (std::chrono::steady_clock::now() - last <= (terminal ? std::chrono::seconds(1) : std::chrono::seconds(10))) return;
        last = std::chrono::steady_clock::now();
        std::fprintf(stderr, "%soceanbox: soak step %llu/%llu (%3.0f%%)%s", terminal ? "\r" : "", static_cast<unsigned long long>(s),
                     static_cast<unsigned long long>(steps), 100.0 * double(s) / double(steps), terminal ? "" : "\n");
    }
    double finish() const {
        if (terminal && std::chrono::steady_clock::now() - start > std::chrono::seconds(1)) std::fprintf(stderr, "\n");
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

} // namespace

int soakCommand(const SceneDef& scene, const std::string& scenePath, const SoakOptions& options) {
    if (!(options.seconds > 0.0)) throw InputError("soak: --seconds must be > 0");
    if (options.checkEvery < 1) throw InputError("soak: --check-every must be >= 1");
    if (!options.stats.empty()) checkWritable(options.stats, "stats");

    Sandbox sandbox(scene);  // no platform: simulation phases only
    SoakLimits limits(sandbox);
    const uint64_t steps = uint64_t(std::llround(options.seconds * double(scene.sim.step_hz)));
    const uint64_t warmup =
        std::max<uint64_t>(1, std::min<uint64_t>(uint64_t(WARMUP_SECONDS * double(scene.sim.step_hz)), steps / 10));
    logInfo("soak: %s, %llu steps (%g s simulated), invariants every %d step(s)", scenePath.c_str(),
            static_cast<unsigned long long>(steps), options.seconds, options.checkEvery);
    const std::vector<float> ceiling = bodyCeilings(sandbox, limits.scene);

    SoakReport report;
    report.rssStartMiB = report.rssMaxMiB = residentMiB();
    report.rssWarmMiB = report.rssStartMiB;
    checkSoakInvariants(sandbox, limits.now, report);
    SoakProgress progress;
    int eventsRun = 0;
    for (uint64_t s = 1; s <= steps; ++s) {
        sandbox.step();
        countEventStamps(sandbox, eventsRun, limits);
        if (s % uint64_t(options.checkEvery) == 0 || s == steps) {
            checkSoakInvariants(sandbox, limits.now, report);
            checkCeilings(sandbox, ceiling);
        }
        sampleMemory(s, steps, warmup, report, limits);
        progress.show(s, steps);
    }
    report.wallSeconds = progress.finish();
    report.steps = steps;
    report.simulatedSeconds = sandbox.schedule().simTime();

    const double growth = report.rssEndMiB - report.rssWarmMiB;
    const double allowed = std::max(RSS_GROWTH_MIB, RSS_GROWTH_FRACTION * report.rssWarmMiB);
    reportSoak(sandbox, scenePath, options, limits.now, report, growth, allowed);
    if (RSS_MEANINGFUL && growth > allowed)
        fail(sandbox, "memory grew by " + fmt(growth) + " MiB after the warm-up (" + fmt(report.rssWarmMiB) + " -> " +
                          fmt(report.rssEndMiB) + " MiB), more than " + fmt(allowed) + " MiB");
    return EXIT_OK;
}

} // namespace ob::game
