// The renderer's texels of the CPU ocean's maps: both textures' layers interleaved and their mip
// chains, made on the thread that updated the maps (a pipelined step's worker), so the render
// phase only copies them (gfx: ocean/gpu/ocean_textures.h).
#pragma once

#include <cstddef>
#include <vector>

namespace ob::ocean {

class OceanFftCpu;

/// Every mip level of the two RGBA32F 2-D array maps OceanTextures draws from, level after level,
/// each [layer][j][i][rgba] (C·(N >> l)² texels at level l):
///   displacement = (Dx, h, Dz, J), slopes = (∂h/∂x, ∂h/∂z, J, |∇h|²).
/// Level l + 1 is the mean of level l's 2 × 2 blocks (the box filter glGenerateMipmap applies to a
/// power of two). Cost: one pass over the six channels and a third more for the mips, C·N²·32
/// bytes written at level 0 (4 MiB at N = 256, C = 2).
struct OceanTexels {
    std::vector<float> displacement, slopes;
    /// Each cascade's extremes over its texels, found in the same pass (OceanFftCpu::displacementBounds).
    struct Extremes {
        float hi = 0.0f, lo = 0.0f;  ///< max(0, h), min(0, h), m
        float d2 = 0.0f;             ///< max(Dx² + Dz²), m², not multiplied by λ²
    };
    std::vector<Extremes> extremes;
    int resolution = 0;  ///< N
    int cascades = 0;    ///< layers
    int levels = 0;      ///< log2(N) + 1
    double time = -1.0;  ///< the maps' time (OceanFftCpu::time) they were made from; < 0: none yet

    /// Makes them from fft's last update().
    void fill(const OceanFftCpu& fft);
    /// Offset (floats) of level l in either array.
    std::size_t levelOffset(int level) const;
};

} // namespace ob::ocean
