// Ocean displacement and slope texture arrays: creation, CPU upload, mips, read-back.
#include "ocean/gpu/ocean_textures.h"

#include "ocean/ocean_fft_cpu.h"
#include "ocean/ocean_texels.h"

#include <cassert>

namespace ob::ocean {

namespace {

gfx::Texture createMap(const char* label, int n, int layers, int levels) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glTextureStorage3D(id, levels, GL_RGBA32F, n, n, layers);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glObjectLabel(GL_TEXTURE, id, -1, label);
    return gfx::Texture(id);
}

std::vector<float> readLevel0(const gfx::Texture& texture, int n, int layers) {
    std::vector<float> out(size_t(n) * size_t(n) * size_t(layers) * 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
    return out;
}

} // namespace

OceanTextures::OceanTextures(int resolution, int cascades) : m_n(resolution), m_cascades(cascades) {
    assert(resolution > 0 && (resolution & (resolution - 1)) == 0 && cascades >= 1);
    while ((1 << (m_levels - 1)) < m_n) ++m_levels;
    m_displacement = createMap("ocean displacement (Dx, h, Dz, J)", m_n, m_cascades, m_levels);
    m_slopes = createMap("ocean slopes (dh/dx, dh/dz, J)", m_n, m_cascades, m_levels);
}

void OceanTextures::upload(const OceanFftCpu& fft) {
    assert(fft.resolution() == m_n && fft.cascadeCount() == m_cascades);
    const size_t texels = size_t(m_n) * size_t(m_n);
    m_staging.resize(texels * size_t(m_cascades) * 4);
    // --- displacement: (Dx, h, Dz, J)
    for (int c = 0; c < m_cascades; ++c) {
        const float* dx = fft.channel(c, OceanChannel::DispX);
        const float* h = fft.channel(c, OceanChannel::Height);
        const float* dz = fft.channel(c, OceanChannel::DispZ);
        const float* jac = fft.channel(c, OceanChannel::Jacobian);
        float* out = m_staging.data() + texels * size_t(c) * 4;
        for (size_t p = 0; p < texels; ++p) {
            out[4 * p] = dx[p];
            out[4 * p + 1] = h[p];
            out[4 * p + 2] = dz[p];
            out[4 * p + 3] = jac[p];
        }
    }
    glTextureSubImage3D(m_displacement.id(), 0, 0, 0, 0, m_n, m_n, m_cascades, GL_RGBA, GL_FLOAT, m_staging.data());
    // --- slopes: (∂h/∂x, ∂h/∂z, J, |∇h|²) (ocean_unpack.comp); the driver has copied the staging array on return
    for (int c = 0; c < m_cascades; ++c) {
        const float* sx = fft.channel(c, OceanChannel::SlopeX);
        const float* sz = fft.channel(c, OceanChannel::SlopeZ);
        const float* jac = fft.channel(c, OceanChannel::Jacobian);
        float* out = m_staging.data() + texels * size_t(c) * 4;
        for (size_t p = 0; p < texels; ++p) {
            out[4 * p] = sx[p];
            out[4 * p + 1] = sz[p];
            out[4 * p + 2] = jac[p];
            out[4 * p + 3] = sx[p] * sx[p] + sz[p] * sz[p];
        }
    }
    glTextureSubImage3D(m_slopes.id(), 0, 0, 0, 0, m_n, m_n, m_cascades, GL_RGBA, GL_FLOAT, m_staging.data());
}

void OceanTextures::upload(const OceanTexels& texels) {
    assert(texels.resolution == m_n && texels.cascades == m_cascades && texels.levels == m_levels);
    for (int l = 0; l < m_levels; ++l) {
        const int n = m_n >> l;
        const size_t offset = texels.levelOffset(l);
        glTextureSubImage3D(m_displacement.id(), l, 0, 0, 0, n, n, m_cascades, GL_RGBA, GL_FLOAT, texels.displacement.data() + offset);
        glTextureSubImage3D(m_slopes.id(), l, 0, 0, 0, n, n, m_cascades, GL_RGBA, GL_FLOAT, texels.slopes.data() + offset);
    }
}

void OceanTextures::generateMipmaps() {
    glGenerateTextureMipmap(m_displacement.id());
    glGenerateTextureMipmap(m_slopes.id());
}

std::vector<float> OceanTextures::readDisplacement() const { return readLevel0(m_displacement, m_n, m_cascades); }

std::vector<float> OceanTextures::readSlopes() const { return readLevel0(m_slopes, m_n, m_cascades); }

} // namespace ob::ocean
