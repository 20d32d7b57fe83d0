// The GPU-side ocean maps every FFT backend writes and the renderer samples: one RGBA32F
// 2-D array texture layer per cascade for displacement and one for slopes (docs/references.md#spectral-ocean).
#pragma once
#include "gfx/handles.h"

#include <vector>

namespace ob::ocean {

class OceanFftCpu;
struct OceanTexels;

/// Two GL_TEXTURE_2D_ARRAY maps, N×N texels × one layer per cascade, RGBA32F, repeat wrap
/// (the tile is periodic), trilinear filtering with a full mip chain. Texel (i, j) of layer
/// c is the point X = (i·L_c/N, j·L_c/N) of cascade c's tile (x along i, z along j):
///   displacement() = (Dx, h, Dz, J)  metres, metres, metres, dimensionless
///   slopes()       = (∂h/∂x, ∂h/∂z, J, |∇h|²)   (J again: the surface shader reads one map per pixel; |∇h|²: its mips give the slope variance a filtered lookup loses)
/// Dx and Dz are NOT multiplied by λ (the shader applies λ = −choppiness); J already is the
/// Jacobian of X → X + λD (OceanChannel::Jacobian). Writers fill level 0 only: call
/// generateMipmaps() after upload() / OceanFftGpu::update() before sampling minified.
class OceanTextures {
public:
    /// N texels per side (power of two ≥ 1), `cascades` layers (≥ 1). Needs a current GL context.
    OceanTextures(int resolution, int cascades);

    /// N, texels per side of every layer.
    int resolution() const { return m_n; }
    /// Number of layers (cascades).
    int cascadeCount() const { return m_cascades; }
    /// Mip levels of each texture, log2(N) + 1.
    int mipLevels() const { return m_levels; }

    /// (Dx, h, Dz, J) per texel, one layer per cascade.
    const gfx::Texture& displacement() const { return m_displacement; }
    /// (∂h/∂x, ∂h/∂z, J, 0) per texel, one layer per cascade.
    const gfx::Texture& slopes() const { return m_slopes; }

    /// CPU backend: copies fft's last update() into level 0 of both textures. Cost per call:
    /// an interleave of 2·C·N² RGBA texels into a reused staging array, then 2·C·N²·16 bytes
    /// through glTextureSubImage3D (synchronous copy by the driver: 2 MiB at N = 256, C = 1;
    /// 32 MiB at N = 1024). fft must have this resolution and cascade count.
    void upload(const OceanFftCpu& fft);

    /// CPU backend, the maps' texels made beside their update (OceanFftCpu::setMakeTexels): every
    /// level of both textures, copied as they are (no interleave, no generateMipmaps() after).
    void upload(const OceanTexels& texels);

    /// Rebuilds levels 1… of both textures from level 0 (glGenerateTextureMipmap).
    void generateMipmaps();

    /// Level 0 of displacement(), every layer: floats [layer][j][i][rgba] (tests, dumps;
    /// waits for the GPU).
    std::vector<float> readDisplacement() const;
    /// Level 0 of slopes(), every layer: floats [layer][j][i][rgba] (waits for the GPU).
    std::vector<float> readSlopes() const;

private:
    int m_n = 0;
    int m_cascades = 0;
    int m_levels = 1;
    gfx::Texture m_displacement;
    gfx::Texture m_slopes;
    std::vector<float> m_staging;  // upload(): C·N²·4 floats, reused for both textures
};

} // namespace ob::ocean
