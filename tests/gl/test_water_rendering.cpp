// The water renderer's passes (docs/references.md#water-rendering): Fresnel against the textbook equations, the
// reflection/refraction clip planes at the mirrored positions, and structural checks of a
// rendered frame (sky vs sea, the reflection switch, a red ship's reflection).
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "gfx/shader.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "support/test_image.h"
#include "support/shader_probe.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>

using namespace ob;
using test::Image;
using test::loadPng;
namespace fs = std::filesystem;

namespace {

// Exact unpolarised reflectance from air (n = 1) into water by the sine/tangent forms of
// the Fresnel equations (Hecht, Optics §4.6) — not the cosine form the shader uses.
double fresnelReference(double theta) {
    const double n = 1.33;
    if (theta < 1e-9) return std::pow((n - 1.0) / (n + 1.0), 2.0);
    double t = std::asin(std::sin(theta) / n);
    double rs = std::sin(theta - t) / std::sin(theta + t);
    double rp = std::tan(theta - t) / std::tan(theta + t);
    return 0.5 * (rs * rs + rp * rp);
}

// RGBA float texels of a 2D texture, rows bottom-up.
std::vector<glm::vec4> readTexture(const gfx::Texture& texture, glm::ivec2 size) {
    std::vector<glm::vec4> texels(size_t(size.x) * size_t(size.y));
    glFinish();  // llvmpipe reads a texture back without waiting for draws into it
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
    return texels;
}

// Centroid (px, bottom-up) and count of the texels an object covered: alpha over `threshold`
// (the reflection target's alpha is coverage; the refraction target's 1 / eye depth, 0 where
// nothing was drawn).
struct Coverage {
    glm::vec2 centroid{0.0f};
    int count = 0;
};
Coverage coverage(const std::vector<glm::vec4>& texels, glm::ivec2 size, float threshold) {
    Coverage c;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            if (texels[size_t(y * size.x + x)].w > threshold) {
                c.centroid += glm::vec2(float(x) + 0.5f, float(y) + 0.5f);
                ++c.count;
            }
    if (c.count) c.centroid /= float(c.count);
    return c;
}


// A 60° camera (near 0.1 m, far 2 km) at `eye` looking at `target`, for a frame of this aspect.
gfx::CameraView lookingAt(glm::vec3 eye, glm::vec3 target, float aspect) {
    gfx::CameraView camera;
    camera.position = eye;
    camera.view = glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
    camera.projection = glm::perspectiveRH_NO(glm::radians(60.0f), aspect, 0.1f, 2000.0f);
    camera.nearM = 0.1f;
    camera.farM = 2000.0f;
    return camera;
}

// A level camera 4 m above the sea looking along −z; a red box ("ship") afloat 25 m ahead.
const char* SHIP_SCENE = R"(
[camera]
mode = "fixed"
position = [0.0, 4.0, 0.0]
target = [0.0, 4.0, -100.0]
[ocean]
amplitude = 0.0
[gerstner]
count = 0
[ripples]
enabled = false
[[objects]]
type = "box"
position = [0.0, 0.5, -25.0]
size = [6.0, 5.0, 2.0]
density = 400.0
color = [0.9, 0.05, 0.03]
)";

Image renderShipScene(glm::ivec2 size, const std::vector<std::string>& overrides) {
    auto platform = platform::createHeadlessPlatform(size);
    int errorsBefore = gfx::glErrorCount();
    game::Sandbox sandbox(game::parseScene(SHIP_SCENE, "ship.toml", overrides));
    sandbox.attachPlatform(*platform, false);
    for (int f = 0; f < 2; ++f) sandbox.frame(f / 60.0);
    std::string path = test::tempPath("ship.png");
    gfx::writeScreenshot(path, size);
    CHECK(gfx::glErrorCount() == errorsBefore);
    Image img = loadPng(path);
    REQUIRE(img.w == size.x);
    return img;
}

} // namespace

TEST_CASE("the water shader's Fresnel matches the Fresnel equations (n = 1.33)", "[gl][render]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({16, 16});
    gfx::Program program = test::loadShaderProbe("fresnel_probe.comp");
    const int count = 91;
    gfx::Buffer result = gfx::createBuffer("fresnel probe", count * sizeof(glm::vec2));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, result.id());
    glUseProgram(program.id());
    glProgramUniform1i(program.id(), 0, count);
    glDispatchCompute(2, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec2> r(count);
    glGetNamedBufferSubData(result.id(), 0, count * sizeof(glm::vec2), r.data());

    // At normal incidence Schlick's law is exact by construction: both equal the textbook
    // reflectance ((n − 1)/(n + 1))² ≈ 0.0201.
    CHECK(r[0].x == Approx(fresnelReference(0.0)).epsilon(1e-4));
    CHECK(r[0].y == Approx(fresnelReference(0.0)).epsilon(1e-4));
    double worst = 0.0;
    for (int i = 0; i < count - 1; ++i) {
        double theta = M_PI / 2.0 * i / (count - 1);
        INFO("angle " << i << "°");
        CHECK(r[size_t(i)].y == Approx(fresnelReference(theta)).margin(2e-4));
        worst = std::max(worst, std::abs(double(r[size_t(i)].x) - fresnelReference(theta)));
    }
    // Schlick with R0 = ((n−1)/(n+1))² departs from the exact curve by at most 0.0599 (at
    // 83.8°), not 0.05: the bound is the approximation's own, checked here as it is.
    CHECK(worst < 0.0605);
    CHECK(worst > 0.055);
    CHECK(r[count - 1].x == Approx(1.0).margin(1e-4));  // grazing: total reflection
    CHECK(r[count - 1].y == Approx(1.0).margin(1e-4));
    CHECK(r[count - 2].y > 0.85f);  // 89°: mostly reflected
    for (int i = 1; i < count; ++i) CHECK(r[size_t(i)].y >= r[size_t(i - 1)].y);  // monotonic toward grazing
}

TEST_CASE("clip planes: above the water only in the reflection, below only in the refraction, at the mirrored place", "[gl][render]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    auto platform = platform::createHeadlessPlatform(size);
    int errorsBefore = gfx::glErrorCount();
    gfx::RenderDef def;
    def.rtt_scale = 0.5f;
    gfx::Renderer renderer(def);
    const gfx::CameraView camera = lookingAt(glm::vec3(0.0f, 6.0f, 0.0f), glm::vec3(0.0f, 0.0f, -30.0f), 320.0f / 180.0f);
    const glm::ivec2 targetSize = size / 2;

    // Where a world point lands in a target of the camera's frame (px, bottom-up).
    auto pixelOf = [&](glm::vec3 p) {
        glm::vec4 clip = camera.projection * camera.view * glm::vec4(p, 1.0f);
        glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return (ndc * 0.5f + 0.5f) * glm::vec2(targetSize);
    };
    auto renderSphereAt = [&](glm::vec3 centre) {
        gfx::ObjectDraw sphere;
        sphere.mesh = gfx::MeshKind::Sphere;
        sphere.model = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(1.5f));
        sphere.color = glm::vec3(0.9f, 0.1f, 0.1f);
        renderer.render(camera, gfx::WaterView{}, {sphere}, 0.0, size);
        return std::pair{coverage(readTexture(renderer.reflectionTarget().color, targetSize), targetSize, 0.5f),
                         coverage(readTexture(renderer.refractionTarget().color, targetSize), targetSize, 0.0f)};
    };

    const glm::vec3 above(2.0f, 3.0f, -30.0f);
    auto [reflection, refraction] = renderSphereAt(above);
    CHECK(refraction.count == 0);
    REQUIRE(reflection.count > 10);
    glm::vec2 mirrored = pixelOf(glm::vec3(above.x, -above.y, above.z));
    INFO("reflection centroid " << reflection.centroid.x << "," << reflection.centroid.y << " expected " << mirrored.x << ","
                                << mirrored.y);
    CHECK(glm::distance(reflection.centroid, mirrored) < 1.5f);
    CHECK(glm::distance(reflection.centroid, pixelOf(above)) > 10.0f);  // not the unmirrored place

    const glm::vec3 below(-2.0f, -3.0f, -30.0f);
    auto [reflection2, refraction2] = renderSphereAt(below);
    CHECK(reflection2.count == 0);
    REQUIRE(refraction2.count > 10);
    CHECK(glm::distance(refraction2.centroid, pixelOf(below)) < 1.5f);
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("an object wholly under the water is seen through it from above, by the refraction alone", "[gl][render]") {
    // A red sphere 3 m under a flat sea, seen from 8 m up: the water surface, opaque in the
    // camera's pass, covers it (so that pass may leave it out); it shows only through the
    // refraction pass, faded by its depth.
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(160, 90);
    auto platform = platform::createHeadlessPlatform(size);
    int errorsBefore = gfx::glErrorCount();
    const gfx::CameraView camera = lookingAt(glm::vec3(0.0f, 8.0f, 0.0f), glm::vec3(0.0f, -3.0f, -12.0f), 160.0f / 90.0f);
    gfx::ObjectDraw sphere;
    sphere.mesh = gfx::MeshKind::Sphere;
    sphere.model = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -3.0f, -12.0f)), glm::vec3(1.5f));
    sphere.color = glm::vec3(0.9f, 0.05f, 0.05f);
    auto frame = [&](bool refractions, std::vector<gfx::ObjectDraw> objects) {
        gfx::RenderDef def;
        def.refractions = refractions;
        def.antialias = gfx::Antialias::Off;
        gfx::Renderer renderer(def);
        renderer.render(camera, gfx::WaterView{}, objects, 0.0, size);
        const std::string path = test::tempPath("under.png");
        gfx::writeScreenshot(path, size);
        return loadPng(path);
    };
    const Image seen = frame(true, {sphere}), empty = frame(true, {});
    const Image covered = frame(false, {sphere}), bare = frame(false, {});
    // The camera looks at the sphere's centre: the middle of the frame.
    auto redness = [](const Image& img) {
        glm::vec3 c = img.mean(img.w / 2 - 6, img.h / 2 - 6, img.w / 2 + 6, img.h / 2 + 6);
        return c.x - 0.5f * (c.y + c.z);
    };
    INFO("redness with the sphere " << redness(seen) << ", without " << redness(empty));
    CHECK(redness(seen) > redness(empty) + 0.05f);   // seen through the water
    CHECK(covered.maxDifference(bare, 0, bare.h) == 0);  // without the refraction pass nothing of it shows
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("the refraction target carries 1 / the eye depth of what lies below, 0 where nothing does", "[gl][render]") {
    // The water pass reads the depth below the surface from the refraction colour's alpha
    // ([KTSDE2017] eq. 7's fade). A sphere of radius 1.5 m centred 3 m under the surface, on the camera's
    // axis: at the frame's centre the eye depth of its front is |centre − eye| − r (its back,
    // |centre − eye| + r, where a mesh wound inside out is culled at the front).
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(160, 90);
    auto platform = platform::createHeadlessPlatform(size);
    const glm::vec3 eye(0.0f, 8.0f, 0.0f), centre(0.0f, -3.0f, -12.0f);
    const float radius = 1.5f;
    gfx::ObjectDraw sphere;
    sphere.mesh = gfx::MeshKind::Sphere;
    sphere.model = glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(radius));
    gfx::RenderDef def;
    def.antialias = gfx::Antialias::Off;
    gfx::Renderer renderer(def);
    renderer.render(lookingAt(eye, centre, 160.0f / 90.0f), gfx::WaterView{}, {sphere}, 0.0, size);
    const glm::ivec2 target = renderer.refractionTarget().size;
    const std::vector<glm::vec4> texels = readTexture(renderer.refractionTarget().color, target);
    const float expected = glm::distance(eye, centre) - radius;
    const float alpha = texels[size_t((target.y / 2) * target.x + target.x / 2)].w;
    INFO("1 / alpha at the centre " << 1.0f / alpha << " m, the sphere's front at " << expected << " m");
    CHECK(std::abs(1.0f / alpha - expected) < 0.02f * expected);
    // The top row looks at the sky: nothing below the surface there.
    CHECK(texels[size_t((target.y - 1) * target.x + target.x / 2)].w == 0.0f);
}

TEST_CASE("a small object across the surface is cut at the surface's tangent plane under it", "[gl][render]") {
    // A sphere of 0.9 m (small: cut at the plane its ObjectDraw carries, not per vertex)
    // centred on the surface, seen level from 6 m. Where the plane rises to +x, more of the
    // sphere lies under it on that side: the refraction's part leans right, the reflection's
    // part (above the plane, its mirror image) leans left; the reverse for the opposite slope.
    const glm::ivec2 size(640, 360);
    auto platform = platform::createHeadlessPlatform(size);
    gfx::RenderDef def;
    def.rtt_scale = 0.5f;
    gfx::Renderer renderer(def);
    const gfx::CameraView camera = lookingAt(glm::vec3(0.0f, 0.0f, 6.0f), glm::vec3(0.0f), 640.0f / 360.0f);
    const glm::ivec2 targetSize = size / 2;
    auto centroidShifts = [&](float slope) {
        gfx::ObjectDraw sphere;
        sphere.model = glm::scale(glm::mat4(1.0f), glm::vec3(0.9f));
        sphere.waterSlope = glm::vec2(slope, 0.0f);
        renderer.render(camera, gfx::WaterView{}, {sphere}, 0.0, size);
        const float centre = 0.5f * float(targetSize.x);
        return std::pair{coverage(readTexture(renderer.refractionTarget().color, targetSize), targetSize, 0.0f).centroid.x - centre,
                         coverage(readTexture(renderer.reflectionTarget().color, targetSize), targetSize, 0.5f).centroid.x - centre};
    };
    const auto [level, levelMirror] = centroidShifts(0.0f);
    const auto [rising, risingMirror] = centroidShifts(0.8f);
    const auto [falling, fallingMirror] = centroidShifts(-0.8f);
    INFO("refraction centroid − centre (px): level " << level << ", rising " << rising << ", falling " << falling);
    INFO("reflection centroid − centre (px): level " << levelMirror << ", rising " << risingMirror << ", falling " << fallingMirror);
    CHECK(std::abs(level) < 0.5f);
    CHECK(std::abs(levelMirror) < 0.5f);
    CHECK(rising > 2.0f);
    CHECK(falling < -2.0f);
    CHECK(risingMirror < -2.0f);
    CHECK(fallingMirror > 2.0f);
}

TEST_CASE("a 320×180 frame: sky and sea differ, reflections change only the sea, a red ship reddens the water below it", "[gl][render]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    Image on = renderShipScene(size, {});
    Image off = renderShipScene(size, {"render.reflections=false"});
    const int horizon = size.y / 2;  // level camera: the horizon is the middle row

    glm::vec3 sky = on.mean(0, 0, on.w, horizon - 6);
    glm::vec3 sea = on.mean(0, horizon + 6, on.w, on.h);
    INFO("sky " << sky.x << " " << sky.y << " " << sky.z << ", sea " << sea.x << " " << sea.y << " " << sea.z);
    CHECK(glm::length(sky - sea) > 0.15f);

    CHECK(on.maxDifference(off, 0, horizon - 2) == 0);       // the sky is untouched by the switch
    CHECK(on.maxDifference(off, horizon + 2, on.h) > 20);    // the sea is not

    // The ship (6 m wide, 3 m of it above the water, 25 m ahead of an eye 4 m up) is mirrored
    // under itself: its image spans rows ≈ horizon + 7…27 (3 px per degree), its reflection
    // rows ≈ horizon + 27…47. There, in its columns, the water turns red with reflections.
    auto redness = [&](const Image& img) {
        glm::vec3 c = img.mean(on.w / 2 - 12, horizon + 31, on.w / 2 + 12, horizon + 44);
        return c.x - 0.5f * (c.y + c.z);
    };
    INFO("redness with reflections " << redness(on) << ", without " << redness(off));
    CHECK(redness(on) > redness(off) + 0.1f);
}

TEST_CASE("a frame drawn at half internal resolution and scaled up matches the full-resolution frame", "[gl][render]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    Image full = renderShipScene(size, {});
    Image half = renderShipScene(size, {"render.resolution_scale=0.5"});
    REQUIRE(half.w == size.x);
    REQUIRE(half.h == size.y);
    // Band by band (sky, horizon, ship, near sea) the colours agree; the edges differ.
    for (int band = 0; band < 6; ++band) {
        const int y0 = band * size.y / 6, y1 = (band + 1) * size.y / 6;
        INFO("rows " << y0 << "-" << y1);
        CHECK(glm::length(full.mean(0, y0, size.x, y1) - half.mean(0, y0, size.x, y1)) < 0.03f);
    }
    CHECK(full.maxDifference(half, 0, size.y) > 0);  // it did draw at another size
}

TEST_CASE("under the surface the frame is water fog and the surface from below, never sky or black", "[gl][render]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(160, 90);
    Image above = renderShipScene(size, {});
    Image below = renderShipScene(size, {"camera.position=[0.0, -3.0, 0.0]", "camera.target=[0.0, -1.0, -100.0]"});
    glm::vec3 skyAbove = above.mean(0, 0, size.x, size.y / 3);
    glm::vec3 top = below.mean(0, 0, size.x, size.y / 3), bottom = below.mean(0, 2 * size.y / 3, size.x, size.y);
    INFO("below: top " << top.x << " " << top.y << " " << top.z << ", bottom " << bottom.x << " " << bottom.y << " " << bottom.z);
    CHECK(glm::length(top - skyAbove) > 0.3f);  // no sky where the water is overhead
    CHECK(top.z > top.x);                       // blue-green water
    CHECK(bottom.z > bottom.x);
    int black = 0;
    for (size_t i = 0; i < below.rgb.size(); i += 3) black += below.rgb[i] + below.rgb[i + 1] + below.rgb[i + 2] < 6;
    CHECK(black == 0);
}

TEST_CASE("a model's far twin (X.lod1.gltf) is drawn only where the object spans a few pixels", "[gl][render]") {
    // A fish model whose "twin" is a ball of 1 m, so that the frame shows which mesh was drawn:
    // at 6 m the fish's bounding sphere spans 13 px of radius (the model), at 150 m 0.5 px (the twin).
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(320, 180);
    auto platform = platform::createHeadlessPlatform(size);
    const fs::path dir = test::tempPath("lod_models");
    fs::create_directories(dir);
    const fs::path models = fs::path(OCEANBOX_SOURCE_DIR) / "assets/models";
    fs::copy_file(models / "fish.gltf", dir / "fish.gltf", fs::copy_options::overwrite_existing);
    fs::copy_file(models / "fish.gltf", dir / "plain.gltf", fs::copy_options::overwrite_existing);  // no twin
    fs::copy_file(models / "cannonball.gltf", dir / "fish.lod1.gltf", fs::copy_options::overwrite_existing);
    auto frame = [&](const std::string& model, float distance) {
        const gfx::CameraView camera = lookingAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 1.0f, -distance), 320.0f / 180.0f);
        gfx::ObjectDraw fish;
        fish.modelFile = (dir / model).string();
        fish.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, -distance)) *
                     glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
        fish.waterHeight = -10.0f;  // well above the water: every pass draws it whole
        gfx::RenderDef def;
        def.antialias = gfx::Antialias::Off;
        gfx::Renderer renderer(def);
        renderer.render(camera, gfx::WaterView{}, {fish}, 0.0, size);
        const std::string path = test::tempPath("lod.png");
        gfx::writeScreenshot(path, size);
        return loadPng(path);
    };
    CHECK(frame("fish.gltf", 6.0f).maxDifference(frame("plain.gltf", 6.0f), 0, size.y) == 0);  // near: the model
    CHECK(frame("fish.gltf", 150.0f).maxDifference(frame("plain.gltf", 150.0f), 0, size.y) > 0);  // far: the twin
}
