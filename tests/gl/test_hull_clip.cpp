// No sea inside a hull (shaders/common_hull_clip.glsl, docs/frame.md#hulls): a hull box whose
// deck lies under the sea, seen from above, shows its deck where the water would cover it, and
// the frame elsewhere is the frame without the clip; seen low over the deck, the water stays
// where the view ray leaves the hull under the sea (no sky opens there). Which pixels are the
// hull's is found here by casting each pixel's ray on the two planes (the sea's and the
// deck's), not from the shader.
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "support/test_image.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <vector>
#include <glm/gtc/matrix_transform.hpp>

using namespace ob;
using test::Image;

namespace {

constexpr glm::ivec2 SIZE{240, 160};
const glm::vec3 HALF{1.5f, 0.75f, 5.0f};  // the ship's hull box, m
const glm::vec3 CENTRE{0.0f, -1.2f, 0.0f};  // its deck 0.45 m under the calm sea (y = 0)

gfx::CameraView camera(glm::vec3 eye, glm::vec3 target) {
    gfx::CameraView c;
    c.position = eye;
    c.view = glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
    c.projection = glm::perspectiveRH_NO(glm::radians(50.0f), float(SIZE.x) / float(SIZE.y), 0.1f, 2000.0f);
    c.nearM = 0.1f;
    c.farM = 2000.0f;
    return c;
}

// The frame with or without the clip; `depth`: its window depth too, rows top-down (drawn
// straight into the framebuffer: antialias off).
Image render(bool clip, const gfx::CameraView& cam, std::vector<float>* depth = nullptr, gfx::Antialias antialias = gfx::Antialias::Off) {
    auto platform = platform::createHeadlessPlatform(SIZE);
    const int errorsBefore = gfx::glErrorCount();
    gfx::RenderDef def;
    def.antialias = antialias;
    def.dither = false;
    def.hull_clip = clip;
    gfx::Renderer renderer(def);
    gfx::ObjectDraw hull;
    hull.mesh = gfx::MeshKind::Box;
    hull.model = glm::translate(glm::mat4(1.0f), CENTRE) * glm::scale(glm::mat4(1.0f), HALF);  // the unit box is [−1, 1]³
    hull.color = glm::vec3(0.8f, 0.1f, 0.1f);
    gfx::WaterView water;
    water.hulls.push_back({glm::scale(glm::mat4(1.0f), 1.0f / HALF) * glm::translate(glm::mat4(1.0f), -CENTRE), nullptr});
    renderer.render(cam, water, {hull}, 0.0, SIZE);
    const std::string path = test::tempPath(clip ? "hull_clip_on.png" : "hull_clip_off.png");
    gfx::writeScreenshot(path, SIZE);
    if (depth) {
        std::vector<float> rows(size_t(SIZE.x) * size_t(SIZE.y));
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, SIZE.x, SIZE.y, GL_DEPTH_COMPONENT, GL_FLOAT, rows.data());
        depth->resize(rows.size());
        for (int y = 0; y < SIZE.y; ++y)
            std::copy_n(&rows[size_t(SIZE.y - 1 - y) * size_t(SIZE.x)], SIZE.x, &(*depth)[size_t(y) * size_t(SIZE.x)]);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = test::loadPng(path);
    REQUIRE(img.w == SIZE.x);
    return img;
}

// Where pixel (x, y) (rows top-down) meets the plane y = h, in world (x, z); false if it does
// not; `distance`: how far from the eye (m).
bool hitPlane(const gfx::CameraView& cam, int x, int y, float h, glm::vec2& out, float* distance = nullptr) {
    const glm::mat4 inv = glm::inverse(cam.projection * cam.view);
    const glm::vec2 ndc((float(x) + 0.5f) / float(SIZE.x) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(SIZE.y) * 2.0f);
    glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - cam.position);
    if (std::abs(dir.y) < 1e-6f) return false;
    const float t = (h - cam.position.y) / dir.y;
    if (t <= 0.0f) return false;
    const glm::vec3 p = cam.position + t * dir;
    out = {p.x, p.z};
    if (distance) *distance = t;
    return true;
}

// Signed distance (m) of (x, z) from the hull's outline on the plane: < 0 inside.
float outline(glm::vec2 p) {
    const glm::vec2 q = glm::abs(p - glm::vec2(CENTRE.x, CENTRE.z)) - glm::vec2(HALF.x, HALF.z);
    return glm::length(glm::max(q, glm::vec2(0.0f))) + std::min(std::max(q.x, q.y), 0.0f);
}

glm::ivec3 pixel(const Image& img, int x, int y) {
    const size_t i = size_t(y * img.w + x) * 3;
    return {img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]};
}

} // namespace

TEST_CASE("no sea inside a hull: a deck under the sea shows where the water would be, the rest of the frame is unchanged",
          "[gl][render][hull_clip]") {
    const gfx::CameraView cam = camera({6.0f, 8.0f, -12.0f}, {0.0f, -0.5f, 0.0f});
    const Image on = render(true, cam), off = render(false, cam);
    // Interior pixels: the sea's point and the deck's point both 0.15 m inside the outline (the
    // deck's red shows there once the sea is gone). Exterior: the sea's point 0.3 m outside it.
    int interior = 0, deckOn = 0, waterOff = 0, exterior = 0, changed = 0;
    glm::ivec3 lo(255), hi(0);  // the range of the clipped frame's interior colours
    const float DECK_Y = CENTRE.y + HALF.y;
    for (int y = 0; y < SIZE.y; ++y)
        for (int x = 0; x < SIZE.x; ++x) {
            glm::vec2 sea, deck;
            if (!hitPlane(cam, x, y, 0.0f, sea) || !hitPlane(cam, x, y, DECK_Y, deck)) continue;
            const glm::ivec3 a = pixel(on, x, y), b = pixel(off, x, y);
            if (outline(sea) < -0.15f && outline(deck) < -0.15f) {
                ++interior;
                if (a.x > a.y + 40 && a.x > a.z + 40) ++deckOn;    // the red deck, not water
                lo = glm::min(lo, a);
                hi = glm::max(hi, a);
                // Without the clip the sea is drawn there: the deck seen through 0.45 m of water
                // (refraction, the water's colour) under the sky's reflection, a colour apart.
                if (glm::any(glm::greaterThan(glm::abs(a - b), glm::ivec3(12)))) ++waterOff;
            } else if (outline(sea) > 0.3f) {
                ++exterior;
                if (glm::any(glm::greaterThan(glm::abs(a - b), glm::ivec3(1)))) ++changed;
            }
        }
    INFO(interior << " interior pixels: " << deckOn << " show the red deck with the clip (colours from " << lo.x << ","
                  << lo.y << "," << lo.z << " to " << hi.x << "," << hi.y << "," << hi.z << "), " << waterOff
                  << " differ without it; " << changed << " of " << exterior << " exterior pixels changed");
    REQUIRE(interior > 500);
    CHECK(waterOff >= interior * 9 / 10);  // without the clip the sea covers the hull (the checks below can fail)
    CHECK(deckOn == interior);             // with it, no water pixel inside the hull: the deck, one flat lit face
    CHECK(glm::all(glm::lessThanEqual(hi - lo, glm::ivec3(6))));
    CHECK(changed == 0);          // and the water elsewhere is the same frame
}

TEST_CASE("no sea inside a hull: the under-water view compiles the clip and draws the hull from below", "[gl][render][hull_clip]") {
    // The eye 3 m down, looking up at the hull: the surface seen from below keeps its look outside
    // the hull, and the frame has no GL error (render() checks).
    const gfx::CameraView cam = camera({0.0f, -6.0f, -10.0f}, {0.0f, -1.0f, 0.0f});
    const Image on = render(true, cam), off = render(false, cam);
    int exterior = 0, changed = 0;
    for (int y = 0; y < SIZE.y; ++y)
        for (int x = 0; x < SIZE.x; ++x) {
            glm::vec2 sea;
            if (!hitPlane(cam, x, y, 0.0f, sea) || outline(sea) < 0.3f) continue;
            ++exterior;
            if (glm::any(glm::greaterThan(glm::abs(pixel(on, x, y) - pixel(off, x, y)), glm::ivec3(1)))) ++changed;
        }
    INFO(changed << " of " << exterior << " pixels of the surface outside the hull changed");
    REQUIRE(exterior > 500);
    CHECK(changed == 0);
}

TEST_CASE("no sea inside a hull: the eye low over a deck, looking out under the far sea, sees no sky below the horizon",
          "[gl][render][hull_clip]") {
    // The eye 1.2 m above the calm sea, 4 m behind the stern, looking along the hull: a ray that
    // meets the sea inside the outline goes on under it and meets either the deck (0.45 m down),
    // or, past about a third of the hull, its far wall from inside (culled) and then the open
    // sea's underside, which the projected grid does not draw: nothing lies behind the surface
    // there. The clip must keep that water; dropped, it would open a hole onto the sky.
    const gfx::CameraView cam = camera({0.0f, 1.2f, -9.0f}, {0.0f, -0.5f, 3.0f});
    std::vector<float> depthOn, depthOff;
    const Image on = render(true, cam, &depthOn), off = render(false, cam, &depthOff);
    const float DECK_Y = CENTRE.y + HALF.y;
    int seaPixels = 0, holes = 0, holesOff = 0, deck = 0, deckRed = 0, leaving = 0, leavingKept = 0;
    for (int y = 0; y < SIZE.y; ++y)
        for (int x = 0; x < SIZE.x; ++x) {
            glm::vec2 sea, floor;
            float distance = 0.0f;
            // Below the horizon, within 500 m (the grid reaches 1800 m): the sea should be there.
            if (!hitPlane(cam, x, y, 0.0f, sea, &distance) || distance > 500.0f) continue;
            const size_t i = size_t(y) * size_t(SIZE.x) + size_t(x);
            ++seaPixels;
            holes += depthOn[i] >= 1.0f;
            holesOff += depthOff[i] >= 1.0f;
            if (outline(sea) > -0.15f || !hitPlane(cam, x, y, DECK_Y, floor)) continue;
            const glm::ivec3 a = pixel(on, x, y), b = pixel(off, x, y);
            if (outline(floor) < -0.15f) {  // the ray meets the deck inside the hull: the deck shows
                ++deck;
                deckRed += a.x > a.y + 40 && a.x > a.z + 40;
            } else if (outline(floor) > 0.15f) {  // it leaves the hull under the sea: the water stays, as without the clip
                ++leaving;
                leavingKept += depthOn[i] < 1.0f && !glm::any(glm::greaterThan(glm::abs(a - b), glm::ivec3(1)));
            }
        }
    INFO(seaPixels << " pixels below the horizon: " << holes << " open with the clip, " << holesOff << " without; " << deckRed
                   << " of " << deck << " deck pixels red; " << leavingKept << " of " << leaving
                   << " pixels whose ray leaves the hull under the sea keep the water");
    REQUIRE(deck > 300);
    REQUIRE(leaving > 300);
    CHECK(holesOff == 0);
    CHECK(holes == 0);
    CHECK(deckRed == deck);
    CHECK(leavingKept == leaving);

    // In msaa4 (FXAA where the driver has no multisampled depth) the clip reads the frame's
    // samples: the same pixels show the deck, and the water where the ray leaves the hull.
    const Image onAa = render(true, cam, nullptr, gfx::Antialias::Msaa4), offAa = render(false, cam, nullptr, gfx::Antialias::Msaa4);
    int deckAa = 0, leavingAa = 0;
    for (int y = 0; y < SIZE.y; ++y)
        for (int x = 0; x < SIZE.x; ++x) {
            glm::vec2 sea, floor;
            if (!hitPlane(cam, x, y, 0.0f, sea) || outline(sea) > -0.15f || !hitPlane(cam, x, y, DECK_Y, floor)) continue;
            const glm::ivec3 a = pixel(onAa, x, y), b = pixel(offAa, x, y);
            if (outline(floor) < -0.15f) deckAa += a.x > a.y + 40 && a.x > a.z + 40;
            else if (outline(floor) > 0.15f) leavingAa += !glm::any(glm::greaterThan(glm::abs(a - b), glm::ivec3(1)));
        }
    INFO(deckAa << " of " << deck << " deck pixels red, " << leavingAa << " of " << leaving << " keep the water in msaa4");
    CHECK(deckAa == deck);
    CHECK(leavingAa == leaving);
}
