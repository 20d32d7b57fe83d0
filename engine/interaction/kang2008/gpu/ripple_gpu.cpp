// Ripple field on the GPU: eq. 1–2 step, eq. 5 + 7 stamps and scrolling in compute shaders
// (shaders/ripple_step.comp, shaders/ripple_stamp.comp), the twin of RippleField and
// stampFootprint ([Kang2008]; docs/references.md#ripple-layer). Table 2 stays on the CPU (planSphereStamp).
#include "interaction/kang2008/gpu/ripple_gpu.h"

#include "gfx/shader.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

namespace ob::interaction {

namespace {

// The shaders' buffers, locations, modes and local sizes (shaders/kang2008_bindings.glsl).
#include "kang2008_bindings.glsl"
constexpr int MAX_STAMPS_PER_DISPATCH = 65535;  // GL's guaranteed work-group count per axis

// One stamp as ripple_stamp.comp reads it.
struct GpuStamp {
    int32_t cx, cz, phOffset, reach;
    float base, heightScale, af;
    uint32_t pad;
};
static_assert(sizeof(GpuStamp) == 32, "std430 struct Stamp");

GLsizeiptr floatBytes(size_t count) { return GLsizeiptr(count * sizeof(float)); }

// What the shaders write and what reads them next: more dispatches (storage), buffer reads
// and copies (glGetBufferSubData, glCopyBufferSubData), and uploads from the buffer to a
// texture (pixel unpack).
constexpr GLbitfield WRITE_BARRIERS =
    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT;

} // namespace


RippleFieldGpu::RippleFieldGpu(int rows, int cols, RippleBoundary boundary, int spongeWidth)
    : m_rows(rows), m_cols(cols), m_cells(size_t(rows) * size_t(cols)) {
    assert(rows >= 1 && cols >= 1);
    m_stepProgram = gfx::loadProgram("ripple step (eq. 1-2) / shift", {"ripple_step.comp"});
    m_stampProgram = gfx::loadProgram("ripple stamps (eq. 5, 7)", {"ripple_stamp.comp"});
    // One invocation per cell: as many work groups as the shader's local size needs.
    GLint local[3] = {1, 1, 1};
    glGetProgramiv(m_stepProgram.id(), GL_COMPUTE_WORK_GROUP_SIZE, local);
    m_stepGroups[0] = (GLuint(cols) + GLuint(local[0]) - 1) / GLuint(local[0]);
    m_stepGroups[1] = (GLuint(rows) + GLuint(local[1]) - 1) / GLuint(local[1]);
    // The three level buffers trade roles (step swaps, scroll swaps in the scratch one).
    m_levels[0] = gfx::createBuffer("ripple level 0 (Vh(t), Vh(t-1) or scroll scratch)", floatBytes(m_cells));
    m_levels[1] = gfx::createBuffer("ripple level 1 (Vh(t), Vh(t-1) or scroll scratch)", floatBytes(m_cells));
    m_scratch = gfx::createBuffer("ripple level 2 (Vh(t), Vh(t-1) or scroll scratch)", floatBytes(m_cells));
    m_sponge = gfx::createBuffer("ripple sponge factors (rows, cols)", floatBytes(size_t(rows) + size_t(cols)));
    m_owner = gfx::createBuffer("ripple stamp claims (stamp index + 1)", GLsizeiptr(m_cells * sizeof(uint32_t)));
    m_staging = gfx::createBuffer("ripple readback staging (Vh(t))", floatBytes(m_cells));
    // Storage made without data is undefined until written.
    glClearNamedBufferData(m_owner.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    clear();
    glProgramUniform2i(m_stepProgram.id(), KANG2008_SIZE_LOCATION, cols, rows);
    glProgramUniform2i(m_stampProgram.id(), KANG2008_SIZE_LOCATION, cols, rows);
    setBoundary(boundary, spongeWidth);
}

RippleFieldGpu::~RippleFieldGpu() {
    if (m_fence) glDeleteSync(static_cast<GLsync>(m_fence));
}

void RippleFieldGpu::setBoundary(RippleBoundary boundary, int spongeWidth) {
    m_boundary = boundary;
    m_spongeWidth = 0;
    if (boundary == RippleBoundary::Absorbing) m_spongeWidth = std::clamp(spongeWidth, 0, std::min(m_rows, m_cols) / 2);
    // The CPU's own factors (RippleField::rebuildSponge), so γ has the same bits.
    std::vector<float> factors(size_t(m_rows) + size_t(m_cols));
    for (int z = 0; z < m_rows; ++z) factors[size_t(z)] = RippleField::spongeFactor(std::min(z, m_rows - 1 - z), m_spongeWidth);
    for (int x = 0; x < m_cols; ++x)
        factors[size_t(m_rows + x)] = RippleField::spongeFactor(std::min(x, m_cols - 1 - x), m_spongeWidth);
    glNamedBufferSubData(m_sponge.id(), 0, floatBytes(factors.size()), factors.data());
    glProgramUniform1i(m_stepProgram.id(), KANG2008_SPONGE_LOCATION, m_spongeWidth > 0 ? 1 : 0);
}

void RippleFieldGpu::clear() {
    // Zeros through the same path as upload(): NVIDIA's driver was seen to run a
    // glClearNamedBufferData after a glNamedBufferSubData issued later (H200, driver 580).
    const std::vector<float> zeros(m_cells, 0.0f);
    for (const gfx::Buffer& level : m_levels) glNamedBufferSubData(level.id(), 0, floatBytes(m_cells), zeros.data());
}

void RippleFieldGpu::upload(std::span<const float> current, std::span<const float> previous) {
    assert(current.size() == m_cells && previous.size() == m_cells);
    glNamedBufferSubData(m_levels[m_cur].id(), 0, floatBytes(m_cells), current.data());
    glNamedBufferSubData(m_levels[1 - m_cur].id(), 0, floatBytes(m_cells), previous.data());
}

void RippleFieldGpu::step(float damping) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_CURRENT_BUFFER, m_levels[m_cur].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_PREVIOUS_BUFFER, m_levels[1 - m_cur].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_SPONGE_BUFFER, m_sponge.id());
    glProgramUniform1f(m_stepProgram.id(), KANG2008_DAMPING_LOCATION, damping);
    glProgramUniform1i(m_stepProgram.id(), KANG2008_MODE_LOCATION, KANG2008_MODE_STEP);
    glUseProgram(m_stepProgram.id());
    glDispatchCompute(m_stepGroups[0], m_stepGroups[1], 1);
    glMemoryBarrier(WRITE_BARRIERS);
    glUseProgram(0);
    // --- rotate levels: Vh(t−1) <- Vh(t), Vh(t) <- Vh(t+1)
    m_cur = 1 - m_cur;
}

void RippleFieldGpu::shift(const gfx::Buffer& src, const gfx::Buffer& dst) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_CURRENT_BUFFER, src.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_PREVIOUS_BUFFER, dst.id());
    glDispatchCompute(m_stepGroups[0], m_stepGroups[1], 1);
    glMemoryBarrier(WRITE_BARRIERS);
}

void RippleFieldGpu::scroll(int dx, int dz) {
    if (dx == 0 && dz == 0) return;
    // Clamped so that the shader's source index cannot overflow; beyond the field it reads nothing.
    dx = std::clamp(dx, -m_cols, m_cols);
    dz = std::clamp(dz, -m_rows, m_rows);
    glProgramUniform1i(m_stepProgram.id(), KANG2008_MODE_LOCATION, KANG2008_MODE_SHIFT);
    glProgramUniform2i(m_stepProgram.id(), KANG2008_SHIFT_LOCATION, dx, dz);
    glUseProgram(m_stepProgram.id());
    // Each level goes into the scratch buffer, which takes its place.
    for (int level = 0; level < 2; ++level) {
        shift(m_levels[level], m_scratch);
        std::swap(m_levels[level], m_scratch);
    }
    glUseProgram(0);
}

const RippleFieldGpu::FootprintSlot& RippleFieldGpu::footprintSlot(float radiusCells) {
    const uint32_t key = std::bit_cast<uint32_t>(radiusCells);
    auto it = m_footprints.find(key);
    if (it != m_footprints.end()) return it->second;
    // Eq. 3–4 by makeFootprint (the CPU's PH bits), laid out as a dense box.
    const FootprintProfile fp = makeFootprint(radiusCells);
    FootprintSlot slot;
    slot.offset = int(m_phTable.size());
    slot.reach = fp.rows.empty() ? 0 : -fp.rows.front().dz;
    for (const FootprintRow& r : fp.rows) slot.reach = std::max(slot.reach, -r.dx0);
    const int box = 2 * slot.reach + 1;
    m_phTable.resize(m_phTable.size() + size_t(box) * size_t(box), -1.0f);
    for (const FootprintRow& r : fp.rows)
        for (int k = 0; k < r.count; ++k) {
            const int bx = r.dx0 + k + slot.reach, bz = r.dz + slot.reach;
            m_phTable[size_t(slot.offset + bz * box + bx)] = fp.ph[size_t(r.offset + k)];
        }
    m_phDirty = true;
    return m_footprints.emplace(key, slot).first->second;
}

void RippleFieldGpu::stamp(std::span<const RippleStamp> stamps) {
    // --- the list: footprints looked up (new SRs appended to the PH table), stamps that can
    // touch no interior cell dropped (it keeps list order, so the last still wins)
    std::vector<GpuStamp> list;
    list.reserve(stamps.size());
    int maxBox = 0;
    for (const RippleStamp& s : stamps) {
        if (!(s.radiusCells > 0.0f)) continue;
        const FootprintSlot& slot = footprintSlot(s.radiusCells);
        const int64_t r = slot.reach;
        if (int64_t(s.cx) + r < 1 || int64_t(s.cx) - r > m_cols - 2 || int64_t(s.cz) + r < 1 || int64_t(s.cz) - r > m_rows - 2)
            continue;
        list.push_back({s.cx, s.cz, slot.offset, slot.reach, s.base, s.heightScale, s.accelerationFactor, 0u});
        maxBox = std::max(maxBox, 2 * slot.reach + 1);
    }
    if (list.empty()) return;
    if (m_phDirty) {
        if (m_phTable.size() > m_phCapacity) {
            m_phCapacity = std::max(m_phTable.size(), 2 * m_phCapacity);
            m_phBuffer = gfx::createBuffer("ripple footprint PH boxes (eq. 3-4)", floatBytes(m_phCapacity));
        }
        glNamedBufferSubData(m_phBuffer.id(), 0, floatBytes(m_phTable.size()), m_phTable.data());
        m_phDirty = false;
    }
    if (list.size() > m_stampCapacity) {
        m_stampCapacity = std::max(list.size(), 2 * m_stampCapacity);
        m_stamps = gfx::createBuffer("ripple stamp list", GLsizeiptr(m_stampCapacity * sizeof(GpuStamp)));
    }
    glNamedBufferSubData(m_stamps.id(), 0, GLsizeiptr(list.size() * sizeof(GpuStamp)), list.data());

    // --- claim pass, then write pass (each over every stamp, in chunks of work groups)
    const GLuint groups = (GLuint(maxBox) + KANG2008_STAMP_TILE - 1) / KANG2008_STAMP_TILE;
    const int count = int(list.size());
    const GLuint program = m_stampProgram.id();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_CURRENT_BUFFER, m_levels[m_cur].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_PREVIOUS_BUFFER, m_levels[1 - m_cur].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_STAMPS_BUFFER, m_stamps.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_PH_BUFFER, m_phBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, KANG2008_OWNER_BUFFER, m_owner.id());
    glProgramUniform1i(program, KANG2008_STAMP_COUNT_LOCATION, count);
    glUseProgram(program);
    for (int pass = 0; pass < 2; ++pass) {
        glProgramUniform1i(program, KANG2008_PASS_LOCATION, pass);
        for (int first = 0; first < count; first += MAX_STAMPS_PER_DISPATCH) {
            glProgramUniform1i(program, KANG2008_FIRST_STAMP_LOCATION, first);
            glDispatchCompute(groups, groups, GLuint(std::min(MAX_STAMPS_PER_DISPATCH, count - first)));
        }
        glMemoryBarrier(WRITE_BARRIERS);
    }
    glUseProgram(0);
}

void RippleFieldGpu::readCurrent(std::vector<float>& out) const {
    out.resize(m_cells);
    glGetNamedBufferSubData(m_levels[m_cur].id(), 0, floatBytes(m_cells), out.data());
}

void RippleFieldGpu::readPrevious(std::vector<float>& out) const {
    out.resize(m_cells);
    glGetNamedBufferSubData(m_levels[1 - m_cur].id(), 0, floatBytes(m_cells), out.data());
}

void RippleFieldGpu::beginReadback() {
    if (m_fence) glDeleteSync(static_cast<GLsync>(m_fence));
    glCopyNamedBufferSubData(m_levels[m_cur].id(), m_staging.id(), 0, 0, floatBytes(m_cells));
    m_fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

bool RippleFieldGpu::finishReadback(std::vector<float>& out, bool wait) {
    if (!m_fence) return false;
    const GLsync fence = static_cast<GLsync>(m_fence);
    // Flush on the first check so the fence is sure to signal; wait up to a second when asked.
    const GLuint64 timeout = wait ? 1'000'000'000ull : 0ull;
    GLenum state = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, timeout);
    while (wait && state == GL_TIMEOUT_EXPIRED) state = glClientWaitSync(fence, 0, timeout);
    if (state == GL_TIMEOUT_EXPIRED) return false;
    glDeleteSync(fence);
    m_fence = nullptr;
    out.resize(m_cells);
    glGetNamedBufferSubData(m_staging.id(), 0, floatBytes(m_cells), out.data());
    return true;
}

} // namespace ob::interaction
