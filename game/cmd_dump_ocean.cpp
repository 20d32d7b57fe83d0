// `oceanbox dump ocean`: one update of the CPU FFT ocean, written as [N, N, 5] float32 .npy.
#include "cmd_dump_ocean.h"

#include "core/error.h"
#include "core/log.h"
#include "core/npy.h"
#include "ocean/ocean_fft_cpu.h"

#include <vector>

namespace ob::game {

int dumpOcean(const ob::ocean::OceanDef& def, double time, const std::string& outPath) {
    ocean::OceanFftCpu ocean(def);
    ocean.update(time);
    const size_t n = size_t(ocean.resolution());
    std::vector<float> data(n * n * ocean::OCEAN_DUMP_CHANNELS);
    ocean.fillDump(0, data.data());
    writeNpy(outPath, {n, n, size_t(ocean::OCEAN_DUMP_CHANNELS)}, data.data());
    logInfo("ocean: wrote %s [%zu, %zu, %d] at t = %g s (patch %g m)", outPath.c_str(), n, n,
            ocean::OCEAN_DUMP_CHANNELS, time, ocean.patchSize(0));
    return EXIT_OK;
}

} // namespace ob::game
