// GPU spectral ocean: synthesis (eq. 2, 6, 7, 9) → row FFTs → column FFTs (eq. 1) → unpack
// into OceanTextures with imageStore. docs/references.md#spectral-ocean; [Lee2007] §3.3; [CodingTower].
#include "ocean/gpu/ocean_fft_gpu.h"

#include "core/error.h"
#include "gfx/gpu_bindings.h"
#include "gfx/shader.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/gpu/ocean_textures.h"

#include <cassert>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

namespace ob::ocean {

namespace {

// Shader interface: the bindings and locations of shaders/common_bindings.glsl.
constexpr GLuint MODES_BINDING = gfx::glsl::OCEAN_MODES_BUFFER;
constexpr GLuint QUARTER_BINDING = gfx::glsl::OCEAN_QUARTER_BUFFER;
constexpr GLuint WAVE_NUMBERS_BINDING = gfx::glsl::OCEAN_WAVE_NUMBERS_BUFFER;
constexpr GLuint SPECTRA_BINDING = gfx::glsl::OCEAN_SPECTRA_BUFFER;
constexpr GLuint TWIDDLES_BINDING = gfx::glsl::OCEAN_TWIDDLES_BUFFER;
constexpr GLuint DISPLACEMENT_UNIT = gfx::glsl::OCEAN_DISPLACEMENT_IMAGE;
constexpr GLuint SLOPES_UNIT = gfx::glsl::OCEAN_SLOPES_IMAGE;
constexpr GLint N_LOCATION = gfx::glsl::OCEAN_N_LOCATION;
constexpr GLint TIME_LOCATION = gfx::glsl::OCEAN_TIME_LOCATION;
constexpr GLint LOG2N_LOCATION = gfx::glsl::OCEAN_LOG2N_LOCATION;
constexpr GLint COLUMNS_LOCATION = gfx::glsl::OCEAN_COLUMNS_LOCATION;
constexpr GLint LAMBDA_LOCATION = gfx::glsl::OCEAN_LAMBDA_LOCATION;
constexpr GLuint TILE = 8;             // local size of ocean_spectrum.comp and ocean_unpack.comp, per axis

// One mode's coefficients of h̃ = (cosRe·c + sinRe·s) + i(cosIm·c + sinIm·s), c, s = cos, sin ωt
// (as CascadeSpectrum::refreshMode).
struct ModeCoefficients {
    float cosRe, sinRe, cosIm, sinIm;
};
static_assert(sizeof(ModeCoefficients) == 16, "std430 vec4");

// ω and 1/k of one |K| (std430 struct {double; float; float}).
struct QuarterMode {
    double omega;
    float invK;
    float pad;
};
static_assert(sizeof(QuarterMode) == 16, "std430 struct QuarterMode");

struct Complex {
    float re, im;
};
static_assert(sizeof(Complex) == 8, "std430 vec2");

int signedIndex(int r, int n) { return r < n / 2 ? r : r - n; }

GLintptr bufferBytes(size_t count, size_t size) { return GLintptr(count * size); }

} // namespace

OceanFftGpu::OceanFftGpu(const OceanDef& def) {
    validateOceanDef(def, OceanFftGpu::MAX_RESOLUTION);
    m_n = def.resolution;
    while ((1 << m_log2n) < m_n) ++m_log2n;
    m_lambda = -def.choppiness;
    const size_t n = size_t(m_n), cascades = size_t(def.cascades), quarter = n / 2 + 1;
    m_patchSizes.assign(cascades, 0.0);

    // --- programs
    m_synthesize = gfx::loadProgram("ocean synthesize h~(K,t)", {"ocean_spectrum.comp"});
    m_fft = gfx::loadProgram("ocean inverse FFT lines", {"ocean_fft.comp"});
    m_unpack = gfx::loadProgram("ocean unpack maps", {"ocean_unpack.comp"});

    // --- buffers: per-mode constants (filled by setSpectrum), FFT work space, twiddles
    m_modes = gfx::createBuffer("ocean modes (h~0 coefficients)", bufferBytes(cascades * n * n, sizeof(ModeCoefficients)));
    m_quarter = gfx::createBuffer("ocean quarter grid (omega, 1/k)", bufferBytes(cascades * quarter * quarter, sizeof(QuarterMode)));
    m_waveNumbers = gfx::createBuffer("ocean wave numbers", bufferBytes(cascades * n, sizeof(float)));
    m_spectra = gfx::createBuffer("ocean packed spectra (FFT in place)", bufferBytes(cascades * 4 * n * n, sizeof(Complex)));
    std::vector<Complex> twiddles(n / 2);
    for (size_t k = 0; k < twiddles.size(); ++k) {
        const double angle = 2.0 * std::numbers::pi * double(k) / double(n);
        twiddles[k] = {float(std::cos(angle)), float(std::sin(angle))};
    }
    m_twiddles = gfx::createBuffer("ocean FFT twiddles", bufferBytes(twiddles.size(), sizeof(Complex)), twiddles.data());

    for (int c = 0; c < def.cascades; ++c) setSpectrum(c, CascadeSpectrum(def, c));

    glProgramUniform1i(m_synthesize.id(), N_LOCATION, m_n);
    glProgramUniform1i(m_fft.id(), N_LOCATION, m_n);
    glProgramUniform1i(m_fft.id(), LOG2N_LOCATION, m_log2n);
    glProgramUniform1i(m_unpack.id(), N_LOCATION, m_n);
    glProgramUniform1f(m_unpack.id(), LAMBDA_LOCATION, m_lambda);
}

void OceanFftGpu::setLambda(float lambda) {
    m_lambda = lambda;
    glProgramUniform1f(m_unpack.id(), LAMBDA_LOCATION, m_lambda);
}

void OceanFftGpu::setSpectrum(int cascade, const CascadeSpectrum& s) {
    assert(cascade >= 0 && cascade < cascadeCount() && s.resolution() == m_n);
    const int n = m_n, half = n / 2, quarter = half + 1;
    m_patchSizes[size_t(cascade)] = s.patchSize();

    // Coefficients in FFT order, from a + ib = h̃0(K), p + iq = conj(h̃0(−K)) (the Nyquist row
    // and column are their own mirror and hold 0).
    std::vector<ModeCoefficients> modes(size_t(n) * n);
    for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
            const int sn = signedIndex(col, n), sm = signedIndex(row, n);
            const std::complex<float> h0 = s.h0(sn, sm);
            const std::complex<float> h0Mirror = s.h0(sn == -half ? sn : -sn, sm == -half ? sm : -sm);
            const float a = h0.real(), b = h0.imag(), p = h0Mirror.real(), q = -h0Mirror.imag();
            modes[size_t(row) * n + col] = {a + p, q - b, b + q, a - p};
        }
    }
    // ω and 1/k by |K| (1/k rounded from double, as CascadeSpectrum does).
    std::vector<QuarterMode> quarterModes(size_t(quarter) * quarter);
    for (int m = 0; m < quarter; ++m) {
        for (int q = 0; q < quarter; ++q) {
            const double kx = s.waveNumber(q), kz = s.waveNumber(m);
            const double k = std::sqrt(kx * kx + kz * kz);
            quarterModes[size_t(m) * quarter + q] = {s.omega(q == half ? -half : q, m == half ? -half : m),
                                                     k > 0.0 ? float(1.0 / k) : 0.0f, 0.0f};
        }
    }
    std::vector<float> waveNumbers(static_cast<size_t>(n));
    for (int r = 0; r < n; ++r) waveNumbers[size_t(r)] = float(s.waveNumber(signedIndex(r, n)));

    const size_t c = size_t(cascade);
    glNamedBufferSubData(m_modes.id(), bufferBytes(c * modes.size(), sizeof(ModeCoefficients)),
                         bufferBytes(modes.size(), sizeof(ModeCoefficients)), modes.data());
    glNamedBufferSubData(m_quarter.id(), bufferBytes(c * quarterModes.size(), sizeof(QuarterMode)),
                         bufferBytes(quarterModes.size(), sizeof(QuarterMode)), quarterModes.data());
    glNamedBufferSubData(m_waveNumbers.id(), bufferBytes(c * waveNumbers.size(), sizeof(float)),
                         bufferBytes(waveNumbers.size(), sizeof(float)), waveNumbers.data());
}

void OceanFftGpu::update(double t, OceanTextures& out) {
    assert(out.resolution() == m_n && out.cascadeCount() == cascadeCount());
    m_time = t;
    const GLuint n = GLuint(m_n), cascades = GLuint(cascadeCount());
    const GLuint tiles = (n + TILE - 1) / TILE;
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, MODES_BINDING, m_modes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, QUARTER_BINDING, m_quarter.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, WAVE_NUMBERS_BINDING, m_waveNumbers.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SPECTRA_BINDING, m_spectra.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, TWIDDLES_BINDING, m_twiddles.id());

    // --- stage 1: the four packed spectra at time t (eq. 2, 6, 7, 9), one invocation per mode
    glProgramUniform1d(m_synthesize.id(), TIME_LOCATION, t);
    glUseProgram(m_synthesize.id());
    glDispatchCompute(tiles, tiles, cascades);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // --- stage 2: inverse FFT of every row, then of every column (eq. 1), in place
    std::chrono::steady_clock::time_point fftStart;
    if (m_profiling) {
        glFinish();
        fftStart = std::chrono::steady_clock::now();
    }
    glUseProgram(m_fft.id());
    for (int columns = 0; columns < 2; ++columns) {
        glProgramUniform1i(m_fft.id(), COLUMNS_LOCATION, columns);
        glDispatchCompute(n, OCEAN_PACKED_TRANSFORMS, cascades);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    if (m_profiling) {
        glFinish();
        m_transformMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - fftStart).count();
    }

    // --- stage 3: unpack into the map layers and the Jacobian
    glUseProgram(m_unpack.id());
    glBindImageTexture(DISPLACEMENT_UNIT, out.displacement().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(SLOPES_UNIT, out.slopes().id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(tiles, tiles, cascades);
    // Readers of the maps: texture sampling, glGetTextureImage, mip generation (a blit or a
    // draw, depending on the driver), image loads; the next update()'s stage 1 overwrites the
    // spectra stage 3 read.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace ob::ocean
