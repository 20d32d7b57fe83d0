// The 8-bit outputs are dithered (shaders/common_dither.glsl): in a calm sea under a smooth sky,
// and under water looking down, no row or column of the sky, the water or the deep holds a run
// of identical pixels longer than a dithered output can show by chance, while the same frame
// rounded without the dither shows the long runs (bands) of its gradients.
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "support/test_image.h"
#include "support/test_support.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

using namespace ob;
using test::Image;

namespace {

constexpr glm::ivec2 SIZE{640, 360};

// A flat sea (1 m/s wind, no swell) seen from `eye` toward `target`: from 3 m up toward the
// horizon, the sky's gradient above it and the water's Fresnel gradient below; from under the
// water looking down, the deep's fog. Each a slope of a fraction of a level a pixel.
Image renderCalm(bool dither, const char* view = "horizon", const char* eye = "[0, 3, -300]", const char* target = "[0, 2, 0]") {
    auto platform = platform::createHeadlessPlatform(SIZE);
    const int errorsBefore = gfx::glErrorCount();
    const std::vector<std::string> overrides = {
        "ocean.wind_speed=1", "camera.mode=fixed", std::string("camera.position=") + eye, std::string("camera.target=") + target,
        std::string("render.dither=") + (dither ? "true" : "false")};
    game::Sandbox sandbox(game::loadScene(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/spectrum_only.toml", overrides));
    sandbox.attachPlatform(*platform, false);
    for (int f = 0; f < 3; ++f) sandbox.frame(f / 60.0);
    const std::string path = test::tempPath(std::string("dither_calm_") + view + (dither ? "_on" : "_off") + ".png");
    gfx::writeScreenshot(path, SIZE);
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = test::loadPng(path);
    REQUIRE(img.w == SIZE.x);
    return img;
}

// A channel this far from 0 and 255 is never clamped: the value under it lies within 1.5 levels
// of it and the noise within 1, so the dither can move it either way.
bool unclamped(const unsigned char* p) {
    return std::all_of(p, p + 3, [](unsigned char c) { return c >= 4 && c <= 251; });
}

// The longest run of identical RGB pixels in rows [y0, y1), along a row or down a column
// (clamped pixels break runs): `step` is (1, 0) along rows, (0, 1) down columns.
int longestRun(const Image& img, int y0, int y1, glm::ivec2 step) {
    const glm::ivec2 lineStep(step.y, step.x);  // from one line's start to the next
    const glm::ivec2 lo(0, y0), hi(img.w, y1);
    int longest = 0;
    for (glm::ivec2 start = lo; start.x < hi.x && start.y < hi.y; start += lineStep) {
        int run = 0;
        const unsigned char* before = nullptr;
        for (glm::ivec2 at = start; at.x < hi.x && at.y < hi.y; at += step) {
            const unsigned char* p = &img.rgb[size_t((at.y * img.w + at.x) * 3)];
            const bool repeats = before && unclamped(p) && std::equal(p, p + 3, before);
            run = repeats ? run + 1 : unclamped(p) ? 1 : 0;
            before = unclamped(p) ? p : nullptr;
            longest = std::max(longest, run);
        }
    }
    return longest;
}

// The longer of the longest runs along the rows and down the columns.
int longestRun(const Image& img, int y0, int y1) {
    return std::max(longestRun(img, y0, y1, {1, 0}), longestRun(img, y0, y1, {0, 1}));
}

// The bound, derived. A channel's true value v plus TPDF noise n (density 1 − |n| on (−1, 1))
// rounds to a given level k when n lies in a window of width 1 around k − v: at most the
// window centred on the peak, 3/4 of the density. The three channels take independent noise
// (separate hash words), so a pixel repeats a given colour with probability ≤ (3/4)³ = 27/64,
// whatever the gradient; neighbouring pixels' noises are independent (a hash of the pixel).
// A run of L starting at a given pixel thus has probability ≤ (27/64)^(L−1), and over the
// N ≤ 2·640·360 starts of a frame (along rows and down columns) the chance of any run ≥ L is
// ≤ N·(27/64)^(L−1); ≤ 1e−6 for L − 1 ≥ ln(N / 1e−6) / ln(64/27) = 31.1, so L = 33 is out of
// reach. Rounded without the dither, a gradient of g levels a pixel (its three channels
// together) holds a colour for 1/g pixels: any stretch flatter than 1/33 level a pixel shows
// runs longer than the bound (the check below that the plain frame does proves the scene has
// such stretches, so the test can fail).
constexpr int MAX_DITHERED_RUN = 33;

// The rows of the sky and of the water in the frame above: the horizon lies at mid-height
// (the eye 3 m up, 300 m away); 15 rows either side of it are left out (the far field's edge).
constexpr int SKY_ROWS[2] = {0, 165};
constexpr int WATER_ROWS[2] = {195, 360};

} // namespace

TEST_CASE("dithered 8-bit outputs show no bands in a calm sea's and sky's gradients", "[gl][dither]") {
    const Image plain = renderCalm(false);
    const Image dithered = renderCalm(true);
    const int plainSky = longestRun(plain, SKY_ROWS[0], SKY_ROWS[1]);
    const int plainWater = longestRun(plain, WATER_ROWS[0], WATER_ROWS[1]);
    const int ditheredSky = longestRun(dithered, SKY_ROWS[0], SKY_ROWS[1]);
    const int ditheredWater = longestRun(dithered, WATER_ROWS[0], WATER_ROWS[1]);
    INFO("longest runs: plain sky " << plainSky << ", water " << plainWater << "; dithered sky " << ditheredSky << ", water "
                                    << ditheredWater << "; bound " << MAX_DITHERED_RUN);
    // The gradients are flat enough to band when rounded plainly...
    CHECK(plainSky > MAX_DITHERED_RUN);
    CHECK(plainWater > MAX_DITHERED_RUN);
    // ...and the dither breaks every band.
    CHECK(ditheredSky <= MAX_DITHERED_RUN);
    CHECK(ditheredWater <= MAX_DITHERED_RUN);
    // The dither is noise about the colour, not a shift of it: the mean stays within 1/4 level.
    const glm::vec3 shift = dithered.mean(0, 0, SIZE.x, SIZE.y) - plain.mean(0, 0, SIZE.x, SIZE.y);
    for (int c = 0; c < 3; ++c) CHECK(std::abs(shift[c]) * 255.0f < 0.25f);
}

TEST_CASE("dithered 8-bit outputs show no bands under water looking down", "[gl][dither]") {
    // 5 m under the surface, 45° down: the deep's fog, brighter toward the surface (sky_background.frag).
    const char* eye = "[0, -5, -300]";
    const char* target = "[0, -105, -200]";
    const int plain = longestRun(renderCalm(false, "deep", eye, target), 0, SIZE.y);
    const int dithered = longestRun(renderCalm(true, "deep", eye, target), 0, SIZE.y);
    INFO("longest runs: plain " << plain << ", dithered " << dithered << "; bound " << MAX_DITHERED_RUN);
    CHECK(plain > MAX_DITHERED_RUN);
    CHECK(dithered <= MAX_DITHERED_RUN);
}
