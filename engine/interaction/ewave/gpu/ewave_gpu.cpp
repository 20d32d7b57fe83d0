// Dispersive ripple field on the GPU: e^{+} line FFTs (shaders/ocean_fft.comp), the exact
// per-mode rotation and the real-space boundary (shaders/ewave_step.comp). docs/references.md#dispersive-ripples.
#include "interaction/ewave/gpu/ewave_gpu.h"

#include "gfx/gpu_bindings.h"
#include "gfx/shader.h"

#include <cassert>
#include <cmath>
#include <numbers>
#include <utility>

namespace ob::interaction {

namespace {

// The step's buffers, locations, modes and local size (shaders/ewave_bindings.glsl); the line
// FFTs are the ocean's program (shaders/common_bindings.glsl).
#include "ewave_bindings.glsl"
using gfx::glsl::OCEAN_COLUMNS_LOCATION;
using gfx::glsl::OCEAN_LOG2N_LOCATION;
using gfx::glsl::OCEAN_N_LOCATION;
using gfx::glsl::OCEAN_SPECTRA_BUFFER;
using gfx::glsl::OCEAN_TWIDDLES_BUFFER;

struct Rotation {
    float a, b, c, pad;
};
static_assert(sizeof(Rotation) == 16, "std430 vec4");

GLsizeiptr bytes(size_t count, size_t size) { return GLsizeiptr(count * size); }

} // namespace


bool EWaveGpu::supports(int rows, int cols) {
    return rows == cols && rows >= 4 && rows <= MAX_RESOLUTION && (rows & (rows - 1)) == 0;
}

EWaveGpu::EWaveGpu(const EWaveField& like)
    : m_n(like.rows()), m_cellSize(like.cellSize()), m_boundary(like.boundary()), m_spongeWidth(like.spongeWidth()) {
    assert(supports(like.rows(), like.cols()));
    while ((1 << m_log2n) < m_n) ++m_log2n;
    const size_t n = size_t(m_n), cells = n * n, quarter = n / 2 + 1;
    m_fft = gfx::loadProgram("ewave FFT lines", {"ocean_fft.comp"});
    m_step = gfx::loadProgram("ewave mode rotation / boundary", {"ewave_step.comp"});
    m_fields[0] = gfx::createBuffer("ewave state w = h - i v (or spectrum)", bytes(cells, 2 * sizeof(float)));
    m_fields[1] = gfx::createBuffer("ewave state w = h - i v (or spectrum)", bytes(cells, 2 * sizeof(float)));
    m_rotation = gfx::createBuffer("ewave mode rotation (a, b, c)", bytes(quarter * quarter, sizeof(Rotation)));
    m_sponge = gfx::createBuffer("ewave sponge factors", bytes(m_boundary == RippleBoundary::Absorbing ? cells : 1, sizeof(float)));
    m_groups = (GLuint(m_n) + EWAVE_TILE - 1) / EWAVE_TILE;
    m_sum = gfx::createBuffer("ewave sums of h per work group, their total", bytes(size_t(m_groups) * m_groups + 1, sizeof(float)));
    // The ocean's twiddles: exp(+2πi·k/N) rounded from double.
    std::vector<float> twiddles(n);
    for (size_t k = 0; k < n / 2; ++k) {
        const double angle = 2.0 * std::numbers::pi * double(k) / double(n);
        twiddles[2 * k] = float(std::cos(angle));
        twiddles[2 * k + 1] = float(std::sin(angle));
    }
    m_twiddles = gfx::createBuffer("ewave FFT twiddles", bytes(n, sizeof(float)), twiddles.data());
    glProgramUniform1i(m_fft.id(), OCEAN_N_LOCATION, m_n);
    glProgramUniform1i(m_fft.id(), OCEAN_LOG2N_LOCATION, m_log2n);
    glProgramUniform1i(m_step.id(), EWAVE_N_LOCATION, m_n);
    m_medium = like.medium();
    setDamping(like.decayTime(), like.viscosity());
    upload(like);
}

void EWaveGpu::setDamping(float decayTime, float viscosity) {
    assert(decayTime >= 0.0f && viscosity >= 0.0f);
    if (decayTime == m_decayTime && viscosity == m_viscosity) return;
    m_decayTime = decayTime;
    m_viscosity = viscosity;
    m_preparedDt = -1.0f;
}

// The CPU's coefficients (EWaveField::modeStep in double, 1/N² folded in) per |K|, rounded to
// float; the sponge factors are the CPU's own floats.
void EWaveGpu::prepare(float dt) {
    const int half = m_n / 2, quarter = half + 1;
    const double norm = 1.0 / (double(m_n) * double(m_n));
    const double dk = 2.0 * std::numbers::pi / (double(m_n) * m_cellSize);
    std::vector<Rotation> rotation(size_t(quarter) * size_t(quarter));
    for (int j = 0; j < quarter; ++j) {
        const double kz = dk * j;
        for (int i = 0; i < quarter; ++i) {
            const double kx = dk * i;
            const EWaveField::ModeStep s = EWaveField::modeStep(m_medium, std::sqrt(kx * kx + kz * kz), dt, m_decayTime, m_viscosity, norm);
            rotation[size_t(j) * size_t(quarter) + size_t(i)] = {float(s.a), float(s.b), float(s.c), 0.0f};
        }
    }
    glNamedBufferSubData(m_rotation.id(), 0, bytes(rotation.size(), sizeof(Rotation)), rotation.data());
    if (m_boundary == RippleBoundary::Absorbing) {
        const std::vector<float> sponge = EWaveField::spongeFactors(m_n, m_n, m_spongeWidth, dt);
        glNamedBufferSubData(m_sponge.id(), 0, bytes(sponge.size(), sizeof(float)), sponge.data());
    }
    m_preparedDt = dt;
}

void EWaveGpu::transform(const gfx::Buffer& field) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, OCEAN_SPECTRA_BUFFER, field.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, OCEAN_TWIDDLES_BUFFER, m_twiddles.id());
    glUseProgram(m_fft.id());
    for (int columns = 0; columns < 2; ++columns) {
        glProgramUniform1i(m_fft.id(), OCEAN_COLUMNS_LOCATION, columns);
        glDispatchCompute(GLuint(m_n), 1, 1);  // one line per work group; plane 0
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

void EWaveGpu::step(float dt) {
    assert(dt > 0.0f);
    if (dt != m_preparedDt) prepare(dt);
    // --- forward: S = conj Z, in place
    transform(m_fields[0]);
    // --- every mode rotated and damped: Y = conj Z'(−K) into the other buffer
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EWAVE_SPECTRUM_BUFFER, m_fields[0].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EWAVE_FIELD_BUFFER, m_fields[1].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EWAVE_ROTATION_BUFFER, m_rotation.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EWAVE_SPONGE_BUFFER, m_sponge.id());
    glProgramUniform1i(m_step.id(), EWAVE_MODE_LOCATION, EWAVE_MODE_ROTATE);
    glUseProgram(m_step.id());
    glDispatchCompute(m_groups, m_groups, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    // --- back: w' = h' − i·v', in place
    transform(m_fields[1]);
    // --- the boundary in real space
    if (m_boundary == RippleBoundary::Fixed) {
        dispatchStep(EWAVE_MODE_RING, m_groups);
    } else if (m_boundary == RippleBoundary::Absorbing) {
        // The sponge towards the level with Σh per work group, their total, h shifted back to the
        // level: the volume kept (EWaveField::conserveVolume; periodic keeps it in the mode pass).
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EWAVE_SUM_BUFFER, m_sum.id());
        glProgramUniform1f(m_step.id(), EWAVE_LEVEL_LOCATION, float(m_level));
        dispatchStep(EWAVE_MODE_SPONGE, m_groups);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        dispatchStep(EWAVE_MODE_TOTAL, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        dispatchStep(EWAVE_MODE_RESTORE, m_groups);
    }
    // Readers of the state: the next step's dispatches, download (glGetNamedBufferSubData) and
    // upload (glNamedBufferSubData, which must not overtake this step's reads).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    std::swap(m_fields[0], m_fields[1]);
}

void EWaveGpu::dispatchStep(int mode, GLuint groups) {
    glProgramUniform1i(m_step.id(), EWAVE_MODE_LOCATION, mode);
    glUseProgram(m_step.id());
    glDispatchCompute(groups, groups, 1);
}

void EWaveGpu::upload(std::span<const double> h, std::span<const double> v) {
    const size_t cells = size_t(m_n) * size_t(m_n);
    assert(h.size() == cells && v.size() == cells);
    double volume = 0.0;  // in index order, as EWaveField counts it
    for (double x : h) volume += x;
    m_level = volume / double(cells);
    m_staging.resize(2 * cells);
    for (size_t i = 0; i < cells; ++i) {
        m_staging[2 * i] = float(h[i]);
        m_staging[2 * i + 1] = -float(v[i]);
    }
    glNamedBufferSubData(m_fields[0].id(), 0, bytes(m_staging.size(), sizeof(float)), m_staging.data());
}

void EWaveGpu::download(std::span<double> h, std::span<double> v) const {
    const size_t cells = size_t(m_n) * size_t(m_n);
    assert(h.size() == cells && v.size() == cells);
    m_staging.resize(2 * cells);
    glGetNamedBufferSubData(m_fields[0].id(), 0, bytes(m_staging.size(), sizeof(float)), m_staging.data());
    for (size_t i = 0; i < cells; ++i) {
        h[i] = m_staging[2 * i];
        v[i] = -double(m_staging[2 * i + 1]);
    }
}

} // namespace ob::interaction
