// `dump gerstner` and `dump surface` contracts: shapes, rest-point layout, unit normals,
// and the surface query at a displaced Gerstner point returning that point's height.
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

namespace {
const std::string WAVE = "--set 'gerstner.waves=[{kx = 0.3, kz = -0.46, amplitude = 0.2, phase = 0.0}]' ";
const std::string CALM = "--set ocean.amplitude=0 ";  // no FFT layer: the Gerstner wave alone
}

TEST_CASE("dump gerstner: [N, N, 6] at rest points (i, j)·E/N, unit normals, particles within a of rest", "[dump]") {
    std::string out = test::tempPath("gerstner.npy");
    auto r = test::runOceanbox("dump gerstner config/scenes/default.toml --set gerstner.count=0 " + WAVE +
                               "--time 1.7 --grid 16 --extent 40 --out " + out);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    NpyArray a = readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{16, 16, 6});
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
            const float* p = &a.data[size_t((j * 16 + i) * 6)];
            float alpha = i * 40.0f / 16, beta = j * 40.0f / 16;
            // One wave: the particle is on a circle of radius a = 0.2 about its rest point.
            float d = std::sqrt((p[0] - alpha) * (p[0] - alpha) + p[1] * p[1] + (p[2] - beta) * (p[2] - beta));
            CHECK(d == Approx(0.2f).margin(1e-4));
            CHECK(std::sqrt(p[3] * p[3] + p[4] * p[4] + p[5] * p[5]) == Approx(1.0f).margin(1e-5));
            CHECK(p[4] > 0.0f);
        }
    CHECK(test::runOceanbox("dump gerstner config/scenes/default.toml --out " + out).exitCode == 2);  // no --grid/--extent
}

TEST_CASE("dump surface: at a displaced Gerstner point the query returns that point's height (to 1 mm)", "[dump]") {
    std::string g = test::tempPath("g.npy");
    REQUIRE(test::runOceanbox("dump gerstner config/scenes/default.toml --set gerstner.count=0 " + WAVE + CALM +
                              "--time 3 --grid 8 --extent 20 --out " + g).exitCode == 0);
    NpyArray rest = readNpy(g);
    std::vector<float> points;
    for (size_t p = 0; p < 64; ++p) {
        points.push_back(rest.data[p * 6 + 0]);
        points.push_back(rest.data[p * 6 + 2]);
    }
    std::string pts = test::tempPath("pts.npy"), out = test::tempPath("surface.npy");
    writeNpy(pts, {64, 2}, points.data());
    auto r = test::runOceanbox("dump surface config/scenes/default.toml --set gerstner.count=0 " + WAVE + CALM +
                               "--time 3 --points " + pts + " --out " + out);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    NpyArray s = readNpy(out);
    REQUIRE(s.shape == std::vector<size_t>{64, 5});
    for (size_t p = 0; p < 64; ++p) {
        CHECK(s.data[p * 5 + 0] == Approx(rest.data[p * 6 + 1]).margin(1e-3));
        CHECK(s.data[p * 5 + 2] == Approx(rest.data[p * 6 + 4]).margin(1e-3));  // ny
    }
    std::string bad = test::tempPath("bad.npy");
    writeNpy(bad, {3, 3}, std::vector<float>(9).data());
    CHECK(test::runOceanbox("dump surface config/scenes/default.toml --points " + bad + " --out " + out).exitCode == 2);
}

TEST_CASE("a Gerstner wave with k·a >= 1 is rejected with exit 2 naming its key path", "[dump]") {
    auto r = test::runOceanbox("dump gerstner config/scenes/default.toml --grid 4 --extent 4 --out " + test::tempPath("x.npy") +
                               " --set 'gerstner.waves=[{kx = 1.0, kz = 0.0, amplitude = 1.5, phase = 0.0}]'");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("gerstner.waves[0]") != std::string::npos);
}
