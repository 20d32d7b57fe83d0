// Anti-aliasing (render.antialias) and the waterline. Every mode draws without a GL error;
// a black box against the sky has pixels between black and sky along its slanted edges with
// fxaa and msaa4 (coverage blended) and none without; on a sea of long waves a red hull's
// image in the water (reflection over refraction) starts at its waterline in every column,
// the way light does, instead of at the mean water level.
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "support/test_image.h"
#include "support/test_support.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

using namespace ob;
using test::Image;

namespace {

float luma(const Image& img, int x, int y) {
    const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
    return (0.299f * float(p[0]) + 0.587f * float(p[1]) + 0.114f * float(p[2])) / 255.0f;
}

// Red less the mean of green and blue, 0..1 units.
float redness(const Image& img, int x, int y) {
    const unsigned char* p = &img.rgb[size_t((y * img.w + x) * 3)];
    return (float(p[0]) - 0.5f * (float(p[1]) + float(p[2]))) / 255.0f;
}

gfx::CameraView cameraAt(glm::vec3 eye, glm::vec3 target, glm::ivec2 size) {
    gfx::CameraView camera;
    camera.position = eye;
    camera.view = glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
    camera.projection = glm::perspectiveRH_NO(glm::radians(60.0f), float(size.x) / float(size.y), 0.1f, 2000.0f);
    camera.nearM = 0.1f;
    camera.farM = 2000.0f;
    return camera;
}

// One frame of the renderer alone (no scene) into a fresh headless context, read back.
Image renderFrame(const char* name, glm::ivec2 size, const gfx::RenderDef& def, const gfx::CameraView& camera, const gfx::WaterView& water,
                  const std::vector<gfx::ObjectDraw>& objects) {
    auto platform = platform::createHeadlessPlatform(size);
    const int errorsBefore = gfx::glErrorCount();
    gfx::Renderer renderer(def);
    renderer.render(camera, water, objects, 0.0, size);
    const std::string path = test::tempPath(std::string(name) + "_" + enumName(def.antialias) + ".png");
    gfx::writeScreenshot(path, size);
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = test::loadPng(path);
    REQUIRE(img.w == size.x);
    return img;
}

// A thin box of grey `shade` centred at `at`, `side` m across and 0.2 m thick, facing the eye
// and turned 25° about the view axis: its four edges are slanted staircases.
gfx::ObjectDraw slantedBox(glm::vec3 at, float side, float shade) {
    gfx::ObjectDraw box;
    box.mesh = gfx::MeshKind::Box;
    box.color = glm::vec3(shade);
    box.model = glm::translate(glm::mat4(1.0f), at) * glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), glm::vec3(0, 0, 1)) *
                glm::scale(glm::mat4(1.0f), glm::vec3(side, side, 0.2f));
    return box;
}

gfx::RenderDef withAntialias(gfx::Antialias mode) {
    gfx::RenderDef def;
    def.antialias = mode;
    return def;
}

} // namespace

TEST_CASE("the antialias key's modes: auto is msaa4 on a GPU and fxaa on a software rasteriser", "[gl][render][antialias]") {
    CHECK(gfx::antialiasMode(gfx::Antialias::Off, false) == gfx::Antialias::Off);
    CHECK(gfx::antialiasMode(gfx::Antialias::Fxaa, false) == gfx::Antialias::Fxaa);
    CHECK(gfx::antialiasMode(gfx::Antialias::Msaa4, true) == gfx::Antialias::Msaa4);
    CHECK(gfx::antialiasMode(gfx::Antialias::Auto, false) == gfx::Antialias::Msaa4);
    CHECK(gfx::antialiasMode(gfx::Antialias::Auto, true) == gfx::Antialias::Fxaa);
}

TEST_CASE("every antialias mode, at full and half internal size, draws the frame without a GL error", "[gl][render][antialias]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(160, 90);
    const gfx::CameraView camera = cameraAt({0.0f, 4.0f, 0.0f}, {0.0f, 2.0f, -100.0f}, size);
    gfx::ObjectDraw box;
    box.mesh = gfx::MeshKind::Box;
    box.model = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, -25.0f)), glm::vec3(3.0f, 2.5f, 1.0f));
    for (gfx::Antialias mode : {gfx::Antialias::Off, gfx::Antialias::Fxaa, gfx::Antialias::Msaa4, gfx::Antialias::Auto})
        for (float scale : {1.0f, 0.5f}) {
            INFO(enumName(mode) << " at resolution_scale " << scale);
            gfx::RenderDef def = withAntialias(mode);
            def.resolution_scale = scale;
            Image img = renderFrame("modes", size, def, camera, gfx::WaterView{}, {box});
            glm::vec3 sky = img.mean(0, 0, size.x, size.y / 4), sea = img.mean(0, 3 * size.y / 4, size.x, size.y);
            CHECK(glm::length(sky - sea) > 0.05f);  // a whole frame: sky over sea
            CHECK(glm::length(img.mean(75, 48, 85, 52) - sky) > 0.1f);  // and the box on the sea
        }
}

TEST_CASE("a black box's slanted edges against the sky: blended pixels with fxaa and msaa4, none with antialias off", "[gl][render][antialias]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    // The eye looks up at a thin black box turned 25° about the view axis, high in the sky:
    // its four edges are slanted staircases, the sky (bright, smooth) on one side, the box
    // (dark, flat) on the other.
    const gfx::CameraView camera = cameraAt({0.0f, 5.0f, 0.0f}, {0.0f, 15.0f, -30.0f}, size);
    const gfx::ObjectDraw box = slantedBox({0.0f, 15.0f, -30.0f}, 5.0f, 0.0f);

    // From the frame without AA: the box's pixels, its outline (box pixels with a sky
    // neighbour), its brightest pixel and the dimmest sky around it.
    gfx::RenderDef def = withAntialias(gfx::Antialias::Off);
    def.sun_direction = glm::vec3(0.0f, 1.0f, 0.0f);  // overhead: no light or glint on the box's face, none in view
    const Image off = renderFrame("edge", size, def, camera, gfx::WaterView{}, {box});
    auto isBox = [&](int x, int y) { return luma(off, x, y) < 0.3f; };
    int x0 = size.x, x1 = 0, y0 = size.y, y1 = 0, outline = 0;
    for (int y = 1; y < size.y - 1; ++y)
        for (int x = 1; x < size.x - 1; ++x) {
            if (!isBox(x, y)) continue;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            outline += !isBox(x - 1, y) || !isBox(x + 1, y) || !isBox(x, y - 1) || !isBox(x, y + 1);
        }
    REQUIRE(outline > 150);
    REQUIRE((x0 > 3 && x1 < size.x - 4 && y0 > 3 && y1 < size.y - 4));
    x0 -= 3, x1 += 3, y0 -= 3, y1 += 3;
    float boxBrightest = 0.0f, skyDimmest = 1.0f;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            if (isBox(x, y)) boxBrightest = std::max(boxBrightest, luma(off, x, y));
            else skyDimmest = std::min(skyDimmest, luma(off, x, y));
        }
    INFO("outline " << outline << " px; brightest box pixel " << boxBrightest << ", dimmest sky " << skyDimmest);
    REQUIRE(skyDimmest - boxBrightest > 0.3f);  // the box stands against the sky alone

    // Pixels clearly between the two: neither the box's shade nor the sky's.
    const float low = boxBrightest + 0.15f * (skyDimmest - boxBrightest), high = skyDimmest - 0.15f * (skyDimmest - boxBrightest);
    auto blended = [&](const Image& img) {
        int count = 0;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) count += luma(img, x, y) > low && luma(img, x, y) < high;
        return count;
    };
    const int none = blended(off);
    def.antialias = gfx::Antialias::Fxaa;
    const int fxaa = blended(renderFrame("edge", size, def, camera, gfx::WaterView{}, {box}));
    def.antialias = gfx::Antialias::Msaa4;
    const int msaa = blended(renderFrame("edge", size, def, camera, gfx::WaterView{}, {box}));
    INFO("blended pixels: off " << none << ", fxaa " << fxaa << ", msaa4 " << msaa);
    CHECK(none <= outline / 50);
    CHECK(fxaa >= outline / 3);
    CHECK(msaa >= outline / 2);
}

TEST_CASE("fxaa at full size keeps every pixel off the edges as drawn and changes pixels on them", "[gl][render][antialias]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    // A sea with sun glitter under the sky, a dark box on the horizon: smooth areas and edges.
    const gfx::CameraView camera = cameraAt({0.0f, 4.0f, 0.0f}, {0.0f, 2.0f, -30.0f}, size);
    const gfx::ObjectDraw box = slantedBox({0.0f, 3.0f, -30.0f}, 4.0f, 0.05f);
    gfx::WaterView water;
    water.gravity = 9.81f;
    water.gerstner = {glm::vec4(0.5f, 0.2f, 0.15f, 0.0f), glm::vec4(-0.3f, 0.7f, 0.08f, 1.0f)};
    // Undithered: the frame drawn into the framebuffer and into the internal target differs in
    // the last bits of a float; a dithered value spread evenly over the rounding step lands
    // within those of a level's boundary in a few pixels (4 of 56000 here) and flips by a
    // level. The claim here is FXAA's choice of pixels, not the output's noise.
    gfx::RenderDef offDef = withAntialias(gfx::Antialias::Off), fxaaDef = withAntialias(gfx::Antialias::Fxaa);
    offDef.dither = fxaaDef.dither = false;
    const Image off = renderFrame("fxaa_keep", size, offDef, camera, water, {box});
    const Image fxaa = renderFrame("fxaa_keep", size, fxaaDef, camera, water, {box});
    // post_fxaa.frag's test on the luma of a pixel's cross: contrast under
    // max(0.0833, 0.166 · brightest) is off the edges. Pixels well under it (80 %, so the
    // 8-bit luma here cannot put them on the other side) must come out as drawn.
    int kept = 0, offEdges = 0, changedOnEdges = 0;
    for (int y = 1; y < size.y - 1; ++y)
        for (int x = 1; x < size.x - 1; ++x) {
            const float c[5] = {luma(off, x, y), luma(off, x - 1, y), luma(off, x + 1, y), luma(off, x, y - 1), luma(off, x, y + 1)};
            const float hi = *std::max_element(c, c + 5), lo = *std::min_element(c, c + 5);
            const float threshold = std::max(0.0833f, 0.166f * hi);
            const size_t i = size_t((y * size.x + x) * 3);
            const bool same = std::equal(&off.rgb[i], &off.rgb[i] + 3, &fxaa.rgb[i]);
            if (hi - lo < 0.8f * threshold) offEdges++, kept += same;
            else if (hi - lo > 1.2f * threshold) changedOnEdges += !same;
        }
    INFO(kept << " of " << offEdges << " pixels off the edges kept; " << changedOnEdges << " on them changed");
    REQUIRE(offEdges > size.x * size.y / 2);
    CHECK(kept == offEdges);
    CHECK(changedOnEdges > 50);
}

TEST_CASE("on long waves a hull's image in the water starts at its waterline in every column", "[gl][render][antialias]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(480, 270);
    // A red hull 12 m wide, 4 m deep (1.5 m of it below the mean level), broadside to an eye
    // 3 m up and 16.5 m off, in a swell of 16 m crests 0.6 m high running along it: its
    // waterline rises and falls by ±0.6 m (±9 px) along the hull.
    const gfx::CameraView camera = cameraAt({0.0f, 3.0f, 18.0f}, {0.0f, 0.0f, 0.0f}, size);
    gfx::WaterView water;
    const float k = 2.0f * float(M_PI) / 16.0f;
    water.gerstner = {glm::vec4(k, 0.0f, 0.6f, 0.0f)};
    gfx::ObjectDraw hull;
    hull.mesh = gfx::MeshKind::Box;
    hull.color = glm::vec3(0.9f, 0.05f, 0.03f);
    hull.model = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)), glm::vec3(6.0f, 2.0f, 1.5f));
    gfx::RenderDef def = withAntialias(gfx::Antialias::Off);
    def.glitter = 0.0f;           // no sun glint to mistake for the sky
    def.grid_resolution = 256;    // the drawn surface follows the wave to a few mm
    const Image img = renderFrame("waterline", size, def, camera, water, {hull});

    // The waterline on the face (z = 1.5) from the trochoid itself: the rest point α that
    // x = α − a·sin(kα) carries to x (Newton), then h = a·cos(kα).
    auto waterline = [&](float x) {
        double alpha = x;
        for (int i = 0; i < 20; ++i) alpha -= (alpha - 0.6 * std::sin(k * alpha) - x) / (1.0 - 0.6 * k * std::cos(k * alpha));
        return float(0.6 * std::cos(k * alpha));
    };
    // Pixel (column, row top-down) of a world point.
    auto pixel = [&](glm::vec3 p) {
        glm::vec4 clip = camera.projection * camera.view * glm::vec4(p, 1.0f);
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return glm::ivec2(int((ndc.x * 0.5f + 0.5f) * float(size.x)), int((0.5f - ndc.y * 0.5f) * float(size.y)));
    };
    // Along the middle 70 % of the face, one sample a pixel: the rows under the waterline's
    // pixel that show no red (sky or water colour) before the hull's image in the water.
    std::vector<int> gap;
    const int columns = pixel({4.2f, 0.0f, 1.5f}).x - pixel({-4.2f, 0.0f, 1.5f}).x;
    for (int i = 0; i <= columns; ++i) {
        const float x = -4.2f + 8.4f * float(i) / float(columns);
        const glm::ivec2 at = pixel({x, waterline(x), 1.5f});
        int rows = 0;
        while (rows < 20 && redness(img, at.x, at.y + 1 + rows) < 0.1f) ++rows;
        gap.push_back(rows);
        UNSCOPED_INFO("x " << x << " m: waterline " << waterline(x) << " m at pixel " << at.x << ", " << at.y << "; gap " << rows);
    }
    double mean = 0.0, variation = 0.0;
    int worst = 0;
    for (size_t i = 0; i < gap.size(); ++i) {
        mean += gap[i];
        worst = std::max(worst, gap[i]);
        if (i) variation += std::abs(gap[i] - gap[i - 1]);
    }
    mean /= double(gap.size());
    INFO(gap.size() << " columns: mean gap " << mean << " px, largest " << worst << " px, total variation " << variation);
    REQUIRE(gap.size() > 100);
    CHECK(mean < 0.5);
    CHECK(worst <= 2);
}
