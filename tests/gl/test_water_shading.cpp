// The water pass's shading against its reference and the far field (docs/frame.md, the water
// pass): in every scene the shipped shading draws the frame the full-quality program draws
// (every term per pixel, trilinear filtering) within a stated structural similarity and mean
// difference; the far field of the cannon scene shows no regular pattern (no peak in the
// spectra of a band of rows under the horizon); a frame scaled up from half size is sharpened
// off the edges and keeps its colours.
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
#include <complex>
#include <glm/gtc/matrix_transform.hpp>
#include <numeric>
#include <vector>

using namespace ob;
using test::Image;

namespace {

// The scene file `name` after `frames` frames of 1/60 s, read back at `size`.
Image renderScene(const char* name, glm::ivec2 size, int frames, const std::vector<std::string>& overrides, const char* tag) {
    auto platform = platform::createHeadlessPlatform(size);
    const int errorsBefore = gfx::glErrorCount();
    game::Sandbox sandbox(game::loadScene(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/" + name + ".toml", overrides));
    sandbox.attachPlatform(*platform, false);
    for (int f = 0; f < frames; ++f) sandbox.frame(f / 60.0);
    const std::string path = test::tempPath(std::string(name) + "_" + tag + ".png");
    gfx::writeScreenshot(path, size);
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = test::loadPng(path);
    REQUIRE(img.w == size.x);
    return img;
}

// Mean absolute channel difference (0..255 units) over the whole image.
double meanDifference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
    return sum / double(a.rgb.size());
}

float luma(const Image& img, int x, int y) {
    const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
    return (0.299f * float(p[0]) + 0.587f * float(p[1]) + 0.114f * float(p[2])) / 255.0f;
}

// Structural similarity of two frames' luma (Wang et al. 2004): the mean over 8×8 windows, 4 px
// apart, of (2·μa·μb + C1)(2·σab + C2) / ((μa² + μb² + C1)(σa² + σb² + C2)), C1 = 0.01², C2 = 0.03²
// (luma in [0, 1]). 1 for equal frames; it falls with any change of local mean, contrast or structure.
double ssim(const Image& a, const Image& b) {
    constexpr int WINDOW = 8, STRIDE = 4;
    constexpr double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03, N = WINDOW * WINDOW;
    double sum = 0.0;
    int windows = 0;
    for (int y0 = 0; y0 + WINDOW <= a.h; y0 += STRIDE)
        for (int x0 = 0; x0 + WINDOW <= a.w; x0 += STRIDE) {
            double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
            for (int y = y0; y < y0 + WINDOW; ++y)
                for (int x = x0; x < x0 + WINDOW; ++x) {
                    const double la = luma(a, x, y), lb = luma(b, x, y);
                    sa += la, sb += lb, saa += la * la, sbb += lb * lb, sab += la * lb;
                }
            const double ma = sa / N, mb = sb / N;
            const double va = saa / N - ma * ma, vb = sbb / N - mb * mb, cov = sab / N - ma * mb;
            sum += (2 * ma * mb + C1) * (2 * cov + C2) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
            ++windows;
        }
    return sum / windows;
}

// How far one bin of a row's power spectrum stands out of its neighbours: the largest ratio,
// over periods of 4 px to a fifth of the row, of a bin's power to the median of the bins 2 to
// 5 away on either side (the row's mean and linear trend removed, Hann window). About 1 for an
// irregular surface (or the haze's flat colour), far more where one period repeats across the row.
double spectralPeak(const Image& img, int y) {
    const int n = img.w;
    std::vector<double> row(static_cast<size_t>(n), 0.0);
    double mean = 0.0, slope = 0.0, spread = 0.0;
    const double middle = 0.5 * (n - 1);
    for (int x = 0; x < n; ++x) mean += (row[size_t(x)] = luma(img, x, y)) / n;
    for (int x = 0; x < n; ++x) slope += (x - middle) * (row[size_t(x)] - mean), spread += (x - middle) * (x - middle);
    slope /= spread;
    const int top = n / 4 + 6;
    std::vector<double> power(size_t(top), 0.0);
    for (int k = 0; k < top; ++k) {
        std::complex<double> sum = 0.0;
        for (int x = 0; x < n; ++x) {
            const double hann = 0.5 - 0.5 * std::cos(2.0 * M_PI * x / (n - 1));
            sum += (row[size_t(x)] - mean - slope * (x - middle)) * hann * std::polar(1.0, -2.0 * M_PI * k * x / n);
        }
        power[size_t(k)] = std::norm(sum);
    }
    double peak = 0.0;
    for (int k = 5; k <= n / 4; ++k) {
        std::vector<double> around;
        for (int j = k - 5; j <= k + 5; ++j)
            if (std::abs(j - k) > 1) around.push_back(power[size_t(j)]);
        std::nth_element(around.begin(), around.begin() + long(around.size() / 2), around.end());
        peak = std::max(peak, power[size_t(k)] / std::max(around[around.size() / 2], 1e-12));
    }
    return peak;
}

// Rings h = a·cos(2πr / 0.8 m) on a 128² patch of 0.1 m cells round the origin.
constexpr int RING_CELLS = 128;
std::vector<float> rings(float amplitude) {
    std::vector<float> h(size_t(RING_CELLS) * size_t(RING_CELLS));
    for (int j = 0; j < RING_CELLS; ++j)
        for (int i = 0; i < RING_CELLS; ++i) {
            const float r = 0.1f * std::hypot(float(i) - 63.5f, float(j) - 63.5f);
            h[size_t(j * RING_CELLS + i)] = amplitude * std::cos(2.0f * float(M_PI) * r / 0.8f);
        }
    return h;
}

// One frame of `renderer` (a headless context of `size` current): the rings (none if empty)
// seen from `eye` toward (0, 0, 1), read back.
Image drawRings(gfx::Renderer& renderer, glm::ivec2 size, const std::vector<float>& heights, glm::vec3 eye, const char* tag) {
    const int errorsBefore = gfx::glErrorCount();
    gfx::WaterView water;
    water.ripples = heights.empty() ? nullptr : heights.data();
    water.rippleCells = heights.empty() ? 0 : RING_CELLS;
    water.rippleOrigin = glm::vec2(-6.35f);
    water.rippleCellSize = 0.1f;
    gfx::CameraView camera;
    camera.position = eye;
    camera.view = glm::lookAtRH(camera.position, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0, 1, 0));
    camera.projection = glm::perspectiveRH_NO(glm::radians(60.0f), float(size.x) / float(size.y), camera.nearM, camera.farM);
    renderer.render(camera, water, {}, 0.0, size);
    const std::string path = test::tempPath(std::string("rings_") + tag + ".png");
    gfx::writeScreenshot(path, size);
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = test::loadPng(path);
    REQUIRE(img.w == size.x);
    return img;
}

} // namespace

TEST_CASE("the optimised water shading keeps the full-quality frame of every scene: SSIM over 0.985, mean difference under 1 of 255", "[gl][render][water][long]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    // The shipped shading differs from full quality where a software rasteriser filters the
    // ocean's slopes, the detail map and the foam pattern from their nearest mip only.
    for (const char* scene : {"default", "all", "cannon", "drop", "fish", "fish_swarm", "ship", "spectrum_only", "wake"}) {
        const Image fast = renderScene(scene, size, 6, {}, "fast");
        const Image full = renderScene(scene, size, 6, {"render.water_full_quality=true"}, "full");
        INFO(scene << ": SSIM " << ssim(fast, full) << ", mean |fast - full| = " << meanDifference(fast, full) << " of 255");
        CHECK(ssim(fast, full) > 0.985);
        CHECK(meanDifference(fast, full) < 1.0);
    }
    // The bounds see one term wrong: the default scene's frame without its sun glitter (SSIM
    // 0.979), or with the exact Fresnel law for Schlick's (mean difference 2.3).
    const Image full = renderScene("default", size, 6, {"render.water_full_quality=true"}, "full");
    for (const char* defect : {"render.glitter=0", "render.fresnel='exact'"}) {
        const Image broken = renderScene("default", size, 6, {"render.water_full_quality=true", defect}, "defect");
        INFO(defect << ": SSIM " << ssim(broken, full) << ", mean difference " << meanDifference(broken, full));
        CHECK((ssim(broken, full) < 0.985 || meanDifference(broken, full) > 1.0));
    }
}

TEST_CASE("the ripple slope from one lookup equals the four-lookup central difference: rings seen from above", "[gl][render][water]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    // Seen from 4 m up and 6 m back: the ripple slope is the only relief in the frame.
    auto render = [&](const std::vector<float>& heights, bool fullQuality, const char* tag) {
        auto platform = platform::createHeadlessPlatform(size);
        gfx::RenderDef def;
        def.water_full_quality = fullQuality;
        gfx::Renderer renderer(def);
        return drawRings(renderer, size, heights, glm::vec3(0.0f, 4.0f, -6.0f), tag);
    };
    const std::vector<float> heights = rings(0.01f), weaker = rings(0.009f);
    const Image fast = render(heights, false, "fast"), full = render(heights, true, "full");
    const Image weakerFull = render(weaker, true, "weaker");
    INFO("mean |fast - full| = " << meanDifference(fast, full) << ", |rings 10 % weaker - full| = " << meanDifference(weakerFull, full) << " of 255");
    CHECK(meanDifference(fast, full) < 0.05);
    // The bound sees a slope 10 % off.
    CHECK(meanDifference(weakerFull, full) > 4 * 0.05);
}

TEST_CASE("the water program follows the frame: after other configurations a renderer draws each frame as a fresh one does", "[gl][render][water]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(160, 90);
    // The water program is compiled per configuration (gfx::WaterVariant): eye above or below,
    // ripples or none. A renderer that drew the others must switch, byte for byte.
    struct Frame {
        bool ripples;
        glm::vec3 eye;
        const char* tag;
    };
    const std::vector<float> heights = rings(0.01f);
    const Frame frames[] = {{true, {0.0f, 4.0f, -6.0f}, "above"}, {true, {0.0f, -3.0f, -6.0f}, "below"}, {false, {0.0f, 4.0f, -6.0f}, "flat"}};
    auto platform = platform::createHeadlessPlatform(size);
    gfx::Renderer reused{gfx::RenderDef{}};
    std::vector<Image> seen;
    for (const Frame& f : frames) seen.push_back(drawRings(reused, size, f.ripples ? heights : std::vector<float>{}, f.eye, f.tag));
    for (size_t i = 0; i < std::size(frames); ++i) {
        gfx::Renderer fresh{gfx::RenderDef{}};
        const Image expected = drawRings(fresh, size, frames[i].ripples ? heights : std::vector<float>{}, frames[i].eye, "fresh");
        INFO(frames[i].tag << ": mean |reused - fresh| = " << meanDifference(seen[i], expected));
        CHECK(meanDifference(seen[i], expected) == 0.0);
    }
    // The three configurations draw three different pictures.
    CHECK(meanDifference(seen[0], seen[1]) > 1.0);
    CHECK(meanDifference(seen[0], seen[2]) > 0.1);
}

TEST_CASE("the far field of the cannon scene shows no regular pattern: no spectral peak under the horizon", "[gl][render][water]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    // The cannon scene's camera: its single long Gerstner wave, sampled by a grid sparser than
    // half its length near the horizon, and the 60 m FFT tile would repeat there.
    const game::SceneDef scene = game::loadScene(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/cannon.toml");
    const glm::vec3 view = scene.camera.target - scene.camera.position;
    const float pitch = std::atan2(-view.y, std::hypot(view.x, view.z));
    const float focal = 0.5f * float(size.y) / std::tan(glm::radians(0.5f * scene.camera.fov_deg));
    const int horizon = int(std::lround(0.5f * float(size.y) - focal * std::tan(pitch)));  // row from the top
    REQUIRE(horizon > 10);

    auto bandPeak = [&](const Image& img) {
        double peak = 0.0;
        for (int y = horizon; y <= horizon + 8; ++y) peak = std::max(peak, spectralPeak(img, y));
        return peak;
    };
    // The cannon stands behind the camera: in view, its hard edges cross these rows, and their
    // broad spectrum raised every bin's local median enough to hide any pattern (the rows read
    // 1.0-1.3 with the fade or without it, once fxaa had softened the edges; 8 to 22 unsoftened,
    // as a GPU's msaa4 or antialias off leave them). Dithered, as shipped: a smooth row's plain
    // 8-bit rounding steps at a regular interval, a pattern of its own (up to 30 undithered).
    // The dither's noise is white: each bin's power over the median of its 8 neighbours
    // exceeds t with probability about e^(-t·ln 2), so the largest of 9 × 76 bins stays under
    // 30 but for odds of 1e-6 (15.5 measured); the tile's repeat reads over 300.
    const std::vector<std::string> common = {"objects[0].position=[40.0, 4.0, 20.0]"};
    auto with = [&](std::vector<std::string> settings) {
        settings.insert(settings.end(), common.begin(), common.end());
        return settings;
    };
    const Image faded = renderScene("cannon", size, 2, with({}), "faded");
    const Image unfaded = renderScene("cannon", size, 2, with({"render.far_fade=false"}), "unfaded");
    INFO("horizon row " << horizon << ": largest peak / median, faded " << bandPeak(faded) << ", unfaded " << bandPeak(unfaded));
    CHECK(bandPeak(faded) < 30.0);
    CHECK(bandPeak(unfaded) > 100.0);  // the test sees the pattern where it is
}

TEST_CASE("a frame scaled up from half size is sharpened off the edges and keeps its colours", "[gl][render][water]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    // Undithered and without the sun's glitter, whose path saturates the lower half of the
    // default view toward its sun: the sea's own texture is the detail measured.
    const Image sharp = renderScene("default", size, 2, {"render.resolution_scale=0.5", "render.antialias=fxaa", "render.dither=false", "render.glitter=0"}, "sharp");
    const Image soft = renderScene("default", size, 2, {"render.resolution_scale=0.5", "render.antialias=fxaa", "render.upscale_sharpness=0", "render.dither=false", "render.glitter=0"}, "soft");
    // Detail: the mean luma step between horizontal neighbours over the sea (lower half).
    auto detail = [&](const Image& img) {
        double sum = 0.0;
        for (int y = size.y / 2; y < size.y; ++y)
            for (int x = 1; x < size.x; ++x) sum += std::abs(luma(img, x, y) - luma(img, x - 1, y));
        return sum / double((size.y - size.y / 2) * (size.x - 1));
    };
    INFO("neighbour step: sharpened " << detail(sharp) << ", bilinear " << detail(soft));
    CHECK(detail(sharp) > 1.2 * detail(soft));
    for (int band = 0; band < 6; ++band) {
        const int y0 = band * size.y / 6, y1 = (band + 1) * size.y / 6;
        INFO("rows " << y0 << "-" << y1);
        CHECK(glm::length(sharp.mean(0, y0, size.x, y1) - soft.mean(0, y0, size.x, y1)) < 0.01f);
    }
    // At full size the key changes nothing.
    const Image full = renderScene("default", size, 2, {"render.antialias=fxaa"}, "fullsize");
    const Image fullSoft = renderScene("default", size, 2, {"render.antialias=fxaa", "render.upscale_sharpness=0"}, "fullsize_soft");
    CHECK(full.maxDifference(fullSoft, 0, size.y) == 0);
}
