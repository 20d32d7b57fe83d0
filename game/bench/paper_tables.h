// The papers' measured numbers the benches chart beside ours (docs/references.md#paper-experiments). Kept here because the
// papers are not part of the repository.
#pragma once
#include <cmath>

namespace ob::game {

/// [Kang2008] (Kang et al. 2008) Table 5: fps against the number of jumping fish, one bounding
/// sphere each, SR 20, fish not drawn; 2.6 GHz CPU, DirectX 9, 800×600.
struct PaperSwarmFps {
    int count;
    double fps;
};
inline constexpr PaperSwarmFps SEED001_TABLE5[] = {
    {1, 39.2},    {10, 39.1},   {30, 38.9},    {100, 38.8},  {300, 38.4},
    {1000, 37.1}, {3000, 32.5}, {10000, 23.7}, {30000, 13.3}, {100000, 5.4},
};

/// [Kang2008] Table 3: fps by height-field size and scenario, all drawn ("full") and with the
/// objects not rendered ("spheres only"); same machine.
struct PaperFieldFps {
    int size;
    const char* scene;
    double full, spheresOnly;
};
inline constexpr PaperFieldFps SEED001_TABLE3[] = {
    {64, "cannon", 91, 114}, {64, "fish", 84, 113}, {64, "ship", 74, 113}, {64, "all", 45, 112},
    {128, "cannon", 41, 43}, {128, "fish", 41, 43}, {128, "ship", 32, 42}, {128, "all", 31, 42},
};

/// [Lee2007] (Lee & Lee 2007) Tables 1–3: fps against spectrum resolution on a GeForce 6800
/// Ultra against a Pentium 4 3 GHz with FFTW. Table 1: simulation + rendering (1280×1024,
/// Gerstner 128² × 16 trochoids, reflection/refraction maps 256²); Table 2: simulation only;
/// Table 3: the Fourier transform only (complex to complex). NAN: not measured.
struct PaperOceanFps {
    int size;
    double simRenderGpu, simRenderCpu, simGpu, simCpu, fftGpu, fftCpuFftw;
};
inline constexpr PaperOceanFps SEED000_TABLES[] = {
    {64, 48, 14, 399, 75, 1925, 3300},
    {128, 37, 14, 220, 52, 600, 970},
    {256, 28, 12, 85, 23, 178, 222},
    {512, 14, 2, 21, 3, 39, 13},
    {1024, NAN, NAN, 4, 0.8, 8, 3},
};

} // namespace ob::game
