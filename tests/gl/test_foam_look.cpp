// How foam looks (shaders/common_foam.glsl, docs/splash_foam.md §6.4): a foam map written by
// hand over flat water, rendered headless from above. Soft edges (no pixel-to-pixel jump at a
// coverage step beyond what a soft ramp allows), lit by the sun's N·L (darker with the sun low),
// and mip-aware (a distant patch has the near one's mean and less variance).
#include "foam/foam_map.h"
#include "gfx/gl.h"
#include "platform/platform.h"
#include "sim/splash_foam_system.h"
#include "support/test_image.h"
#include "world/sandbox.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>

using namespace ob;
using test::Image;

namespace {

const glm::ivec2 SIZE(320, 180);

Image readFrame() {
    Image img;
    img.w = SIZE.x;
    img.h = SIZE.y;
    std::vector<unsigned char> pixels(size_t(SIZE.x) * size_t(SIZE.y) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glFinish();
    glReadPixels(0, 0, SIZE.x, SIZE.y, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    img.rgb.resize(pixels.size());
    const size_t stride = size_t(SIZE.x) * 3;
    for (int y = 0; y < SIZE.y; ++y) std::memcpy(&img.rgb[stride * size_t(y)], &pixels[stride * size_t(SIZE.y - 1 - y)], stride);
    return img;
}

float luma(const Image& img, int x, int y) {
    const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
    return (0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]) / 255.0f;
}

// Flat, still water (no waves; the wind `windSpeed` m/s toward +x), a foam map of 256² cells `extent` m wide centred on the origin,
// the camera `height` m straight above it (a hair off the vertical for the look-at), the sun at
// `elevation` degrees toward +z; the map's coverage set by `coverage(x, z)` after the first step.
// Drawn at the latest step (render.interpolate off): the frame after a whole step would draw the
// camera where it was before it, while the map written by hand is the step's.
Image renderFoam(float height, float elevation, const std::function<float(float, float)>& coverage, float extent = 25.6f,
                 float windSpeed = 10.0f) {
    const float e = glm::radians(elevation);
    const std::string sun = "[0.0, " + std::to_string(std::sin(e)) + ", " + std::to_string(std::cos(e)) + "]";
    const std::string text = "[ocean]\namplitude = 0.0\nwind_speed = " + std::to_string(windSpeed) + "\n[ripples]\nresolution = 128\ncell_size = 0.2\n"
                             "[foam]\nresolution = 256\nextent_m = " + std::to_string(extent) + "\n[splash]\nenabled = false\n"
                             "[render]\ninterpolate = false\nsun_direction = " + sun + "\n"
                             "[camera]\nmode = \"fixed\"\nposition = [0.0, " + std::to_string(height) + ", -0.001]\n"
                             "target = [0.0, 0.0, 0.0]\nfov_deg = 60.0\n";
    auto platform = platform::createHeadlessPlatform(SIZE);
    const int errors = gfx::glErrorCount();
    game::Sandbox sandbox(game::parseScene(text, "foam_look.toml"));
    sandbox.attachPlatform(*platform, false);
    const double h = sandbox.schedule().stepSeconds();
    sandbox.frame(h);  // the first step makes the map
    // The map is the simulation's; written here by hand, as a tool would (it holds no other state).
    auto* map = const_cast<foam::FoamMap*>(game::foamMap(sandbox.world()));
    REQUIRE(map);
    const int n = map->grid().n;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec2 p = map->grid().origin() + glm::vec2(float(i), float(j)) * map->grid().cell;
            map->coverage()[size_t(j) * size_t(n) + size_t(i)] = coverage(p.x, p.y);
        }
    sandbox.frame(h);  // the same time: no step, the frame drawn again with the map as set
    REQUIRE(gfx::glErrorCount() == errors);
    return readFrame();
}

struct BoxStats {
    double mean = 0.0, variance = 0.0;
};
BoxStats boxStats(const Image& img, int x0, int y0, int x1, int y1) {
    double sum = 0.0, sum2 = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += luma(img, x, y), sum2 += double(luma(img, x, y)) * luma(img, x, y);
    const double count = double((x1 - x0) * (y1 - y0));
    return {sum / count, std::max(0.0, sum2 / count - (sum / count) * (sum / count))};
}

} // namespace

TEST_CASE("foam has soft edges: across a step of the coverage no pixel column jumps from water to white", "[gl][render][foam]") {
    // Coverage 1 for x < 0, 0 beyond, seen from 4 m (1.4 cm a pixel): across the edge the
    // foam's luma, averaged along it (100 rows), climbs over the map's bilinear cell (0.1 m, 7
    // pixels) and the lace's soft ramp: no column more than a fifth of the foam's contrast with
    // the water above its neighbour (a threshold would put most of it in one column). (Within the foam the bubbles are sharp, as bubbles are: the mean along the
    // edge measures the edge, not them.)
    const Image img = renderFoam(4.0f, 50.0f, [](float x, float) { return x < 0.0f ? 1.0f : 0.0f; });
    const Image water = renderFoam(4.0f, 50.0f, [](float, float) { return 0.0f; });
    std::vector<float> profile;
    for (int x = 20; x < 300; ++x) {
        float sum = 0.0f;
        for (int y = 40; y < 140; ++y) sum += luma(img, x, y) - luma(water, x, y);
        profile.push_back(sum / 100.0f);
    }
    float worst = 0.0f, contrast = 0.0f;
    for (size_t k = 0; k + 1 < profile.size(); ++k) {
        worst = std::max(worst, std::abs(profile[k + 1] - profile[k]));
        contrast = std::max(contrast, std::abs(profile[k]));
    }
    INFO("largest step between neighbouring columns " << worst << "; the foam's contrast with the water " << contrast);
    CHECK(contrast > 0.2f);
    CHECK(worst < 0.25f * contrast);
    // Half coverage: the lace's opacity ramps over its pattern rather than cutting it at a
    // threshold, so at least a third of the pixels lie between a fifth and four fifths of the
    // dense foam's excess over the water (a cut leaves them at either end).
    const Image half = renderFoam(4.0f, 50.0f, [](float, float) { return 0.5f; });
    const Image dense = renderFoam(4.0f, 50.0f, [](float, float) { return 1.0f; });
    const double full = boxStats(dense, 60, 40, 260, 140).mean - boxStats(water, 60, 40, 260, 140).mean;
    int between = 0;
    for (int y = 40; y < 140; ++y)
        for (int x = 60; x < 260; ++x) {
            const double excess = (luma(half, x, y) - luma(water, x, y)) / full;
            between += excess > 0.2 && excess < 0.8 ? 1 : 0;
        }
    INFO("pixels between: " << between << " of 20000; dense foam's mean excess " << full);
    CHECK(between > 20000 / 3);
}

TEST_CASE("foam is lit by the sun's N·L: flat foam darkens as the sun sinks, by sin(elevation)", "[gl][render][foam]") {
    // Coverage 1 everywhere, the sun at 70°, 40° and 20°: the foam's luma, mean over the centre
    // (dense foam hides most of the water, which changes little with the sun); a Lambert surface gains sun·sin e (the sun's tint is white above
    // 15°), so the step from 20° to 70° is (sin 70° − sin 20°)/(sin 40° − sin 20°) = 1.99 times the
    // step from 20° to 40° (within 35%: the display transform compresses the bright end).
    double foam[3];
    const float elevations[3] = {20.0f, 40.0f, 70.0f};
    for (int k = 0; k < 3; ++k)
        foam[k] = boxStats(renderFoam(4.0f, elevations[k], [](float, float) { return 1.0f; }), 110, 50, 210, 130).mean;
    INFO("foam luma at 20°, 40°, 70°: " << foam[0] << ", " << foam[1] << ", " << foam[2]);
    CHECK(foam[0] < foam[1]);
    CHECK(foam[1] < foam[2]);
    const double ratio = (foam[2] - foam[0]) / (foam[1] - foam[0]);
    const double lambert = (std::sin(glm::radians(70.0)) - std::sin(glm::radians(20.0))) /
                           (std::sin(glm::radians(40.0)) - std::sin(glm::radians(20.0)));
    INFO("step ratio " << ratio << ", Lambert " << lambert);
    CHECK(ratio == Approx(lambert).epsilon(0.35));
}

TEST_CASE("foam far away averages to its mean: a distant patch keeps the near one's mean, with less variance", "[gl][render][foam]") {
    // Half coverage everywhere, seen from 20 m (7 cm a pixel: the lace resolved, the box over
    // a repeat of it along the wind and two across) and from 80 m (29 cm a pixel, the lace's
    // finer octaves and the bubbles under one): the box's mean luma within 10%, its variance at
    // most half.
    const auto half = [](float, float) { return 0.5f; };
    const BoxStats near = boxStats(renderFoam(20.0f, 50.0f, half, 204.8f), 20, 20, 300, 160);
    const BoxStats far = boxStats(renderFoam(80.0f, 50.0f, half, 204.8f), 20, 20, 300, 160);
    const BoxStats water = boxStats(renderFoam(80.0f, 50.0f, [](float, float) { return 0.0f; }, 204.8f), 20, 20, 300, 160);
    INFO("near mean " << near.mean << " var " << near.variance << "; far mean " << far.mean << " var " << far.variance
                      << "; water " << water.mean);
    CHECK(near.mean > water.mean + 0.1);  // there is foam to average
    CHECK(far.mean == Approx(near.mean).epsilon(0.1));
    CHECK(far.variance < 0.5 * near.variance);
}

TEST_CASE("fresh foam is not paper: dense new foam has bubble holes at every 16×16 block and lets the water through", "[gl][render][foam][fresh]") {
    // Coverage 1 (the map's fresh foam, as the stir or a splash leave it) over a 6 m square seen
    // from 4 m (1.4 cm a pixel): no 16×16 block inside is flat (luma σ under 4 of 255), and the
    // mean over the patch, linear, lies at least 15 % below its solid foam (the brightest
    // percent of its pixels, where the bubbles leave no hole): the holes and the thin foam show
    // the water.
    const Image dense = renderFoam(4.0f, 50.0f, [](float x, float z) { return std::abs(x) < 3.0f && std::abs(z) < 3.0f ? 1.0f : 0.0f; });
    const auto linear = [&](int x, int y) { return std::pow(double(luma(dense, x, y)), 2.2); };
    int flat = 0, blocks = 0;
    std::vector<double> inside;
    for (int by = 50; by + 16 <= 130; by += 16)
        for (int bx = 100; bx + 16 <= 220; bx += 16) {
            const BoxStats s = boxStats(dense, bx, by, bx + 16, by + 16);
            ++blocks;
            flat += std::sqrt(s.variance) * 255.0 < 4.0;
            for (int y = by; y < by + 16; ++y)
                for (int x = bx; x < bx + 16; ++x) inside.push_back(linear(x, y));
        }
    std::sort(inside.begin(), inside.end());
    double mean = 0.0;
    for (double v : inside) mean += v / double(inside.size());
    const double solid = inside[inside.size() * 99 / 100];
    INFO(flat << " of " << blocks << " blocks flat; mean " << mean << " against solid foam " << solid << " (linear)");
    CHECK(flat == 0);
    CHECK(mean <= 0.85 * solid);
}

namespace {

// The lag (px, interpolated) at which the luma's autocorrelation over [x0, x1) × [y0, y1) first
// falls below 1/e, along the rows (dx = 1) or the columns (dy = 1).
double correlationLength(const Image& img, int x0, int y0, int x1, int y1, int dx, int dy) {
    const BoxStats s = boxStats(img, x0, y0, x1, y1);
    double previous = 1.0;
    for (int lag = 1; lag < 100; ++lag) {
        double sum = 0.0;
        int count = 0;
        for (int y = y0; y + lag * dy < y1; ++y)
            for (int x = x0; x + lag * dx < x1; ++x, ++count)
                sum += (luma(img, x, y) - s.mean) * (luma(img, x + lag * dx, y + lag * dy) - s.mean);
        const double r = sum / count / s.variance;
        if (r < std::exp(-1.0)) return lag - 1 + (previous - std::exp(-1.0)) / (previous - r);
        previous = r;
    }
    return 100.0;
}

} // namespace

TEST_CASE("spume at a gale: from force 8 up the foam's lace is drawn out along the wind, not across it", "[gl][render][foam][spume]") {
    // Half coverage everywhere seen from 20 m straight down (12.8 cm a pixel; the wind along the
    // picture's rows): at 25 m/s (force 10, "dense white streaks along the direction of the
    // wind") the luma's correlation length along the wind is the lace's 10 : 1 stretch over the
    // 3 : 1 of 10 m/s (force 5), 10/3 as long (within 25 %: the pixels and the bubbles' holes),
    // and across the wind the same (within 15 %).
    const auto half = [](float, float) { return 0.5f; };
    const Image fresh = renderFoam(20.0f, 50.0f, half, 204.8f, 10.0f);
    const Image gale = renderFoam(20.0f, 50.0f, half, 204.8f, 25.0f);
    const double alongFresh = correlationLength(fresh, 20, 20, 300, 160, 1, 0), acrossFresh = correlationLength(fresh, 20, 20, 300, 160, 0, 1);
    const double alongGale = correlationLength(gale, 20, 20, 300, 160, 1, 0), acrossGale = correlationLength(gale, 20, 20, 300, 160, 0, 1);
    INFO("correlation lengths (px) along / across the wind: 10 m/s " << alongFresh << " / " << acrossFresh << ", 25 m/s " << alongGale
                                                                      << " / " << acrossGale);
    CHECK(alongGale / alongFresh == Approx(10.0 / 3.0).epsilon(0.25));
    CHECK(acrossGale / acrossFresh == Approx(1.0).epsilon(0.15));
}
