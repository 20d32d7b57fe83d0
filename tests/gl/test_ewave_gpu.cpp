// GPU ewave field (EWaveGpu: shaders/ocean_fft.comp + shaders/ewave_step.comp) against its CPU
// twin EWaveField (double, FFTW) on random fields with every boundary, damping and sources,
// against theory (one Fourier mode: cos(K·X)·cos ωt, ω² = g·k + (σ/ρ)·k³; docs/references.md#dispersive-ripples), and end
// to end through ripples.backend = "gpu". Timings under a hidden tag.
#include "gfx/gl.h"
#include "interaction/ewave/ewave_field.h"
#include "interaction/ewave/ewave_solver.h"
#include "interaction/ewave/gpu/ewave_gpu.h"
#include "interaction/gpu/attach_gpu.h"
#include "interaction/ripple_def.h"
#include "interaction/ripple_patch.h"
#include "platform/platform.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

using namespace ob;
using namespace ob::interaction;

namespace {

std::unique_ptr<platform::Platform> glContext() {
    gfx::requestDebugOutput(true);
    return platform::createHeadlessPlatform({16, 16});
}

// max |a − b| / max |b|.
double relativeError(std::span<const double> a, std::span<const double> b) {
    REQUIRE(a.size() == b.size());
    double diff = 0.0, peak = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        diff = std::max(diff, std::abs(a[i] - b[i]));
        peak = std::max(peak, std::abs(b[i]));
    }
    REQUIRE(peak > 0.0);
    return diff / peak;
}

// White noise h in [−A, A] and v in [−A·ω₁, A·ω₁], ω₁ = ω at a quarter of the grid's Nyquist
// wavenumber (so neither field's rounding swamps the other's: see EWaveGpu).
void randomState(EWaveField& f, unsigned seed, double amplitude) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double w1 = f.omega(std::numbers::pi / (4.0 * f.cellSize()));
    for (double& x : f.editHeight()) x = amplitude * unit(rng);
    for (double& x : f.editVelocity()) x = amplitude * w1 * unit(rng);
    f.syncHeight();
}

// A source list that changes from step to step (positions off the cell centres, both signs,
// one clipped by the field's edge).
struct Source {
    float gx, gz, radius, accel;
};
std::vector<Source> sourcesAt(int step, int n) {
    const float s = float(step), m = float(n);
    return {{0.3f * m + 0.37f * s * 0.1f, 0.4f * m, 3.5f, 4.0f},
            {0.7f * m, 0.25f * m + 0.21f * s * 0.1f, 6.0f, -9.81f},
            {1.2f, 0.5f * m, 5.0f, 20.0f}};
}

} // namespace

// Tolerance. Float rounds at u = 2^-24 ≈ 6e-8; a radix-2 transform of N² points has 2·log2 N
// butterfly stages, and a step makes two transforms (forward, back) and one rounded rotation,
// so a step's error relative to the field is about 4·log2(N)·u ≈ 2.4e-7·log2 N, ≈ 1e-6·log2 N
// with a safety factor of 4. Over many modes of random sign the steps' errors add as a random
// walk: √100 · 1e-6·log2 N = 1e-5·log2 N after 100 steps (6e-5 at N = 64, 8e-5 at 256; the
// worst case, all adding up, is ten times that). Checked relative to each field's max.
// Measured on llvmpipe: 0.4–2.3e-5.
TEST_CASE("GPU ewave steps equal EWaveField::step within 1e-5 log2 N of the field's max over 100 steps on random "
          "64x64 and 256x256 fields, periodic, fixed and absorbing, with sources",
          "[ewave_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    struct Case {
        int n;
        RippleBoundary boundary;
        float decayTime, viscosity;
        bool sources;
    };
    const Case cases[] = {
        {64, RippleBoundary::Periodic, 0.0f, 0.0f, false}, {64, RippleBoundary::Fixed, 3.0f, 1e-3f, true},
        {64, RippleBoundary::Absorbing, 0.0f, 0.0f, true}, {256, RippleBoundary::Periodic, 3.0f, 1e-3f, true},
        {256, RippleBoundary::Fixed, 0.0f, 0.0f, false},   {256, RippleBoundary::Absorbing, 3.0f, 1e-3f, true},
    };
    const float dt = 1.0f / 60.0f, cell = 0.25f;
    unsigned seed = 7;
    for (const Case& c : cases) {
        EWaveField cpu(c.n, c.n, cell, c.boundary, 16);
        cpu.setDamping(c.decayTime, c.viscosity);
        randomState(cpu, ++seed, 0.1);
        // The GPU path as RipplePatch drives it: sources added to a CPU mirror, uploaded, stepped, read back.
        EWaveField mirror(c.n, c.n, cell, c.boundary, 16);
        mirror.setDamping(c.decayTime, c.viscosity);
        std::copy(cpu.heightState().begin(), cpu.heightState().end(), mirror.editHeight().begin());
        std::copy(cpu.velocityState().begin(), cpu.velocityState().end(), mirror.editVelocity().begin());
        EWaveGpu gpu(mirror);
        double worstH = 0.0, worstV = 0.0;
        for (int k = 1; k <= 100; ++k) {
            if (c.sources) {
                for (const Source& s : sourcesAt(k, c.n)) {
                    cpu.addSource(s.gx, s.gz, s.radius, s.accel, dt);
                    mirror.addSource(s.gx, s.gz, s.radius, s.accel, dt);
                }
                gpu.upload(mirror);
            }
            cpu.step(dt);
            gpu.step(dt);
            gpu.download(mirror.editHeight(), mirror.editVelocity());
            if (k % 10 == 0) {
                worstH = std::max(worstH, relativeError(mirror.heightState(), cpu.heightState()));
                worstV = std::max(worstV, relativeError(mirror.velocityState(), cpu.velocityState()));
            }
        }
        const double tolerance = 1e-5 * std::log2(double(c.n));
        INFO(c.n << "² boundary " << int(c.boundary) << " tau " << c.decayTime << " nu " << c.viscosity << " sources "
                 << c.sources << ": max |gpu - cpu| / max |cpu|: h " << worstH << ", v " << worstV << " (tolerance "
                 << tolerance << ")");
        CHECK(worstH <= tolerance);
        CHECK(worstV <= tolerance);
        // The field is still alive, so the comparison means something.
        double peak = 0.0;
        for (double h : cpu.heightState()) peak = std::max(peak, std::abs(h));
        CHECK(peak > 1e-3);
        if (c.boundary == RippleBoundary::Fixed)
            for (int i = 0; i < c.n; ++i) REQUIRE(mirror.heightAt(i, 0) == 0.0f);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

// Theory: one mode h = A·cos(K·X), v = 0 on the torus stays that mode and evolves as
// A·cos(K·X)·cos(ωt)·e^{−(1/τ + 2νk²)t}, ω² = g·k + (σ/ρ)·k³. The double CPU field holds 1e-4
// of A; the float one cannot promise that over 200 steps (3.3 s, up to 14 periods): a float
// transform pair with rounded twiddles multiplies one mode by a gain 1 + ε, |ε| up to about
// 4·log2(N)·u ≈ 1.4e-6 at N = 64 (u = 2^-24), and for a single mode that error is the same
// every step, so it grows linearly: 200 · 1.4e-6 ≈ 3e-4 of A. The rounded rotation adds
// ~u per step (1e-5). Measured: 1e-6 to 1.1e-4. A wrong ω (no surface tension: 2 % at the
// capillary case, radians of phase) fails by far.
TEST_CASE("GPU ewave: a single Fourier mode cos(K.X) on a periodic field evolves as cos(K.X) cos(wt) to 3e-4 of its "
          "amplitude over 200 steps",
          "[ewave_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    struct Case {
        int mx, mz;       // mode numbers along x and z
        float cell;       // m
        float decayTime;  // s
        float viscosity;  // m²/s
    };
    const Case cases[] = {
        {1, 0, 0.25f, 0.0f, 0.0f}, {3, 5, 0.25f, 0.0f, 0.0f}, {32, 32, 0.25f, 0.0f, 0.0f},  // up to the Nyquist corner
        {7, -2, 0.01f, 0.0f, 0.0f},                                                         // capillary range
        {4, 9, 0.1f, 2.0f, 2e-3f},                                                          // damping on
    };
    const int n = 64, steps = 200;
    const float dt = 1.0f / 60.0f;
    const double amplitude = 0.05;
    for (const Case& c : cases) {
        EWaveField field(n, n, c.cell, RippleBoundary::Periodic);
        field.setDamping(c.decayTime, c.viscosity);
        const double l = double(n) * c.cell;
        const double kx = 2.0 * std::numbers::pi * c.mx / l, kz = 2.0 * std::numbers::pi * c.mz / l;
        const double k = std::hypot(kx, kz), omega = std::sqrt(9.81 * k + 0.074 / 1025.0 * k * k * k);  // a default [environment]
        auto mode = [&](int x, int z) { return std::cos(kx * x * c.cell + kz * z * c.cell); };
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) field.editHeight()[size_t(z * n + x)] = amplitude * mode(x, z);
        EWaveGpu gpu(field);
        double worst = 0.0;
        for (int s = 1; s <= steps; ++s) {
            gpu.step(dt);
            if (s % 50 != 0) continue;
            gpu.download(field.editHeight(), field.editVelocity());
            const double t = double(s) * double(dt);
            const double rate = (c.decayTime > 0.0f ? 1.0 / c.decayTime : 0.0) + 2.0 * c.viscosity * k * k;
            const double expected = amplitude * std::cos(omega * t) * std::exp(-rate * t);
            for (int z = 0; z < n; ++z)
                for (int x = 0; x < n; ++x)
                    worst = std::max(worst, std::abs(field.heightState()[size_t(z * n + x)] - expected * mode(x, z)));
        }
        INFO("mode (" << c.mx << ", " << c.mz << "), cell " << c.cell << " m, omega " << omega << " rad/s: max error "
                      << worst / amplitude << " of the amplitude");
        CHECK(worst <= 3e-4 * amplitude);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("RipplePatch on the ewave GPU twin: written state (fieldEdited) and scrolling (centerOn) reach the GPU as on the CPU",
          "[ewave_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    RippleDef def;
    def.model = interaction::rippleModel("ewave");
    def.resolution = 64;
    def.cell_size = 0.25f;
    def.boundary = interaction::RippleBoundary::Absorbing;
    def.sponge_width = 8;
    RipplePatch cpu(def), gpu(def);
    REQUIRE(attachGpu(gpu));
    REQUIRE(gpu.onGpu());
    REQUIRE_FALSE(cpu.onGpu());
    const float dt = 1.0f / 60.0f;
    for (int k = 0; k < 40; ++k) {
        if (k == 5) {
            // A smooth bump written straight into h, as splash landings do.
            for (RipplePatch* p : {&cpu, &gpu}) {
                auto h = p->solverAs<interaction::EWaveSolver>()->field().editHeight();
                for (int z = 0; z < 64; ++z)
                    for (int x = 0; x < 64; ++x)
                        h[size_t(z * 64 + x)] += 0.1 * std::exp(-((x - 30) * (x - 30) + (z - 25) * (z - 25)) / 20.0);
                p->solverAs<interaction::EWaveSolver>()->field().syncHeight();
                p->solverAs<interaction::EWaveSolver>()->fieldEdited();
            }
        }
        if (k == 20 || k == 30)
            for (RipplePatch* p : {&cpu, &gpu}) p->centerOn(glm::vec2(0.25f * float(k / 10), -0.5f * float(k / 10)));  // whole cells
        cpu.step(dt);
        gpu.step(dt);
    }
    REQUIRE(gpu.origin() == cpu.origin());
    const double error = relativeError(gpu.solverAs<interaction::EWaveSolver>()->field().heightState(), cpu.solverAs<interaction::EWaveSolver>()->field().heightState());
    INFO("max |gpu - cpu| / max |cpu| " << error);
    CHECK(error <= 1e-5 * std::log2(64.0));
    // The height copy the renderer and queries read is the GPU's h.
    CHECK(gpu.height()[size_t(25 * 64 + 30)] == float(gpu.solverAs<interaction::EWaveSolver>()->field().heightState()[size_t(25 * 64 + 30)]));
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("a ball dropped into the ewave field rings out on the GPU as on the CPU (ripples.backend = gpu)", "[ewave_gpu]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({32, 32});
    const int errors = gfx::glErrorCount();
    auto run = [&](const char* backend) {
        game::SceneDef scene = game::parseScene(
            "[ocean]\namplitude = 0.0\n[ripples]\nmodel = \"ewave\"\nresolution = 128\ncell_size = 0.05\nbackend = \"" +
                std::string(backend) +
                "\"\n[[objects]]\ntype = \"sphere\"\nposition = [0.3, 1.0, -0.2]\nradius = 0.2\ndensity = 600.0\n",
            "drop.toml");
        game::Sandbox sandbox(scene);
        sandbox.attachPlatform(*platform, false);
        auto* patch = sandbox.world().resource<interaction::RipplePatch>();
        REQUIRE(patch->solverAs<interaction::EWaveSolver>());
        REQUIRE(patch->onGpu() == (std::string(backend) == "gpu"));
        for (int i = 0; i < 90; ++i) sandbox.step();
        auto h = patch->solverAs<interaction::EWaveSolver>()->field().heightState();
        return std::vector<double>(h.begin(), h.end());
    };
    const std::vector<double> cpu = run("cpu"), gpu = run("gpu");
    double peak = 0.0;
    for (double h : cpu) peak = std::max(peak, std::abs(h));
    const double error = relativeError(gpu, cpu);
    INFO("peak " << peak << " m, max |gpu - cpu| / peak " << error);
    CHECK(peak > 1e-3);
    // The sphere's motion feeds back (buoyancy reads the ripples), so the float field's rounding
    // (above: ~1e-5 over 100 steps) also moves the ball a little; 1e-4 of the peak allows that
    // and still tells a wrong source, upload or step apart. Measured 4e-6.
    CHECK(error <= 1e-4);
    CHECK(gfx::glErrorCount() == errors);
}

// The horizontal surface velocity on the GPU backend: derived on the CPU from the read-back state
// (EWaveField::deriveHorizontal), the same per-mode law as the CPU step's, so on a periodic field
// (no boundary between the two) the GPU's equals the CPU twin's within the state's tolerance
// above, 1e-5·log2 N of its max, after 40 steps with a bump written in and a scroll. With the
// absorbing border the CPU step derives u before its sponge and scales it by the sponge factors,
// the GPU path after it: inside the level's interior (2·sponge from the edge, where the
// composite reads it) the band's change reaches in only through the Riesz kernel's 1/r² tail:
// within 2e-4 of the max (measured on llvmpipe: 1.6e-5 periodic, 4.7e-5 absorbing; the
// wavenumbers 1e-6 and 2e-5 apart).
TEST_CASE("RipplePatch on the ewave GPU twin: the horizontal velocity and velocityWavenumber equal the CPU twin's",
          "[ewave_gpu][ewave_velocity]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    for (const auto boundary : {interaction::RippleBoundary::Periodic, interaction::RippleBoundary::Absorbing}) {
        RippleDef def;
        def.model = interaction::rippleModel("ewave");
        def.resolution = 64;
        def.cell_size = 0.25f;
        def.boundary = boundary;
        def.sponge_width = 8;
        RipplePatch cpu(def), gpu(def);
        REQUIRE(attachGpu(gpu));
        const float dt = 1.0f / 60.0f;
        for (int k = 0; k < 40; ++k) {
            if (k == 0) {
                for (RipplePatch* p : {&cpu, &gpu}) {
                    auto* s = p->solverAs<interaction::EWaveSolver>();
                    auto h = s->field().editHeight();
                    for (int z = 0; z < 64; ++z)
                        for (int x = 0; x < 64; ++x)
                            h[size_t(z * 64 + x)] += 0.1 * std::exp(-((x - 30) * (x - 30) + (z - 25) * (z - 25)) / 20.0);
                    s->field().syncHeight();
                    s->fieldEdited();
                }
            }
            if (k == 20)
                for (RipplePatch* p : {&cpu, &gpu}) p->centerOn(glm::vec2(0.5f, -0.75f));  // whole cells
            cpu.step(dt);
            gpu.step(dt);
        }
        const int margin = boundary == interaction::RippleBoundary::Absorbing ? 2 * def.sponge_width : 0;
        double diff = 0.0, peak = 0.0;
        for (int z = margin; z < 64 - margin; ++z)
            for (int x = margin; x < 64 - margin; ++x) {
                const glm::vec2 world = cpu.origin() + glm::vec2(x, z) * def.cell_size;
                const glm::vec2 a = gpu.horizontalVelocityAt(world), b = cpu.horizontalVelocityAt(world);
                diff = std::max(diff, double(glm::length(a - b)));
                peak = std::max(peak, double(glm::length(b)));
            }
        const double tolerance = boundary == interaction::RippleBoundary::Periodic ? 1e-5 * std::log2(64.0) : 2e-4;
        INFO((boundary == interaction::RippleBoundary::Periodic ? "periodic" : "absorbing, interior")
             << ": max |u_gpu − u_cpu| / max |u_cpu| " << diff / peak << " (peak " << peak << " m/s, tolerance "
             << tolerance << "); velocityWavenumber gpu " << gpu.velocityWavenumber() << ", cpu "
             << cpu.velocityWavenumber() << " rad/m");
        CHECK(peak > 1e-3);
        CHECK(diff <= tolerance * peak);
        CHECK(gpu.velocityWavenumber() == Approx(cpu.velocityWavenumber()).epsilon(boundary == interaction::RippleBoundary::Periodic ? 1e-4 : 1e-3));
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("ewave levels on the GPU twins (ripples.backend = gpu, levels = 3) step as their CPU twins", "[ewave_gpu][levels]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    RippleDef def;
    def.model = interaction::rippleModel("ewave");
    def.resolution = 32;
    def.cell_size = 0.25f;
    def.levels = 3;
    def.boundary = interaction::RippleBoundary::Absorbing;
    def.sponge_width = 4;
    RipplePatch cpu(def), gpu(def);
    REQUIRE(attachGpu(gpu));
    for (int L = 1; L < 3; ++L) {
        CHECK(gpu.levels()->solver(L).onGpu());
        CHECK_FALSE(cpu.levels()->solver(L).onGpu());
    }
    interaction::BoundingSphere sphere;
    sphere.radius = 0.6f;
    sphere.direction = interaction::SphereDirection::Down;
    const float dt = 1.0f / 60.0f;
    for (int k = 0; k < 40; ++k) {  // a sphere crossing level 0 into level 1, the patch following it
        const glm::vec2 at(-2.0f + 4.0f * float(k) * dt, 0.3f);
        for (RipplePatch* p : {&cpu, &gpu}) {
            interaction::SphereContact contact;
            p->centerOn(at);
            p->stampSphere(sphere, contact, glm::vec3(at.x, 0.0f, at.y), glm::vec3(4.0f, 0.0f, 0.0f), 1000.0f, 0.0f);
            p->step(dt);
        }
    }
    // Every level against its CPU twin, with the tolerance of the one-grid twin above.
    for (int L = 1; L < 3; ++L) {
        INFO("level " << L);
        const std::span<const double> c = dynamic_cast<const interaction::EWaveSolver&>(cpu.levels()->solver(L)).field().heightState();
        const std::span<const double> g = dynamic_cast<const interaction::EWaveSolver&>(gpu.levels()->solver(L)).field().heightState();
        double peak = 0.0;
        for (double h : c) peak = std::max(peak, std::abs(h));
        CHECK(peak > 0.0);  // the sphere's source reached the level
        const double error = relativeError(g, c);
        INFO("max |gpu - cpu| / max |cpu| " << error);
        CHECK(error <= 1e-5 * std::log2(32.0));
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}
