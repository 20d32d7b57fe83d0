// Ripple field on the GPU: the compute-shader twin of RippleField ([Kang2008] eq. 1–2, fixed ring
// or absorbing sponge) and of stampFootprint (eq. 5 then eq. 7), tested against them (docs/references.md#ripple-layer).
#pragma once
#include "gfx/handles.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/sphere_stamp.h"

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace ob::interaction {

/// N×M ripple field in GPU buffers, stepped and stamped by compute shaders. Same layout and
/// semantics as RippleField: row-major floats (index z·M + x), two levels Vh(t), Vh(t−1)
/// ping-ponged (step writes Vh(t+1) over Vh(t−1), then they swap), outer ring held at 0.
///
/// Arithmetic: every float operation of RippleField::step and stampFootprint, in the same
/// order, marked `precise` (no fused multiply-add), with the sponge factors and the eq. 4 PH
/// values computed on the CPU (RippleField::spongeFactor, makeFootprint) and uploaded. GLSL
/// rounds +, −, × correctly, so the result equals the CPU field to the bit where the device
/// keeps denormals (measured on llvmpipe: bit-identical); the tests allow 1e-5 after 100 steps.
///
/// Overlapping stamps: the LAST stamp in list order wins each cell, in both levels — the
/// same result as calling stampFootprint for the list in order on the CPU. A claim pass
/// takes a per-cell atomicMax of (stamp index + 1) over every footprint cell; a write pass
/// lets only the owner write the cell (and reset its claim to 0 for the next call). Every
/// stamp's values depend only on its own inputs (the base is remembered, not read), so the
/// order of writes does not matter. Where footprints do not overlap, each cell is written by
/// its one stamp: the CPU's bits.
///
/// Cost: one dispatch per step, reading Vh(t) 9 times and Vh(t−1) once per cell. On llvmpipe
/// (2-core EPYC, `oceanbox_bench --benchmark_filter=BM_RippleGpu`) a step takes 0.4 / 5 / 20 ms at N = 128 /
/// 512 / 1024 against 0.007 / 0.12 / 0.45 ms for RippleField::step: on a software renderer
/// the CPU field is the faster choice, as for the ocean FFT.
///
/// Needs a current GL 4.3+ context for its whole life.
class RippleFieldGpu {
public:
    /// As RippleField's constructor: rows (N, z) and cols (M, x) >= 1, sponge width clamped to
    /// half the smaller side; both levels 0. Throws ob::RuntimeError if a shader fails to build.
    RippleFieldGpu(int rows, int cols, RippleBoundary boundary = RippleBoundary::Fixed,
                   int spongeWidth = RippleField::DEFAULT_SPONGE_WIDTH);
    ~RippleFieldGpu();
    RippleFieldGpu(const RippleFieldGpu&) = delete;
    RippleFieldGpu& operator=(const RippleFieldGpu&) = delete;

    /// One step of eq. 1–2 with DF in [0, 1] (and the sponge's friction when Absorbing), then
    /// the levels swap. One dispatch; no CPU round trip.
    void step(float damping);

    /// Eq. 5 then eq. 7 for every stamp, the last in list order winning where footprints
    /// overlap (see the class comment). Cells off the field or on its ring are skipped, as on
    /// the CPU. Uploads the list (and any footprint of a new SR), then two dispatches.
    void stamp(std::span<const RippleStamp> stamps);

    /// As RippleField::scroll: the value at (x+dx, z+dz) moves to (x, z) in both levels, new
    /// cells 0, ring 0. Two dispatches into a scratch level.
    void scroll(int dx, int dz);

    /// Sets both levels to 0.
    void clear();

    /// As RippleField::setBoundary; uploads the sponge profile.
    void setBoundary(RippleBoundary boundary, int spongeWidth = RippleField::DEFAULT_SPONGE_WIDTH);

    /// Replaces both levels (N·M values each, row-major).
    void upload(std::span<const float> current, std::span<const float> previous);
    /// Copies both levels of a CPU field of the same size.
    void upload(const RippleField& field) { upload(field.current(), field.previous()); }

    /// Vh(t) into out (resized to N·M). STALLS: waits for every queued dispatch to finish
    /// (the WaterQuery needs this step's heights; prefer beginReadback/finishReadback a step
    /// ahead where a frame of latency is acceptable).
    void readCurrent(std::vector<float>& out) const;
    /// Vh(t−1) into out (resized to N·M). Stalls like readCurrent.
    void readPrevious(std::vector<float>& out) const;

    /// Starts an asynchronous copy of Vh(t) into a staging buffer and fences it; returns at once.
    void beginReadback();
    /// If the copy begun by beginReadback has finished (or `wait`), writes it to out (resized
    /// to N·M) and returns true; otherwise returns false and leaves out alone. False if no
    /// readback is pending.
    bool finishReadback(std::vector<float>& out, bool wait = false);

    /// N: rows (z).
    int rows() const { return m_rows; }
    /// M: columns (x).
    int cols() const { return m_cols; }
    /// The boundary mode in use.
    RippleBoundary boundary() const { return m_boundary; }
    /// Sponge width after clamping (0 for Fixed), cells.
    int spongeWidth() const { return m_spongeWidth; }
    /// The buffer holding Vh(t) now (N·M floats, row-major); it changes at every step.
    const gfx::Buffer& currentBuffer() const { return m_levels[m_cur]; }
    /// The buffer holding Vh(t−1) now.
    const gfx::Buffer& previousBuffer() const { return m_levels[1 - m_cur]; }

private:
    // Footprint of one SR in the PH table: a dense (2·reach+1)² box, −1 outside the disc.
    struct FootprintSlot {
        int offset = 0;  // first float in m_phTable
        int reach = 0;   // half-width of the box, cells
    };
    const FootprintSlot& footprintSlot(float radiusCells);
    void shift(const gfx::Buffer& src, const gfx::Buffer& dst);

    int m_rows, m_cols;
    size_t m_cells;
    RippleBoundary m_boundary = RippleBoundary::Fixed;
    int m_spongeWidth = 0;
    int m_cur = 0;                // index of Vh(t) in m_levels
    GLuint m_stepGroups[2] = {1, 1};  // work groups of ripple_step.comp covering (M, N)
    gfx::Program m_stepProgram;   // ripple_step.comp: eq. 1–2 (mode 0) or a whole-cell shift (mode 1)
    gfx::Program m_stampProgram;  // ripple_stamp.comp: claim pass, then write pass
    gfx::Buffer m_levels[2];      // Vh(t), Vh(t−1); the step writes the second and they swap
    gfx::Buffer m_scratch;        // scroll's destination, swapped in
    gfx::Buffer m_sponge;         // N row factors then M column factors, s(d)
    gfx::Buffer m_owner;          // N·M uint claims of the stamp pass, 0 between calls
    gfx::Buffer m_stamps;         // this call's GpuStamp list
    size_t m_stampCapacity = 0;   // GpuStamps m_stamps holds
    gfx::Buffer m_phBuffer;       // every footprint's PH box, concatenated
    size_t m_phCapacity = 0;      // floats m_phBuffer holds
    std::vector<float> m_phTable; // CPU copy of the PH boxes
    bool m_phDirty = false;
    std::unordered_map<uint32_t, FootprintSlot> m_footprints;  // by the bits of SR
    gfx::Buffer m_staging;        // beginReadback's copy of Vh(t)
    void* m_fence = nullptr;      // GLsync of the pending readback
};

} // namespace ob::interaction
