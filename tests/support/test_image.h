// PNG screenshots read back for structural image checks.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace ob::test {

/// An RGB8 image, rows top-down.
struct Image {
    int w = 0, h = 0;
    std::vector<unsigned char> rgb;
    /// Mean colour (0..1) of [x0, x1) × [y0, y1).
    glm::vec3 mean(int x0, int y0, int x1, int y1) const {
        double sum[3] = {0, 0, 0};
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                for (int c = 0; c < 3; ++c) sum[c] += rgb[size_t((y * w + x) * 3 + c)];
        const double n = double((x1 - x0) * (y1 - y0)) * 255.0;
        return glm::vec3(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
    }
    /// Largest channel difference to `o` over rows [y0, y1).
    int maxDifference(const Image& o, int y0, int y1) const {
        int d = 0;
        for (size_t i = size_t(y0 * w * 3); i < size_t(y1 * w * 3); ++i) d = std::max(d, std::abs(int(rgb[i]) - int(o.rgb[i])));
        return d;
    }
};

/// Reads a PNG as RGB8; an empty image (w = 0) when it cannot.
Image loadPng(const std::string& path);

} // namespace ob::test
