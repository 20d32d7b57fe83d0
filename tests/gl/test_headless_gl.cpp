// Headless GL through OSMesa: a GL 4.5 core context with compute shaders, a rendered frame
// with sky above the horizon and sea below it, and no GL error reported.
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "support/test_image.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

using namespace ob;
using test::Image;
using test::loadPng;

namespace {



} // namespace

TEST_CASE("OSMesa gives a GL 4.5 core context with compute shaders", "[gl]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({64, 48});
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    CHECK(major * 10 + minor >= 45);
    CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
    GLint groups = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groups);
    CHECK(groups > 0);
    CHECK(platform->framebufferSize() == glm::ivec2(64, 48));
}

TEST_CASE("GL debug output counts a deliberate GL error (the check that fails tests works)", "[gl]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({16, 16});
    int before = gfx::glErrorCount();
    glBindTexture(GL_TEXTURE_2D, 123456);  // not a texture name: GL_INVALID_OPERATION
    CHECK(gfx::glErrorCount() == before + 1);
}

TEST_CASE("a headless frame of the default scene shows sky above the horizon and sea below", "[gl]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(160, 96);
    auto platform = platform::createHeadlessPlatform(size);
    int errorsBefore = gfx::glErrorCount();
    game::SceneDef scene = game::loadScene(game::defaultScenePath(), {"camera.mode=fixed", "camera.position=[0, 5, 0]",
                                                                      "camera.target=[0, 5, 100]"});
    game::Sandbox sandbox(scene);
    sandbox.attachPlatform(*platform, false);
    for (int f = 0; f < 3; ++f) sandbox.frame(f / 60.0);
    std::string path = test::tempPath("frame.png");
    gfx::writeScreenshot(path, size);
    CHECK(gfx::glErrorCount() == errorsBefore);

    Image img = loadPng(path);
    REQUIRE(img.w == size.x);
    REQUIRE(img.h == size.y);
    // A level camera puts the horizon on the middle row: sky above, water below.
    glm::vec3 sky = img.mean(0, 0, img.w, img.h / 2 - 4);
    glm::vec3 sea = img.mean(0, img.h / 2 + 8, img.w, img.h);
    INFO("sky " << sky.x << " " << sky.y << " " << sky.z << ", sea " << sea.x << " " << sea.y << " " << sea.z);
    CHECK(sky.z > sky.x);                          // blue sky
    CHECK(sea.z > sea.x);                          // blue-green water
    CHECK(sky.x + sky.y + sky.z > sea.x + sea.y + sea.z + 0.3f);  // the sea is darker than the sky
    // Not uniform: some pixel differs clearly from the first.
    bool varied = false;
    for (size_t i = 0; i < img.rgb.size() && !varied; ++i) varied = std::abs(int(img.rgb[i]) - int(img.rgb[i % 3])) > 40;
    CHECK(varied);
}

TEST_CASE("looking straight up shows only sky, looking down only sea", "[gl]") {
    gfx::requestDebugOutput(true);
    const glm::ivec2 size(64, 64);
    auto platform = platform::createHeadlessPlatform(size);
    auto meanOf = [&](const char* target) {
        game::SceneDef scene = game::loadScene(game::defaultScenePath(),
                                               {"camera.mode=fixed", "camera.position=[0, 10, 0]", std::string("camera.target=") + target});
        game::Sandbox sandbox(scene);
        sandbox.attachPlatform(*platform, false);
        sandbox.frame(0.0);
        std::string path = test::tempPath("look.png");
        gfx::writeScreenshot(path, size);
        Image img = loadPng(path);
        return img.mean(0, 0, img.w, img.h);
    };
    glm::vec3 up = meanOf("[0.01, 100, 0]");
    glm::vec3 down = meanOf("[0.01, -100, 0]");
    CHECK(up.z > 0.4f);                              // bright blue zenith
    CHECK(down.x + down.y + down.z < up.x + up.y + up.z); // water darker than the sky
    CHECK(down.z > down.x);
}

namespace {

// A platform that records what it is asked (a present with the steps run by then), around a
// headless one.
struct RecordingPlatform final : platform::Platform {
    std::unique_ptr<platform::Platform> inner = platform::createHeadlessPlatform({32, 24});
    game::Sandbox* sandbox = nullptr;
    std::vector<std::string> calls;
    const char* name() const override { return inner->name(); }
    bool headless() const override { return true; }
    glm::ivec2 framebufferSize() const override { return inner->framebufferSize(); }
    void pollEvents(std::vector<platform::InputEvent>& out) override {
        calls.push_back("poll");
        inner->pollEvents(out);
    }
    void present() override {
        calls.push_back("present after step " + std::to_string(sandbox->schedule().steps()));
        inner->present();
    }
};

} // namespace

TEST_CASE("a frame is presented once, after the next frame's input and steps and before its passes", "[gl]") {
    RecordingPlatform platform;
    game::Sandbox sandbox(game::loadScene(game::defaultScenePath(), {"ocean.resolution=32", "ripples.resolution=32"}));
    platform.sandbox = &sandbox;
    sandbox.attachPlatform(platform, false);
    for (int f = 0; f < 3; ++f) sandbox.frame(f / 60.0);  // one step a frame
    // Frame 1 presents nothing yet; frames 2 and 3 present the frame before, after their poll
    // and their step.
    CHECK(platform.calls == std::vector<std::string>{"poll", "poll", "present after step 2", "poll", "present after step 3"});
    sandbox.present();
    sandbox.present();  // nothing new to show
    CHECK(platform.calls.size() == 6);
    CHECK(platform.calls.back() == "present after step 3");
}
