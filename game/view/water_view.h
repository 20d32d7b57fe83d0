// The water on the GPU: the ocean's textures and GPU FFT, the ripple patch's GPU twin, and
// what the render phase hands the renderer of the water's layers.
#pragma once
#include "ecs/world.h"
#include "gfx/renderer.h"

#include <array>
#include <cstdint>
#include <memory>

namespace ob::ocean {
class OceanFftGpu;
class OceanTextures;
}

namespace ob::game {

/// The ocean's GPU side (a resource, with a GL context only).
struct OceanGpu {
    std::unique_ptr<ocean::OceanTextures> textures;
    std::unique_ptr<ocean::OceanFftGpu> gpu;  ///< set when the GPU backend renders
    double uploadedTime = -1.0;               ///< time of the maps in the textures (s)
    std::uint64_t seaVersion = 0;             ///< OceanState::seaVersion the GPU FFT's h̃0 and λ follow
    std::array<float, 4> slopeVariance{};     ///< ocean::cascadeSlopeVariance per cascade, of the sea in `slopeSea`
    std::array<float, 6> slopeSea{-1.0f};     ///< the spectrum keys it was summed for (a live change sums again)
    /// The far sea's whitecaps (gfx::WaterView::whitecapJacobian, whitecapSigma) and the
    /// OceanState::seaVersion + 1 they were read at (0: never).
    float whitecapJacobian = 0.0f, whitecapSigma = 0.0f;
    std::uint64_t whitecapVersion = 0;
    ~OceanGpu();
};

/// Creates the textures and, per [ocean] and [ripples] backend, the GPU FFT and the GPU
/// ripple field (needs a current GL context).
void attachWaterGpu(ecs::World& world);
/// Render phase helper: brings the textures to `time` and describes the water layers.
gfx::WaterView prepareWaterView(ecs::World& world, double time);

} // namespace ob::game
