// Time of day ([render] time_of_day, gfx/sun.h): the sun where spherical astronomy puts it,
// and a sky, set live, that follows it: sunset colours with a low sun, dark at night.
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "gfx/sun.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/script.h"
#include "support/test_image.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

using namespace ob;
using test::Image;

TEST_CASE("the sun by the hour: noon at 90° − φ + δ toward +z, rising toward +x, setting at cos H = −tan φ·tan δ", "[gl][sky]") {
    constexpr double DEG = std::numbers::pi / 180.0;
    const float lat = 40.0f, dec = 10.0f;
    const glm::vec3 noon = gfx::sunAtHour(12.0f, lat, dec);
    CHECK(std::asin(noon.y) / DEG == Approx(90.0 - 40.0 + 10.0).margin(1e-3));
    CHECK(noon.x == Approx(0.0f).margin(1e-6));
    CHECK(noon.z > 0.0f);
    CHECK(gfx::sunAtHour(8.0f, lat, dec).x > 0.5f);   // morning: east
    CHECK(gfx::sunAtHour(16.0f, lat, dec).x < -0.5f); // afternoon: west
    const double h0 = std::acos(-std::tan(lat * DEG) * std::tan(dec * DEG)) / DEG / 15.0;  // hours from noon to sunset
    CHECK(gfx::sunAtHour(float(12.0 + h0), lat, dec).y == Approx(0.0f).margin(1e-5));
    CHECK(gfx::sunAtHour(float(12.0 - h0), lat, dec).y == Approx(0.0f).margin(1e-5));
    CHECK(gfx::sunAtHour(0.0f, lat, dec).y < -0.5f);  // midnight: well below
    gfx::RenderDef def;
    CHECK(gfx::sunDirection(def) == glm::normalize(def.sun_direction));  // −1: the scene's direction
    def.time_of_day = 12.0f;
    CHECK(gfx::sunDirection(def) == noon);
}

TEST_CASE("a live time of day re-bakes the sky: sunset reddens the horizon toward the sun, night darkens it", "[gl][sky][sea_live]") {
    const glm::ivec2 size(192, 108);
    auto platform = platform::createHeadlessPlatform(size);
    const char* text = R"(
[camera]
mode = "fixed"
position = [0.0, 5.0, 0.0]
target = [-100.0, 5.0, -20.0]
[render]
time_of_day = 12.0
[ocean]
resolution = 64
[ripples]
enabled = false
)";
    game::Sandbox sandbox(game::parseScene(text, "sky.toml"));
    sandbox.attachPlatform(*platform, false);
    double t = 0.0;
    // The sky band just above the horizon, around the sunset's azimuth (the view's centre).
    const auto shot = [&](const char* tag) {
        for (int f = 0; f < 3; ++f) sandbox.frame(t += 1.0 / 60.0);
        sandbox.present();
        const std::string path = test::tempPath(std::string("sky_") + tag + ".png");
        gfx::writeScreenshot(path, size);
        const Image img = test::loadPng(path);
        return img.mean(size.x / 4, size.y / 2 - 20, 3 * size.x / 4, size.y / 2 - 4);
    };
    const glm::vec3 noon = shot("noon");
    REQUIRE(game::requestLiveSet(sandbox.world(), "render.time_of_day", 18.3f).empty());
    const glm::vec3 sunset = shot("sunset");
    REQUIRE(game::requestLiveSet(sandbox.world(), "render.time_of_day", 21.0f).empty());
    const glm::vec3 night = shot("night");
    INFO("horizon rgb: noon " << noon.x << " " << noon.y << " " << noon.z << ", sunset " << sunset.x << " " << sunset.y << " "
                              << sunset.z << ", night " << night.x << " " << night.y << " " << night.z);
    CHECK(noon.z > noon.x);                          // a blue-white day horizon
    CHECK(sunset.x > sunset.z);                      // orange toward the low sun
    CHECK(sunset.x / sunset.z > 1.3f * noon.x / noon.z);
    CHECK(night.x + night.y + night.z < 0.25f * (noon.x + noon.y + noon.z));
}
