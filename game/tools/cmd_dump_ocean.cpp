// `oceanbox dump ocean`: one update of the CPU FFT ocean, written as [N, N, 5] float32 .npy.
#include "tools/cmd_dump_ocean.h"

#include "core/error.h"
#include "core/log.h"
#include "core/npy.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/gpu/ocean_fft_gpu.h"
#include "ocean/gpu/ocean_textures.h"
#include "platform/platform.h"

#include <vector>

namespace ob::game {

// The GPU backend's cascade 0, read back from its textures into the dump layout.
static std::vector<float> gpuDump(const ob::ocean::OceanDef& def, double time) {
    auto context = platform::createHeadlessPlatform({16, 16});
    ocean::OceanTextures textures(def.resolution, def.cascades);
    ocean::OceanFftGpu fft(def);
    fft.update(time, textures);
    std::vector<float> displacement = textures.readDisplacement(), slopes = textures.readSlopes();
    const size_t points = size_t(def.resolution) * size_t(def.resolution);
    std::vector<float> data(points * ocean::OCEAN_DUMP_CHANNELS);
    for (size_t p = 0; p < points; ++p) {
        const float* d = &displacement[p * 4];  // (Dx, h, Dz, J), layer 0 first
        const float* s = &slopes[p * 4];        // (dh/dx, dh/dz, J, 0)
        float* out = &data[p * ocean::OCEAN_DUMP_CHANNELS];
        out[0] = d[1];
        out[1] = d[0];
        out[2] = d[2];
        out[3] = s[0];
        out[4] = s[1];
    }
    return data;
}

int dumpOcean(const ob::ocean::OceanDef& def, double time, const std::string& outPath) {
    const size_t n = size_t(def.resolution);
    std::vector<float> data(n * n * ocean::OCEAN_DUMP_CHANNELS);
    const bool gpu = def.backend == Backend::Gpu;
    if (gpu) {
        data = gpuDump(def, time);
    } else {
        ocean::OceanFftCpu ocean(def);
        ocean.update(time);
        ocean.fillDump(0, data.data());
    }
    writeNpy(outPath, {n, n, size_t(ocean::OCEAN_DUMP_CHANNELS)}, data.data());
    logInfo("ocean: wrote %s [%zu, %zu, %d] at t = %g s (%s backend, patch %g m)", outPath.c_str(), n, n,
            ocean::OCEAN_DUMP_CHANNELS, time, gpu ? "gpu" : "cpu", double(ocean::cascadePatchSize(def, 0)));
    return EXIT_OK;
}

} // namespace ob::game
