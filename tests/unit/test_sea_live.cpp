// A live change of the sea (ocean/sea_fade.h, changeSea, the `set` path): the spectrum keeps
// its random phases, the surface cross-fades within the derived per-step bound, floating
// bodies ride the change, and the set path refuses what it cannot apply.
#include "core/error.h"
#include "ocean/gerstner.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/sea_fade.h"
#include "ocean/spectrum.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/script.h"
#include "world/sea_presets.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <complex>
#include <string>
#include <vector>

using namespace ob;

namespace {

constexpr double DT = 1.0 / 60.0;

// Old and new sea of the fade tests: a breeze turning into a storm from another heading.
ocean::OceanDef breeze() {
    ocean::OceanDef d;
    d.resolution = 64;
    d.cascades = 2;
    d.wind_speed = 8.0f;
    d.wind_direction = {1.0f, 0.0f};
    d.choppiness = 1.0f;
    d.seed = 11;
    return d;
}
ocean::OceanDef storm() {
    ocean::OceanDef d = breeze();
    d.wind_speed = 20.0f;
    d.wind_direction = {0.6f, 0.8f};
    d.choppiness = 1.8f;
    return d;
}
ocean::GerstnerDef swell(float scale) {
    ocean::GerstnerDef g;
    g.count = 8;
    g.seed = 7;
    g.amplitude_scale = scale;
    return g;
}

// One sea on its own: maps, Gerstner waves and the query over both.
struct Sea {
    ocean::OceanFftCpu fft;
    std::vector<ocean::GerstnerWave> waves;
    water::CompositeWater water;
    Sea(const ocean::OceanDef& def, const ocean::GerstnerDef& g)
        : fft(def, 1), waves(ocean::resolveWaves(g, def)), water(waves, def.gravity, &fft) {}
    void at(double t) {
        fft.update(t);
        water.update(t);
    }
    const float* height(int c) const { return fft.channel(c, ocean::OceanChannel::Height); }
};

std::string sceneError(const std::string& text) {
    try {
        game::parseScene(text, "bad.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("a live wind change keeps the spectrum's random phases: after the fade h0 is the new wind's freshly seeded h0",
          "[sea_live]") {
    // eq. 4: h0 = ξ·sqrt(Ph/2) with Ph ≥ 0 real, so arg h0 = arg ξ for any wind; the fade
    // moves amplitudes only, and ends on the new sea's own draw of the same ξ.
    ocean::OceanFftCpu live(breeze(), 1);
    const ocean::SeaFade fade(live, {}, storm(), swell(1.0f), 1.0);
    for (int c = 0; c < 2; ++c) {
        const ocean::CascadeSpectrum fresh(storm(), c);
        const ocean::CascadeSpectrum old(breeze(), c);
        fade.apply(live, 2.0);  // halfway: the phase of every mode is its ξ's
        int compared = 0;
        for (int m = -31; m < 32; ++m)
            for (int n = -31; n < 32; ++n) {
                const std::complex<float> a = old.h0(n, m), b = fresh.h0(n, m), mid = live.spectrum(c).h0(n, m);
                if (std::abs(a) > 1e-12f && std::abs(b) > 1e-12f) {
                    ++compared;
                    CHECK(std::abs(std::arg(a * std::conj(b))) < 1e-4f);    // same ξ behind both winds
                    CHECK(std::abs(std::arg(mid * std::conj(b))) < 1e-4f);  // the blend keeps it
                }
            }
        CHECK(compared > 100);
        fade.apply(live, 3.0);  // over: the new sea bit for bit
        for (int m = -31; m < 32; ++m)
            for (int n = -31; n < 32; ++n) REQUIRE(live.spectrum(c).h0(n, m) == fresh.h0(n, m));
    }
    CHECK(live.lambda() == -storm().choppiness);
}

TEST_CASE("a live wind change in a running world ends on the sea of a world that started with that wind", "[sea_live]") {
    const char* text = R"(
[ocean]
resolution = 64
cascades = 2
wind_speed = 8.0
seed = 5
[gerstner]
count = 8
seed = 3
[ripples]
enabled = false
[[events]]
at = 0.5
action = "set"
key = "ocean.wind_speed"
value = 20.0
[[events]]
at = 0.5
action = "set"
key = "ocean.wind_direction_deg"
value = 53.0
)";
    game::Sandbox live(game::parseScene(text, "live.toml"));
    while (live.schedule().simTime() < 3.0 - 1e-9) live.step();
    game::SceneDef started = game::parseScene(text, "started.toml");
    started.events.clear();
    started.ocean.wind_speed = 20.0f;
    started.ocean.wind_direction = live.scene().ocean.wind_direction;
    CHECK(started.ocean.wind_direction.y == Approx(std::sin(53.0 * 3.14159265358979 / 180.0)).margin(1e-6));
    game::Sandbox fresh(started);
    while (fresh.schedule().simTime() < 3.0 - 1e-9) fresh.step();
    const auto& a = *live.world().resource<game::OceanState>();
    const auto& b = *fresh.world().resource<game::OceanState>();
    for (int c = 0; c < 2; ++c)
        for (int m = -31; m < 32; ++m)
            for (int n = -31; n < 32; ++n) REQUIRE(a.cpu->spectrum(c).h0(n, m) == b.cpu->spectrum(c).h0(n, m));
    // Same h0, same λ, same time: the same maps and the same swell.
    const size_t count = 64 * 64;
    for (int c = 0; c < 2; ++c)
        for (size_t i = 0; i < count; ++i)
            REQUIRE(a.cpu->channel(c, ocean::OceanChannel::Height)[i] == b.cpu->channel(c, ocean::OceanChannel::Height)[i]);
    REQUIRE(a.waves.size() == b.waves.size());
    for (size_t i = 0; i < a.waves.size(); ++i) CHECK(a.waves[i].amplitude == b.waves[i].amplitude);
}

TEST_CASE("during a live wind change no step moves the surface more than the cross-fade allows, which an instant switch breaks",
          "[sea_live]") {
    // The bound (sea_fade.h), with s the fade's weight (smoothstep over T = 2 s, slope ≤ 1.5/T):
    //   h(t+Δt) − h(t) = (1−s₁)·Δh_old + s₁·Δh_new + (s₁ − s₀)·(h_new − h_old)(t)
    //   |Δh| ≤ max(|Δh_old|, |Δh_new|) + 1.5·Δt/T·|h_new − h_old|          (every rest point)
    // checked at every texel of both cascades' height maps (the FFT layer: linear, exact up to
    // float rounding) and, over all probe points together, at world points through the
    // composite query (Gerstner + FFT, displacement inverted: what bodies feel).
    const double start = 1.0, T = ocean::SEA_FADE_SECONDS;
    struct Result {
        double mapsWorst = 0.0;      // max over steps and texels of |Δh_live| − bound(texel)
        double worldLive = 0.0;      // max |ΔH_live| over steps and probe points
        double worldNatural = 0.0;   // max over steps and points of max(|ΔH_old|, |ΔH_new|)
        double worldGap = 0.0;       // max |H_new − H_old|
    };
    const auto run = [&](double duration) {
        Sea old(breeze(), swell(1.0f)), neu(storm(), swell(1.5f)), live(breeze(), swell(1.0f));
        std::vector<glm::vec2> probes;
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) probes.push_back({-70.0f + 20.0f * float(i), -70.0f + 20.0f * float(j)});
        std::unique_ptr<ocean::SeaFade> fade;
        Result r;
        const size_t count = 64 * 64;
        std::vector<float> prevOld, prevNew, prevLive;
        std::vector<float> hOld(probes.size()), hNew(probes.size()), hLive(probes.size());
        std::vector<float> pOld, pNew, pLive;
        for (int k = 0; k * DT < start + T + 0.5; ++k) {
            const double t = k * DT;
            if (!fade && t >= start - 1e-9) fade = std::make_unique<ocean::SeaFade>(live.fft, live.waves, storm(), swell(1.5f), t, duration);
            if (fade) {
                fade->apply(live.fft, t);
                live.waves = fade->waves(t);
                live.water.setWaves(live.waves, 9.81f);
            }
            old.at(t);
            neu.at(t);
            live.at(t);
            for (size_t p = 0; p < probes.size(); ++p) {
                hOld[p] = old.water.sample(probes[p].x, probes[p].y).height;
                hNew[p] = neu.water.sample(probes[p].x, probes[p].y).height;
                hLive[p] = live.water.sample(probes[p].x, probes[p].y).height;
            }
            std::vector<float> mapsOld, mapsNew, mapsLive;
            for (int c = 0; c < 2; ++c) {
                mapsOld.insert(mapsOld.end(), old.height(c), old.height(c) + count);
                mapsNew.insert(mapsNew.end(), neu.height(c), neu.height(c) + count);
                mapsLive.insert(mapsLive.end(), live.height(c), live.height(c) + count);
            }
            if (!prevLive.empty()) {
                if (fade) CHECK(std::abs(fade->weight(t) - fade->weight(t - DT)) <= 1.5 * DT / T + 1e-12 + (duration <= 0.0 ? 1.0 : 0.0));
                for (size_t i = 0; i < mapsLive.size(); ++i) {
                    const double natural = std::max(std::abs(mapsOld[i] - prevOld[i]), std::abs(mapsNew[i] - prevNew[i]));
                    const double bound = natural + 1.5 * DT / T * std::abs(prevNew[i] - prevOld[i]);
                    r.mapsWorst = std::max(r.mapsWorst, std::abs(double(mapsLive[i]) - prevLive[i]) - bound);
                }
                for (size_t p = 0; p < probes.size(); ++p) {
                    r.worldLive = std::max(r.worldLive, double(std::abs(hLive[p] - pLive[p])));
                    r.worldNatural = std::max(r.worldNatural, double(std::max(std::abs(hOld[p] - pOld[p]), std::abs(hNew[p] - pNew[p]))));
                    r.worldGap = std::max(r.worldGap, double(std::abs(hNew[p] - hOld[p])));
                }
            }
            prevOld = mapsOld;
            prevNew = mapsNew;
            prevLive = mapsLive;
            pOld = hOld;
            pNew = hNew;
            pLive = hLive;
        }
        return r;
    };
    const Result fade = run(T);
    const double worldBound = fade.worldNatural + 1.5 * DT / T * fade.worldGap;
    INFO("maps: worst |Δh| − bound " << fade.mapsWorst << " m; world: max |ΔH| " << fade.worldLive << " m, bound " << worldBound
                                     << " m (natural " << fade.worldNatural << " m + 1.5·Δt/T · " << fade.worldGap << " m)");
    CHECK(fade.mapsWorst <= 1e-4);  // float rounding of the maps (heights of metres)
    CHECK(fade.worldLive <= worldBound);
    CHECK(fade.worldGap > 1.0);  // the two seas differ by metres: the bound has something to hold
    // The same change as an instant switch breaks both bounds by far.
    const Result instant = run(0.0);
    INFO("instant: maps " << instant.mapsWorst << " m over; world max |ΔH| " << instant.worldLive << " m");
    CHECK(instant.mapsWorst > 0.1);
    CHECK(instant.worldLive > 2.0 * worldBound);
}

TEST_CASE("floating bodies stay afloat through a calm to storm change: partly submerged, near the surface", "[sea_live]") {
    // Balls of 1 m radius at 400 and 600 kg/m³, a crate and a barrel, through the storm preset
    // (3 → 20 m/s, swell ×5) and 6 s of storm. Afloat: every body partly under water (submerged
    // fraction in (0, 1)) at every step but for moments of at most 0.1 s (a ball thrown off a
    // steep crest, measured 0.05 s; a denser or smaller body is washed over for longer in this
    // storm, as real ones are: a 0.6 m ball at 700 kg/m³ was under for 0.6 s), and its centre
    // within 2 m of the surface throughout (measured 1.37 m).
    const char* text = R"(
[ocean]
resolution = 64
wind_speed = 3.0
choppiness = 0.5
[gerstner]
count = 8
amplitude_scale = 0.3
[ripples]
resolution = 64
cell_size = 0.5
[[objects]]
type = "sphere"
name = "light ball"
position = [0.0, 0.5, 0.0]
radius = 1.0
density = 400.0
[[objects]]
type = "sphere"
name = "heavy ball"
position = [6.0, 0.5, 2.0]
radius = 1.0
density = 600.0
[[objects]]
type = "box"
name = "crate"
position = [-6.0, 0.5, 3.0]
size = [1.6, 1.0, 1.6]
density = 350.0
[[objects]]
type = "box"
name = "barrel"
position = [2.0, 0.5, -7.0]
size = [0.8, 1.2, 0.8]
density = 500.0
)";
    game::SceneDef scene = game::parseScene(text, "afloat.toml");
    // The storm preset at 2 s, as the Sea panel's button asks for it.
    for (const game::PresetSet& s : game::presetSets(game::SeaPreset::Storm)) {
        game::EventDef e;
        e.at = 2.0f;
        e.action = game::EventAction::Set;
        e.key = s.key;
        e.value = s.value;
        scene.events.push_back(e);
    }
    game::Sandbox sandbox(scene);
    ecs::World& world = sandbox.world();
    const auto& ocean = *world.resource<game::OceanState>();
    float farthest = 0.0f;
    int steps = 0, outside = 0, longest = 0;
    std::vector<int> run;  // per body: consecutive steps outside (0, 1) so far
    while (sandbox.schedule().simTime() < 10.0 - 1e-9) {
        sandbox.step();
        if (sandbox.schedule().simTime() < 1.0) continue;  // dropped in: let them settle
        ++steps;
        auto& bodies = world.pool<game::Body>();
        run.resize(bodies.size(), 0);
        for (size_t i = 0; i < bodies.size(); ++i) {
            const game::Body& body = bodies.components()[i];
            const glm::vec3 p = world.get<ecs::Transform>(bodies.entities()[i]).position;
            const float surface = ocean.water->sample(p.x, p.z).height;
            const bool partly = body.submergedFraction > 0.0f && body.submergedFraction < 1.0f;
            run[i] = partly ? 0 : run[i] + 1;
            outside += partly ? 0 : 1;
            longest = std::max(longest, run[i]);
            farthest = std::max(farthest, std::abs(p.y - surface));
        }
    }
    INFO(outside << " body-steps of " << 4 * steps << " outside (0, 1), the longest " << longest << " steps; centre at most "
                 << farthest << " m from the surface");
    CHECK(steps > 500);
    CHECK(sandbox.scene().ocean.wind_speed == 20.0f);
    CHECK(longest <= 6);                      // 0.1 s at 60 Hz
    CHECK(outside <= 4 * steps / 100);        // under 1 % of the time
    for (int r : run) CHECK(r == 0);          // all afloat at the end
    CHECK(farthest < 2.0f);
}

TEST_CASE("live set path: sea keys are live, bad keys and values are refused with the file, line and key", "[sea_live][config]") {
    const std::string head = "[[events]]\nat = 1\naction = \"set\"\n";
    CHECK(sceneError(head + "key = \"ocean.wind_speed\"\nvalue = 12\n").empty());
    CHECK(sceneError(head + "key = \"ocean.wind_direction_deg\"\nvalue = 135\n").empty());
    CHECK(sceneError(head + "key = \"gerstner.amplitude_scale\"\nvalue = 2\n").empty());
    CHECK(sceneError(head + "key = \"render.time_of_day\"\nvalue = 19.5\n").empty());
    CHECK(sceneError(head + "key = \"ripples.decay_time\"\nvalue = 5\n").empty());
    CHECK(sceneError(head + "key = \"ocean.gale\"\nvalue = 1\n") ==
          "bad.toml:4:7: events[0].key: 'ocean.gale' is not a number or switch of the scene");
    CHECK(sceneError(head + "key = \"ocean.resolution\"\nvalue = 128\n").rfind(
              "bad.toml:4:7: events[0].key: 'ocean.resolution' is read once at start; live keys: ", 0) == 0);
    CHECK(sceneError(head + "key = \"ocean.wind_speed\"\nvalue = 99\n") ==
          "bad.toml:5:9: events[0].value: value out of the key's range: in [0, 60] (ocean.wind_speed)");
    CHECK(sceneError(head + "key = \"ocean.choppiness\"\nvalue = -1\n").rfind("bad.toml:5:9: events[0].value: ", 0) == 0);
    CHECK(sceneError(head + "key = \"ocean.wind_direction_deg\"\nvalue = 5000\n").rfind("bad.toml:5:9: events[0].value: ", 0) == 0);
    CHECK(sceneError(head + "key = \"gerstner.count\"\nvalue = 2.5\n").rfind("bad.toml:5:9: events[0].value: this key takes an integer", 0) == 0);
}

TEST_CASE("requestLiveSet queues a change for the next step and logs it with that step's start time", "[sea_live]") {
    game::Sandbox sandbox(game::parseScene("[ocean]\nresolution = 32\n[ripples]\nenabled = false\n", "request.toml"));
    ecs::World& world = sandbox.world();
    for (int k = 0; k < 10; ++k) sandbox.step();
    CHECK(game::requestLiveSet(world, "ocean.resolution", 64).rfind("key: 'ocean.resolution' is read once", 0) == 0);
    CHECK(game::requestLiveSet(world, "ocean.wind_speed", 70).rfind("value: ", 0) == 0);
    CHECK(game::requestLiveSet(world, "ocean.wind_speed", 14).empty());
    CHECK(game::requestPreset(world, game::SeaPreset::Calm).empty());
    CHECK(sandbox.scene().ocean.wind_speed == 10.0f);  // not before the next step
    const double stepStart = sandbox.schedule().simTime();
    sandbox.step();
    const auto& changes = world.resource<game::ScriptState>()->liveChanges;
    REQUIRE(changes.size() == 1 + game::presetSets(game::SeaPreset::Calm).size());
    CHECK(changes[0].key == "ocean.wind_speed");
    CHECK(changes[0].value == 14.0f);
    CHECK(changes[0].time == stepStart);
    CHECK(sandbox.scene().ocean.wind_speed == 3.0f);  // the preset came after, and won
    CHECK(world.resource<game::OceanState>()->def.wind_speed == 3.0f);
    CHECK(world.resource<game::ScriptState>()->requested.empty());
}

TEST_CASE("the same live changes, as requests or as timeline events at their logged times, give the same world", "[sea_live]") {
    const std::string text = "[ocean]\nresolution = 32\n[gerstner]\ncount = 4\n[ripples]\nresolution = 32\n"
                             "[[objects]]\ntype = \"sphere\"\nposition = [0.0, 0.3, 0.0]\nradius = 0.5\ndensity = 500.0\n";
    game::Sandbox requested(game::parseScene(text, "a.toml"));
    for (int k = 0; k < 200; ++k) {
        if (k == 30) game::requestLiveSet(requested.world(), "ocean.wind_speed", 18.0f);
        if (k == 31) game::requestLiveSet(requested.world(), "ocean.wind_direction_deg", 90.0f);
        if (k == 90) game::requestPreset(requested.world(), game::SeaPreset::Calm);
        requested.step();
    }
    game::SceneDef replay = game::parseScene(text, "b.toml");
    for (const game::LiveChange& c : requested.world().resource<game::ScriptState>()->liveChanges) {
        game::EventDef e;
        e.at = float(c.time);
        e.action = game::EventAction::Set;
        e.key = c.key;
        e.value = c.value;
        replay.events.push_back(e);
    }
    game::Sandbox replayed(replay);
    for (int k = 0; k < 200; ++k) replayed.step();
    CHECK(replayed.stateHash() == requested.stateHash());
}

// Not a test (hidden, no timing asserts): what a live change costs the step that applies it and
// each step of its fade, for docs/benchmarks.md. `tests_unit "[.sea_cost]"`.
TEST_CASE("cost of a live change of the sea: the fade's build and its per-step blend", "[.sea_cost]") {
    ocean::OceanDef def;  // the showcase scene's sea: 256², 2 cascades
    def.cascades = 2;
    def.wind_speed = 16.0f;
    ocean::OceanDef next = def;
    next.wind_speed = 20.0f;
    next.amplitude = 0.002f;
    ocean::GerstnerDef g;
    g.count = 8;
    ocean::OceanFftCpu fft(def);
    const std::vector<ocean::GerstnerWave> waves = ocean::resolveWaves(g, def);
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    std::vector<double> generate, build, apply, update;
    for (int r = 0; r < 9; ++r) {
        const auto t0 = Clock::now();
        std::vector<ocean::GerstnerWave> target = ocean::resolveWaves(g, next);
        const auto t1 = Clock::now();
        ocean::SeaFade fade(fft, waves, next, std::move(target), 0.0);
        const auto t2 = Clock::now();
        fade.apply(fft, 1.0);
        const auto t3 = Clock::now();
        fft.update(1.0);
        const auto t4 = Clock::now();
        generate.push_back(ms(t0, t1));
        build.push_back(ms(t1, t2));
        apply.push_back(ms(t2, t3));
        update.push_back(ms(t3, t4));
    }
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    // A measurement, not a property: printed, never asserted.
    std::printf("median ms of 9: swell drawn %.3f, fade built (2 new spectra) %.3f, blend per step %.3f, the maps' update %.3f\n",
                median(generate), median(build), median(apply), median(update));
}
