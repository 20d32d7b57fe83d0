// The generated DU/DV + foam detail map: tileable, zero-mean distortion in [−1, 1], foam in [0, 1];
// the foam pattern baked from it is its formula at every texel.
#include "gfx/detail_map.h"
#include "gfx/renderer.h"
#include "platform/platform.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

TEST_CASE("the detail map tiles seamlessly and its DU/DV has zero mean and unit peak", "[render]") {
    const int n = 64;
    std::vector<glm::vec4> map = gfx::makeDetailMap(n, 7);
    REQUIRE(map.size() == size_t(n * n));
    auto at = [&](int x, int y) { return map[size_t(((y + n) % n) * n + (x + n) % n)]; };
    double mean[2] = {0, 0}, peak = 0;
    double inner = 0, seam = 0;  // largest neighbour step inside the map and across its edges
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            glm::vec4 t = at(x, y);
            mean[0] += t.x / (n * n);
            mean[1] += t.y / (n * n);
            peak = std::max({peak, double(std::abs(t.x)), double(std::abs(t.y))});
            CHECK(t.z >= 0.0f);
            CHECK(t.z <= 1.0f);
            double step = std::max(std::abs(at(x + 1, y).x - t.x), std::abs(at(x, y + 1).y - t.y));
            (x == n - 1 || y == n - 1 ? seam : inner) = std::max(x == n - 1 || y == n - 1 ? seam : inner, step);
        }
    CHECK(std::abs(mean[0]) < 1e-3);  // a gradient of a periodic field integrates to zero
    CHECK(std::abs(mean[1]) < 1e-3);
    CHECK(peak == Approx(1.0));
    CHECK(seam <= inner * 1.05);  // crossing the edge is no bigger a step than inside: it tiles
    // Different seeds, different maps.
    CHECK(gfx::makeDetailMap(n, 8)[5].x != map[5].x);
}

namespace {

// Level 0 of an RGBA8 texture as bytes.
std::vector<unsigned char> readRgba8(const gfx::Texture& texture, int size) {
    std::vector<unsigned char> texels(size_t(size) * size_t(size) * 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(texels.size()), texels.data());
    return texels;
}

} // namespace

TEST_CASE("the baked foam pattern is three octaves of the detail map's streaks, sharpened, at every texel", "[gl][render][foam]") {
    // The pattern (shaders/common_detail.glsl, foamPattern) written out here: at foam-tile
    // coordinate f, ridges = 0.5 b(f) + 0.3 b(8f/3 + 0.37) + 0.2 b(22f/3 + 0.71) of the detail
    // map's streak channel b (bilinear, repeating), pattern = clamp((ridges^0.4 − 0.47) / 0.41);
    // the baked map spans three foam tiles: texel (i, j) is f = 3 (i + ½, j + ½) / size.
    auto platform = platform::createHeadlessPlatform({16, 16});
    gfx::Renderer renderer{gfx::RenderDef{}};
    GLint detailSize = 0, patternSize = 0;
    glGetTextureLevelParameteriv(renderer.detailMap().id(), 0, GL_TEXTURE_WIDTH, &detailSize);
    glGetTextureLevelParameteriv(renderer.foamPatternMap().id(), 0, GL_TEXTURE_WIDTH, &patternSize);
    REQUIRE(detailSize > 0);
    REQUIRE(patternSize > 0);
    const std::vector<unsigned char> detail = readRgba8(renderer.detailMap(), detailSize);
    const std::vector<unsigned char> baked = readRgba8(renderer.foamPatternMap(), patternSize);
    const auto texel = [&](int x, int y, int c) {
        x = ((x % detailSize) + detailSize) % detailSize, y = ((y % detailSize) + detailSize) % detailSize;
        return double(detail[size_t((y * detailSize + x) * 4 + c)]) / 255.0;
    };
    const auto bilinear = [&](double u, double v, int c) {
        const double x = u * detailSize - 0.5, y = v * detailSize - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        return (1 - fy) * ((1 - fx) * texel(x0, y0, c) + fx * texel(x0 + 1, y0, c)) +
               fy * ((1 - fx) * texel(x0, y0 + 1, c) + fx * texel(x0 + 1, y0 + 1, c));
    };
    double worst = 0.0, sum = 0.0, warpWorst = 0.0;
    for (int j = 0; j < patternSize; j += 3)
        for (int i = 0; i < patternSize; i += 3) {
            const double fu = 3.0 * (i + 0.5) / patternSize, fv = 3.0 * (j + 0.5) / patternSize;
            const double ridges = 0.5 * bilinear(fu, fv, 2) + 0.3 * bilinear(fu * 8 / 3 + 0.37, fv * 8 / 3 + 0.37, 2) +
                                  0.2 * bilinear(fu * 22 / 3 + 0.71, fv * 22 / 3 + 0.71, 2);
            const double pattern = std::clamp((std::pow(ridges, 0.4) - 0.47) / (0.88 - 0.47), 0.0, 1.0);
            const unsigned char* t = &baked[size_t((j * patternSize + i) * 4)];
            const double error = std::abs(t[2] / 255.0 - pattern);
            worst = std::max(worst, error);
            sum += error;
            // The warp: the detail map's (du, dv) at f, stored the same way.
            warpWorst = std::max({warpWorst, std::abs(t[0] / 255.0 - bilinear(fu, fv, 0)), std::abs(t[1] / 255.0 - bilinear(fu, fv, 1))});
        }
    const double mean = sum / double(((patternSize + 2) / 3) * ((patternSize + 2) / 3));
    INFO("baked pattern against the formula: worst " << worst * 255 << "/255, mean " << mean * 255 << "/255; warp worst " << warpWorst * 255 << "/255");
    CHECK(worst < 4.0 / 255);
    CHECK(mean < 0.5 / 255);
    CHECK(warpWorst < 1.5 / 255);
}
