// CPU spectral ocean: synthesis (eq. 2, 6, 7) → four packed inverse FFTs (eq. 1, 9, FFTW) →
// SoA channels and the foam Jacobian. docs/references.md#spectral-ocean; [Lee2007] §2.1, §3.3; [CodingTower] "Future".
#include "core/simd.h"
#include "ocean/ocean_fft_cpu.h"

#include "core/error.h"
#include "core/log.h"
#include "core/parallel.h"
#include "core/thread_choice.h"
#include "core/fftw_wisdom.h"

#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <string>
#include <algorithm>
#include <tuple>
#include <fcntl.h>
#include <fftw3.h>
#include <sys/file.h>
#include <unistd.h>


namespace ob::ocean {

namespace {

// update() may split over threads (up to MAX_THREADS, one whole transform each at a time, so
// the bits do not depend on the count) from this N on; whether it pays is measured per size
// (measuredThreads). Below it a thread's start costs more than the update (2-core EPYC, FFTW
// 3.3.10: N = 64 takes 0.03 ms on one thread, 0.08 ms on two).
constexpr int PARALLEL_MIN_N = 128;
constexpr unsigned MAX_THREADS = 4;
constexpr int FFT_BLOCK = 16;  // see spectrum.cpp: whole blocks vectorise at -O2

// The one N×N in-place backward plan, from the shared wisdom (see fftw_wisdom.h): different
// FFTW plans of the same transform round differently (measured: FFTW_ESTIMATE, _MEASURE and
// _PATIENT plans of 256² disagree in the last bits), so every run must use the same one.
fftwf_plan plan(int n, fftwf_complex* buffer) {
    return planWithWisdom([&](unsigned flags) { return fftwf_plan_dft_2d(n, n, buffer, buffer, FFTW_BACKWARD, flags); });
}

// Packed pairs → SoA channels, and J from the three displacement derivatives.
[[gnu::always_inline]] inline void unpackPoint(
    const float* __restrict p0, const float* __restrict p1, const float* __restrict p2,
    const float* __restrict p3, float* __restrict h, float* __restrict dx, float* __restrict dz,
    float* __restrict sx, float* __restrict sz, float* __restrict jac, float lambda, int i) {
    h[i] = p0[2 * i];
    dx[i] = p1[2 * i];
    dz[i] = p1[2 * i + 1];
    sx[i] = p2[2 * i];
    sz[i] = p2[2 * i + 1];
    const float dxz = lambda * p0[2 * i + 1];
    jac[i] = (1.0f + lambda * p3[2 * i]) * (1.0f + lambda * p3[2 * i + 1]) - dxz * dxz;
}

OB_VECTOR_KERNEL void unpackRange(
    const float* __restrict p0, const float* __restrict p1, const float* __restrict p2,
    const float* __restrict p3, float* __restrict h, float* __restrict dx, float* __restrict dz,
    float* __restrict sx, float* __restrict sz, float* __restrict jac, float lambda, int count) {
    int base = 0;
    for (; base + FFT_BLOCK <= count; base += FFT_BLOCK)
        for (int q = 0; q < FFT_BLOCK; ++q)
            unpackPoint(p0, p1, p2, p3, h, dx, dz, sx, sz, jac, lambda, base + q);
    for (int i = base; i < count; ++i)
        unpackPoint(p0, p1, p2, p3, h, dx, dz, sx, sz, jac, lambda, i);
}

} // namespace

struct OceanFftCpu::Cascade {
    CascadeSpectrum spectrum;
    VelocityBands bands;
    fftwf_complex* buffers[OCEAN_PACKED_TRANSFORMS] = {};  // PackedSpectra order, in place
    std::vector<fftwf_complex*> velocity;                  // bands.transforms() of them, in place
    std::vector<float> planes[OCEAN_CHANNEL_COUNT];

    Cascade(const OceanDef& def, int c)
        : spectrum(def, c), bands(ocean::velocityBands(def.resolution, cascadePatchSize(def, c), cascadeBand(def, c))) {
        const size_t count = size_t(def.resolution) * size_t(def.resolution);
        const auto allocate = [count] {
            fftwf_complex* buffer = fftwf_alloc_complex(count);
            if (!buffer) throw RuntimeError("out of memory for the ocean FFT buffers");
            std::memset(buffer, 0, count * sizeof(fftwf_complex));
            return buffer;
        };
        for (auto& buffer : buffers) buffer = allocate();
        velocity.resize(size_t(bands.transforms()), nullptr);
        for (auto& buffer : velocity) buffer = allocate();
        for (auto& plane : planes) plane.assign(count, 0.0f);
    }
    ~Cascade() {
        for (auto* buffer : buffers) fftwf_free(buffer);
        for (auto* buffer : velocity) fftwf_free(buffer);
    }
    Cascade(const Cascade&) = delete;
    Cascade& operator=(const Cascade&) = delete;
};

OceanFftCpu::OceanFftCpu(const OceanDef& def, int threads) {
    validateOceanDef(def, 4096);
    m_n = def.resolution;
    m_lambda = -def.choppiness;
    for (int c = 0; c < def.cascades; ++c) {
        m_cascades.push_back(std::make_unique<Cascade>(def, c));
        for (fftwf_complex* buffer : m_cascades.back()->velocity) m_velocityBuffers.push_back(reinterpret_cast<float*>(buffer));
    }

    // One plan serves every buffer: same size, in place, fftwf_alloc alignment.
    m_plan = plan(m_n, m_cascades[0]->buffers[0]);
    if (!m_plan) throw RuntimeError("FFTW could not plan a " + std::to_string(m_n) + "² transform");

    // Auto: the thread count measured for this size (updates at t = 0, alternating 1 and all
    // cores; the maps are cleared after, so nothing depends on whether it was measured here).
    const int cores = std::clamp(workerCount(), 1, int(MAX_THREADS));
    m_threads = threads > 0 ? threads : 1;
    if (threads <= 0 && m_n >= PARALLEL_MIN_N) {
        const std::string key = "ocean " + std::to_string(m_n) + "² ×" + std::to_string(def.cascades);
        m_threads = measuredThreads(key, cores, [&](int n) {
            m_threads = n;
            update(0.0);
        });
        for (auto& c : m_cascades) {
            for (auto* buffer : c->buffers) std::memset(buffer, 0, size_t(m_n) * size_t(m_n) * sizeof(fftwf_complex));
            for (auto* buffer : c->velocity) std::memset(buffer, 0, size_t(m_n) * size_t(m_n) * sizeof(fftwf_complex));
            for (auto& plane : c->planes) std::fill(plane.begin(), plane.end(), 0.0f);
        }
        m_time = 0.0;
        m_velocityTime = -1.0;
        m_stageMs = {};
    }
}

OceanFftCpu::~OceanFftCpu() {
    std::lock_guard<std::mutex> lock(fftwPlannerMutex());
    if (m_plan) fftwf_destroy_plan(m_plan);
}

double OceanFftCpu::patchSize(int cascade) const { return spectrum(cascade).patchSize(); }

CascadeSpectrum& OceanFftCpu::spectrum(int cascade) {
    assert(cascade >= 0 && cascade < cascadeCount());
    return m_cascades[cascade]->spectrum;
}

const CascadeSpectrum& OceanFftCpu::spectrum(int cascade) const {
    assert(cascade >= 0 && cascade < cascadeCount());
    return m_cascades[cascade]->spectrum;
}

DisplacementBounds OceanFftCpu::displacementBounds() const {
    DisplacementBounds bounds;
    const size_t count = size_t(m_n) * size_t(m_n);
    const OceanTexels* made = texels();  // their pass found them already
    for (int c = 0; c < cascadeCount(); ++c) {
        float hi = 0.0f, lo = 0.0f, d2 = 0.0f;
        if (made) {
            const OceanTexels::Extremes& e = made->extremes[size_t(c)];
            hi = e.hi, lo = e.lo, d2 = e.d2;
        } else {
            const float *h = channel(c, OceanChannel::Height), *dx = channel(c, OceanChannel::DispX), *dz = channel(c, OceanChannel::DispZ);
            for (size_t i = 0; i < count; ++i) {
                hi = std::max(hi, h[i]);
                lo = std::min(lo, h[i]);
                d2 = std::max(d2, dx[i] * dx[i] + dz[i] * dz[i]);
            }
        }
        bounds += {hi, -lo, std::abs(m_lambda) * std::sqrt(d2)};
    }
    return bounds;
}

const float* OceanFftCpu::channel(int cascade, OceanChannel ch) const {
    assert(cascade >= 0 && cascade < cascadeCount());
    return m_cascades[cascade]->planes[int(ch)].data();
}

const VelocityBands& OceanFftCpu::velocityBands(int cascade) const {
    assert(cascade >= 0 && cascade < cascadeCount());
    return m_cascades[cascade]->bands;
}

const float* OceanFftCpu::velocityPacked(int cascade, int k) const {
    assert(cascade >= 0 && cascade < cascadeCount() && k >= 0 && k < m_cascades[cascade]->bands.transforms());
    return m_velocityTime == m_time ? reinterpret_cast<const float*>(m_cascades[cascade]->velocity[size_t(k)]) : nullptr;
}

const float* OceanFftCpu::packed(int cascade, int k) const {
    assert(cascade >= 0 && cascade < cascadeCount() && k >= 0 && k < OCEAN_PACKED_TRANSFORMS);
    return reinterpret_cast<const float*>(m_cascades[cascade]->buffers[k]);
}

void OceanFftCpu::fillDump(int cascade, float* out) const {
    assert(cascade >= 0 && cascade < cascadeCount());
    const Cascade& c = *m_cascades[cascade];
    const size_t count = size_t(m_n) * size_t(m_n);
    for (size_t p = 0; p < count; ++p)
        for (int k = 0; k < OCEAN_DUMP_CHANNELS; ++k) out[p * OCEAN_DUMP_CHANNELS + k] = c.planes[k][p];
}

void OceanFftCpu::synthesizeRows(int pairBegin, int pairEnd) {
    for (auto& c : m_cascades) {
        PackedSpectra out;
        out.heightDxz = reinterpret_cast<float*>(c->buffers[0]);
        out.dispXZ = reinterpret_cast<float*>(c->buffers[1]);
        out.slopeXZ = reinterpret_cast<float*>(c->buffers[2]);
        out.dxxDzz = reinterpret_cast<float*>(c->buffers[3]);
        c->spectrum.synthesize(m_time, pairBegin, pairEnd, out);
        if (m_velocityBands && !c->velocity.empty())
            c->spectrum.synthesizeVelocity(m_time, pairBegin, pairEnd, c->bands, reinterpret_cast<float* const*>(c->velocity.data()));
    }
}

// The height transforms of every cascade, then (bands on) every cascade's velocity transforms.
int OceanFftCpu::transformCount() const {
    return cascadeCount() * OCEAN_PACKED_TRANSFORMS + (m_velocityBands ? int(m_velocityBuffers.size()) : 0);
}

void OceanFftCpu::transform(int index) {
    const int heights = cascadeCount() * OCEAN_PACKED_TRANSFORMS;
    fftwf_complex* buffer = index < heights
                                ? m_cascades[index / OCEAN_PACKED_TRANSFORMS]->buffers[index % OCEAN_PACKED_TRANSFORMS]
                                : reinterpret_cast<fftwf_complex*>(m_velocityBuffers[size_t(index - heights)]);
    fftwf_execute_dft(m_plan, buffer, buffer);
}

void OceanFftCpu::unpackRows(int rowBegin, int rowEnd) {
    const size_t off = size_t(rowBegin) * m_n;
    const int count = (rowEnd - rowBegin) * m_n;
    for (auto& c : m_cascades) {
        const auto pair = [&](int k) { return reinterpret_cast<const float*>(c->buffers[k]) + 2 * off; };
        const auto plane = [&](OceanChannel ch) { return c->planes[int(ch)].data() + off; };
        unpackRange(pair(0), pair(1), pair(2), pair(3), plane(OceanChannel::Height),
                    plane(OceanChannel::DispX), plane(OceanChannel::DispZ), plane(OceanChannel::SlopeX),
                    plane(OceanChannel::SlopeZ), plane(OceanChannel::Jacobian), m_lambda, count);
    }
}

void OceanFftCpu::update(double t) {
    updateMaps(t);
    if (m_texels) m_texels->fill(*this);
}

void OceanFftCpu::setMakeTexels(bool on) {
    if (on && !m_texels) m_texels = std::make_unique<OceanTexels>();
    if (!on) m_texels.reset();
}

void OceanFftCpu::updateMaps(double t) {
    m_time = t;
    m_velocityTime = m_velocityBands ? t : -1.0;
    const int transforms = transformCount();
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    Clock::time_point marks[4];
    if (m_threads == 1) {
        marks[0] = Clock::now();
        synthesizeRows(0, m_n / 2 + 1);
        marks[1] = Clock::now();
        for (int k = 0; k < transforms; ++k) transform(k);
        marks[2] = Clock::now();
        unpackRows(0, m_n);
        marks[3] = Clock::now();
        m_stageMs = {ms(marks[0], marks[1]), ms(marks[1], marks[2]), ms(marks[2], marks[3])};
        return;
    }
    // The three stages on the worker pool, the end of each a barrier (a transform reads every
    // row, a row of the output depends on every mode). Chunks are claimed as workers come, so
    // a worker that wakes late leaves its chunks to the caller instead of making it wait.
    const int pairs = m_n / 2 + 1;
    marks[0] = Clock::now();
    // --- stage 1: packed spectra at time t (eq. 2, 6, 7; eq. 9 packing), by row pairs {m, −m}
    parallelFor(0, pairs, std::max(1, pairs / m_threads), [&](int b, int e) { synthesizeRows(b, e); });
    marks[1] = Clock::now();
    // --- stage 2: unnormalised inverse FFTs (eq. 1), whole transforms per chunk
    parallelFor(0, transforms, std::max(1, transforms / m_threads), [&](int b, int e) {
        for (int k = b; k < e; ++k) transform(k);
    });
    marks[2] = Clock::now();
    // --- stage 3: unpack to channels and the Jacobian, by rows
    parallelFor(0, m_n, std::max(1, m_n / m_threads), [&](int b, int e) { unpackRows(b, e); });
    marks[3] = Clock::now();
    m_stageMs = {ms(marks[0], marks[1]), ms(marks[1], marks[2]), ms(marks[2], marks[3])};
}

} // namespace ob::ocean
