// Two-way coupling through the ewave ripple layer (docs/references.md#dispersive-ripples): a ship's Kelvin wake rocks a
// floating box beside its track; a floating body's own ripples damp its heave instead of
// driving it into a limit cycle. Figures are given (INFO) to the checks, shown when one fails.
#include "ecs/components.h"
#include "sim/objects.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace ob;

namespace {

struct Motion {
    double heave = 0.0;  // standard deviation of the centre height, m
    double roll = 0.0;   // largest |roll| or |pitch|, deg
};

// A ship along x = 0 towards +z at 6 m/s and a 2 × 1 × 2 m box of density 500 kg/m³ 15 m to
// its side on calm water, no wind (windage would heel the box); the box's motion from the time the wake can reach it (10 s) to 20 s.
Motion boxBesideWake(bool ripples) {
    const std::string text = std::string("[ocean]\namplitude = 0.0\nresolution = 16\nwind_speed = 0.0\n[gerstner]\ncount = 0\n") +
                             "[ripples]\nenabled = " + (ripples ? "true" : "false") +
                             "\nmodel = \"ewave\"\nresolution = 512\ncell_size = 0.25\ncenter = [0.0, 10.0]\n"
                             "[[objects]]\ntype = \"ship\"\nname = \"ship\"\nposition = [0, 0.1, -40]\ndensity = 450\n"
                             "speed = 6.0\nvelocity = [0, 0, 6]\nwaypoints = [[0.0, 400.0]]\n"
                             "[[objects]]\ntype = \"box\"\nname = \"box\"\nposition = [15.0, 0.0, 10.0]\nsize = [2, 1, 2]\n"
                             "density = 500\n";
    game::Sandbox sandbox(game::parseScene(text, "coupling.toml"));
    const ecs::Entity box = game::findObject(sandbox.world(), "box");
    std::vector<double> ys;
    Motion m;
    for (int i = 0; i < 1200; ++i) {
        sandbox.step();
        if (i < 600) continue;
        const auto& t = sandbox.world().get<ecs::Transform>(box);
        ys.push_back(t.position.y);
        const glm::vec2 rp = game::rollPitchDeg(t.rotation);
        m.roll = std::max({m.roll, double(std::abs(rp.x)), double(std::abs(rp.y))});
    }
    double mean = 0.0, var = 0.0;
    for (double y : ys) mean += y / double(ys.size());
    for (double y : ys) var += (y - mean) * (y - mean) / double(ys.size());
    m.heave = std::sqrt(var);
    return m;
}

} // namespace

TEST_CASE("ewave coupling: a ship's wake rocks a floating box 15 m beside its track", "[ewave][coupling][long]") {
    const Motion on = boxBesideWake(true), off = boxBesideWake(false);
    INFO("box 15 m beside a ship at 6 m/s, 10-20 s: heave std " << on.heave << " m with ewave, " << off.heave
                                                                 << " m without; largest roll/pitch " << on.roll << " deg with, "
                                                                 << off.roll << " deg without");
    CHECK(on.heave > 5.0 * off.heave + 2e-3);
    CHECK(on.roll > 5.0 * off.roll + 0.2);
}

TEST_CASE("ewave coupling: a floating sphere's heave decays (no limit cycle), its damping ratio is reported", "[ewave][coupling]") {
    // A sphere of radius 0.5 m at half the density of water, released 0.2 m above its floating
    // height on calm water; its own ripples carry energy away (radiation damping).
    auto run = [](bool ripples) {
        const std::string text = std::string("[ocean]\namplitude = 0.0\nresolution = 16\nwind_speed = 0.0\n[gerstner]\ncount = 0\n") +
                                 "[ripples]\nenabled = " + (ripples ? "true" : "false") +
                                 "\nmodel = \"ewave\"\nresolution = 256\ncell_size = 0.1\n"
                                 "[[objects]]\ntype = \"sphere\"\nname = \"ball\"\nposition = [0, 0.2, 0]\nradius = 0.5\n"
                                 "density = 500\n";
        game::Sandbox sandbox(game::parseScene(text, "heave.toml"));
        const ecs::Entity ball = game::findObject(sandbox.world(), "ball");
        std::vector<double> y;
        for (int i = 0; i < 1200; ++i) {
            sandbox.step();
            y.push_back(sandbox.world().get<ecs::Transform>(ball).position.y);
        }
        return y;
    };
    const std::vector<double> y = run(true), yOff = run(false);
    // Equilibrium: the mean of the last 5 s. Peaks of |y − rest| give the log decrement.
    auto analyse = [](const std::vector<double>& y, double& zeta, double& late, double& early) {
        double rest = 0.0;
        for (size_t i = y.size() - 300; i < y.size(); ++i) rest += y[i] / 300.0;
        std::vector<double> peaks;
        for (size_t i = 1; i + 1 < y.size(); ++i) {
            const double a = y[i] - rest;
            if (a > 0 && a >= y[i - 1] - rest && a > y[i + 1] - rest) peaks.push_back(a);
        }
        zeta = 0.0;
        if (peaks.size() >= 2 && peaks[1] > 0) {
            const double delta = std::log(peaks[0] / peaks[1]);
            zeta = delta / std::sqrt(4 * std::numbers::pi * std::numbers::pi + delta * delta);
        }
        early = 0.0;
        late = 0.0;
        for (size_t i = 0; i < 120; ++i) early = std::max(early, std::abs(y[i] - rest));
        for (size_t i = y.size() - 300; i < y.size(); ++i) late = std::max(late, std::abs(y[i] - rest));
    };
    double zeta, late, early, zetaOff, lateOff, earlyOff;
    analyse(y, zeta, late, early);
    analyse(yOff, zetaOff, lateOff, earlyOff);
    INFO("floating half-density sphere (r 0.5 m): heave damping ratio " << zeta << " with ewave coupling, " << zetaOff
                                                                         << " without (drag only); Hulme (1982) ≈ 0.09; "
                                                                         << "largest |y − rest| in the last 5 s " << late
                                                                         << " m against " << early << " m at the start");
    CHECK(late < 0.1 * early);  // no limit cycle: the motion has died down
}
