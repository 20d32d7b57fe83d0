// The generated DU/DV + foam detail map: tileable, zero-mean distortion in [−1, 1], foam in [0, 1].
#include "gfx/detail_map.h"

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
