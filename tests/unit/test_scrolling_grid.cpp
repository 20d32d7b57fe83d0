// The scrolling grid: where a world point falls, and the one scroll routine against a naive
// copy cell by cell (new (i, j) = old (i + dx, j + dz), outside filled).
#include "core/scrolling_grid.h"

#include <catch2/catch.hpp>

#include <vector>

using ob::ScrollingGrid;

TEST_CASE("A scrolling grid centres on the nearest cell and maps world to grid", "[scroll]") {
    ScrollingGrid g = ScrollingGrid::centredOn({10.2f, -3.9f}, 0.5f, 8);
    CHECK(g.originCell == glm::ivec2(20 - 4, -8 - 4));
    CHECK(g.origin().x == Approx(8.0f));
    CHECK(g.toGrid({10.0f, -4.0f}).x == Approx(4.0f));
    CHECK(g.toGrid({10.0f, -4.0f}).y == Approx(4.0f));
    CHECK(g.extent() == Approx(4.0f));
    const glm::ivec2 shift = g.centreOn({11.0f, -5.0f});
    CHECK(shift == glm::ivec2(2, -2));
    CHECK(g.centreOn({11.1f, -5.1f}) == glm::ivec2(0));
}

TEST_CASE("scrollCells moves data as a cell-by-cell copy does", "[scroll]") {
    const int rows = 5, cols = 7;
    for (int dz = -6; dz <= 6; ++dz)
        for (int dx = -8; dx <= 8; ++dx) {
            std::vector<double> a(size_t(rows * cols));
            for (size_t k = 0; k < a.size(); ++k) a[k] = double(k) + 1.0;
            std::vector<double> want(a.size());
            for (int j = 0; j < rows; ++j)
                for (int i = 0; i < cols; ++i) {
                    const int si = i + dx, sj = j + dz;
                    want[size_t(j * cols + i)] =
                        (si >= 0 && si < cols && sj >= 0 && sj < rows) ? a[size_t(sj * cols + si)] : -1.0;
                }
            ob::scrollCells(a.data(), rows, cols, {dx, dz}, -1.0);
            INFO("shift " << dx << ", " << dz);
            CHECK(a == want);
        }
}
