// The renderer's texels of the CPU ocean's maps, with their mips.
#include "ocean/ocean_texels.h"

#include "ocean/ocean_fft_cpu.h"

#include <algorithm>

namespace ob::ocean {

namespace {
// Level l + 1 of one array from level l (n texels a side there), every layer: each texel the
// mean of its 2 × 2 block.
void halve(const float* from, float* to, int n, int layers) {
    const int m = n / 2;
    for (int c = 0; c < layers; ++c) {
        const float* src = from + size_t(c) * size_t(n) * size_t(n) * 4;
        float* dst = to + size_t(c) * size_t(m) * size_t(m) * 4;
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const float* a = src + (size_t(2 * j) * size_t(n) + size_t(2 * i)) * 4;
                const float* b = a + size_t(n) * 4;
                float* out = dst + (size_t(j) * size_t(m) + size_t(i)) * 4;
                for (int k = 0; k < 4; ++k) out[k] = 0.25f * ((a[k] + a[4 + k]) + (b[k] + b[4 + k]));
            }
    }
}
} // namespace

size_t OceanTexels::levelOffset(int level) const {
    size_t offset = 0;
    for (int l = 0; l < level; ++l) offset += size_t(cascades) * size_t(resolution >> l) * size_t(resolution >> l) * 4;
    return offset;
}

void OceanTexels::fill(const OceanFftCpu& fft) {
    resolution = fft.resolution();
    cascades = fft.cascadeCount();
    levels = 1;
    while ((1 << (levels - 1)) < resolution) ++levels;
    const size_t total = levelOffset(levels);
    displacement.resize(total);
    slopes.resize(total);
    const size_t texels = size_t(resolution) * size_t(resolution);
    extremes.assign(size_t(cascades), {});
    for (int c = 0; c < cascades; ++c) {
        const float* dx = fft.channel(c, OceanChannel::DispX);
        const float* h = fft.channel(c, OceanChannel::Height);
        const float* dz = fft.channel(c, OceanChannel::DispZ);
        const float* sx = fft.channel(c, OceanChannel::SlopeX);
        const float* sz = fft.channel(c, OceanChannel::SlopeZ);
        const float* jac = fft.channel(c, OceanChannel::Jacobian);
        float* d = displacement.data() + texels * size_t(c) * 4;
        float* s = slopes.data() + texels * size_t(c) * 4;
        Extremes& e = extremes[size_t(c)];
        for (size_t p = 0; p < texels; ++p) {
            e.hi = std::max(e.hi, h[p]);
            e.lo = std::min(e.lo, h[p]);
            e.d2 = std::max(e.d2, dx[p] * dx[p] + dz[p] * dz[p]);
            d[4 * p] = dx[p];
            d[4 * p + 1] = h[p];
            d[4 * p + 2] = dz[p];
            d[4 * p + 3] = jac[p];
            s[4 * p] = sx[p];
            s[4 * p + 1] = sz[p];
            s[4 * p + 2] = jac[p];
            s[4 * p + 3] = sx[p] * sx[p] + sz[p] * sz[p];
        }
    }
    for (int l = 0; l + 1 < levels; ++l)
        for (std::vector<float>* map : {&displacement, &slopes})
            halve(map->data() + levelOffset(l), map->data() + levelOffset(l + 1), resolution >> l, cascades);
    time = fft.time();
}

} // namespace ob::ocean
