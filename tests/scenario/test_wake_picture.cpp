// The Kelvin wake as a person sees it: in wake.toml's picture, the high-passed luminance of
// the water behind the ship lies within the 19.47° wedge of the track, as the ripple field's
// energy does (tests/unit/test_ewave_wake.cpp): the picture shows the wake the solver computes,
// and it shows it hundreds of metres behind the ship, where the coarse levels hold it.
#include "support/test_image.h"
#include "support/test_support.h"
#include "world/scene.h"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace ob;

namespace {

constexpr int BINS = 60;  // 1° bins of the angle to the track, 0°–60°

// Energy of the high-passed luminance per 1° bin of the angle θ between the track and the
// ground point a pixel sees, for points `nearM`–`farM` behind the ship.
struct AngularEnergy {
    std::array<double, BINS> energy{}, pixels{};
    double density(int from, int to) const {  // mean energy per pixel over bins [from, to)
        double e = 0.0, n = 0.0;
        for (int b = from; b < to; ++b) e += energy[size_t(b)], n += pixels[size_t(b)];
        return n > 0.0 ? e / n : 0.0;
    }
};

// Luminance minus its mean over a (2R+1)² box: the picture's detail at scales under ~R pixels,
// where the wake's 1–10 m crests are; the sky's and the sea's smooth gradients drop out.
std::vector<double> highPassedLuminance(const test::Image& img, int radius) {
    const size_t n = size_t(img.w) * size_t(img.h);
    std::vector<double> lum(n), rows(n), box(n);
    for (size_t i = 0; i < n; ++i)
        lum[i] = (0.2126 * img.rgb[3 * i] + 0.7152 * img.rgb[3 * i + 1] + 0.0722 * img.rgb[3 * i + 2]) / 255.0;
    auto boxMean = [&](const std::vector<double>& in, std::vector<double>& out, bool alongRows) {
        for (int y = 0; y < img.h; ++y)
            for (int x = 0; x < img.w; ++x) {
                double sum = 0.0;
                int count = 0;
                for (int k = -radius; k <= radius; ++k) {
                    const int xx = alongRows ? x + k : x, yy = alongRows ? y : y + k;
                    if (xx < 0 || yy < 0 || xx >= img.w || yy >= img.h) continue;
                    sum += in[size_t(yy) * size_t(img.w) + size_t(xx)];
                    ++count;
                }
                out[size_t(y) * size_t(img.w) + size_t(x)] = sum / count;
            }
    };
    boxMean(lum, rows, true);
    boxMean(rows, box, false);
    for (size_t i = 0; i < n; ++i) lum[i] -= box[i];
    return lum;
}

// Each pixel's view ray meets the still water (y = 0) at a ground point; its angle to the
// track behind the ship `ship` heading `heading` (unit, xz) bins its high-passed energy.
AngularEnergy measure(const test::Image& img, const game::CameraDef& cam, glm::vec2 ship, glm::vec2 heading, float nearM,
                      float farM) {
    const std::vector<double> hp = highPassedLuminance(img, 6);
    const glm::vec3 forward = glm::normalize(cam.target - cam.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanHalf = std::tan(glm::radians(cam.fov_deg) * 0.5f), aspect = float(img.w) / float(img.h);
    const glm::vec2 side(heading.y, -heading.x);
    AngularEnergy a;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) {
            const float u = (2.0f * (float(x) + 0.5f) / float(img.w) - 1.0f) * tanHalf * aspect;
            const float v = (1.0f - 2.0f * (float(y) + 0.5f) / float(img.h)) * tanHalf;
            const glm::vec3 d = forward + u * right + v * up;
            if (d.y > -1e-3f) continue;
            const glm::vec3 g = cam.position - d * (cam.position.y / d.y);
            const glm::vec2 rel = glm::vec2(g.x, g.z) - ship;
            const float behind = -glm::dot(rel, heading), across = std::abs(glm::dot(rel, side));
            if (behind < nearM || behind > farM) continue;
            const int bin = int(glm::degrees(std::atan2(across, behind)));
            if (bin >= BINS) continue;
            const double h = hp[size_t(y) * size_t(img.w) + size_t(x)];
            a.energy[size_t(bin)] += h * h;
            a.pixels[size_t(bin)] += 1.0;
        }
    return a;
}

} // namespace

TEST_CASE("wake.toml's picture: the high-passed luminance behind the ship lies within the 19.47° Kelvin wedge, 300 m back", "[wake][render][long]") {
    const std::string scene = "config/scenes/wake.toml";
    const std::string png = test::tempPath("wake_picture.png"), stats = test::tempPath("wake_picture.json");
    // The scene's whole run (its end_time, 100 s: the ship runs about 490 m from rest), drawn
    // only every 64th step (the simulation does not depend on it): the picture is the last frame.
    const test::ProcessResult r =
        test::runOceanbox("run " + scene + " --headless --steps-per-frame 64 --size 480x270 --screenshot " + png + " --stats " + stats);
    REQUIRE(r.exitCode == 0);
    const test::Image img = test::loadPng(png);
    REQUIRE(img.w == 480);
    const nlohmann::json s = nlohmann::json::parse(std::ifstream(stats));
    const nlohmann::json& at = s["bodies"][0]["position"];
    const game::SceneDef def = game::loadScene(scene);
    // The headland's view: where the scene's camera event puts it for the end of the run.
    game::CameraDef camera = def.camera;
    for (const game::EventDef& e : def.events)
        if (e.action == game::EventAction::Camera) {
            camera.mode = e.mode;
            camera.position = e.position;
            camera.target = e.look_at;
        }
    const glm::vec2 start(def.objects[0].position.x, def.objects[0].position.z);
    const glm::vec2 waypoint = def.objects[0].ship.waypoints.at(0);
    const glm::vec2 heading = glm::normalize(waypoint - start);
    const glm::vec2 ship{at[0].get<float>(), at[2].get<float>()};
    REQUIRE(glm::dot(ship - start, heading) > 450.0f);  // a wake 300 m long has formed (docs/ewave.md#levels)

    // From 20 m behind the ship (its hull is 10 m long) to 150 m: the wedge and its arms.
    const AngularEnergy a = measure(img, camera, ship, heading, 20.0f, 150.0f);
    std::ostringstream table;
    for (int b = 0; b < BINS; b += 3) table << b << "°: " << a.density(b, b + 3) * 1e6 << " (" << a.pixels[size_t(b)] << " px)\n";
    INFO("high-passed energy per pixel (×1e-6) by angle to the track, 20–150 m behind:\n" << table.str());
    // Outside the wedge the water is the faint sea alone: its level is the background.
    const double background = a.density(35, 60);
    double inside = 0.0, all = 0.0;
    for (int b = 0; b < BINS; ++b) {
        const double excess = std::max(0.0, a.energy[size_t(b)] - background * a.pixels[size_t(b)]);
        all += excess;
        if (b < 22) inside += excess;
    }
    INFO("excess energy within 22°: " << inside / all << " of the excess within 60°; background " << background * 1e6);
    CHECK(inside / all >= 0.8);
    // The wedge stands out: the arms' band (15°–22°) is well above the water outside it.
    CHECK(a.density(15, 22) >= 3.0 * background);

    // 150–300 m behind, beyond the finest grid (its weight ends 112 m behind the ship), on the
    // 2 m grid alone: the arms' band against the same angular width just outside the wedge, at
    // the same distances (the same sky in the water there).
    const AngularEnergy far = measure(img, camera, ship, heading, 150.0f, 300.0f);
    std::ostringstream farTable;
    for (int b = 0; b < BINS; b += 3) farTable << b << "°: " << far.density(b, b + 3) * 1e6 << " (" << far.pixels[size_t(b)] << " px)\n";
    INFO("150–300 m behind:\n" << farTable.str());
    REQUIRE(far.pixels[30] > 100.0);  // the picture sees the water beside the wedge there
    INFO("20–150 m behind: " << inside / all << " of the excess energy within 22°, arms' band " << a.density(15, 22) / background
                              << " × the background; 150–300 m behind: arms' band " << far.density(13, 21) / far.density(28, 36)
                              << " × the band beside the wedge");
    CHECK(far.density(13, 21) >= 3.0 * far.density(28, 36));
}
