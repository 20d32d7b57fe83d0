// The jumping-fish swarm of [Kang2008] Table 5: one bounding sphere per fish on a ballistic jump
// arc through the water over a ripple field, stamped by Table 2 and eq. 3–7 (docs/references.md#ripple-layer, docs/references.md#paper-experiments).
#pragma once
#include "environment/environment_def.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/sphere_stamp.h"
#include "interaction/kang2008/stamp_batch.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace ob::game {

/// How the swarm's spheres reach the field.
enum class StampMode : uint8_t {
    Batched,     ///< Table 2 in parallel, stamps queued in fish order in a StampBatch, applied once
    Sequential,  ///< stepSphere per fish, in order: the reference the batch must match bit for bit
};

/// The swarm. Defaults are the paper's fish (docs/references.md#ripple-layer: SHR 1.4, AF −0.3, DF 0.93) on its
/// 128² field with SR 20.
struct FishSwarmDef {
    int count = 1000;                  ///< fish (one sphere each), >= 0
    int field = 128;                   ///< ripple field cells per side, >= 3
    float radius_cells = 20.0f;        ///< SR, sphere radius in cells, > 0
    float cell_size = 0.25f;           ///< Δ, m per cell, > 0
    float height_ratio = 1.4f;         ///< SHR, > 0
    float acceleration_factor = -0.3f; ///< AF of eq. 7, fixed
    float damping = 0.93f;             ///< DF of eq. 2, [0, 1]
    float step_hz = 60.0f;             ///< simulation steps per second
    uint64_t seed = 1;                 ///< positions, headings, speeds and arc phases
    float gravity = environment::EnvironmentDef{}.gravity;  ///< g of the jump arcs, m/s², > 0 (a scene's environment.gravity)
    StampMode mode = StampMode::Batched;
};

/// Fish jump from a depth of 2R below the still surface (y = 0) to 2R above it and back, R
/// the sphere radius in metres, under the Def's g (period 2·sqrt(16R/g): 4 s for R = 5 m, g = 9.81 m/s²),
/// each at its own phase, and swim 0.5–2 m/s in a fixed heading, bouncing off the field's
/// edges. A fish sees the water surface as y = 0 plus Vh(t) at its centre cell as it was at the
/// start of the step (all fish see the same water, whatever their order). SD follows the
/// vertical velocity (+1 rising, −1 falling). The field has the fixed boundary.
class FishSwarm {
public:
    explicit FishSwarm(const FishSwarmDef& def);

    /// One step: Table 2 and the stamps in fish order ([Kang2008]: stamp, then move), the fish
    /// move, then the convolution step (eq. 1–2). Allocates nothing once the batch has grown.
    /// Batched, the moves run in the Table 2 pass (their time counts as stamping).
    void step();

    /// Wall ms of the last step's phases.
    struct Timings {
        double stamp = 0.0;  ///< Table 2 + eq. 5, 7 (both modes)
        double move = 0.0;   ///< ballistic arcs
        double step = 0.0;   ///< eq. 1–2
    };
    const Timings& lastTimings() const { return m_timings; }
    /// Spheres that stamped in the last step.
    int lastStamps() const { return m_lastStamps; }

    /// The ripple field the fish stamp.
    const interaction::RippleField& field() const { return m_field; }
    /// Table 2 state of each fish's sphere, in fish order.
    const std::vector<interaction::SphereContact>& contacts() const { return m_contacts; }
    /// The settings it was built with.
    const FishSwarmDef& def() const { return m_def; }
    /// Centre of fish i, world m: x = column·Δ, z = row·Δ (cell (0, 0) at the origin), y up.
    float worldX(size_t i) const { return m_gx[i] * m_def.cell_size; }
    float worldZ(size_t i) const { return m_gz[i] * m_def.cell_size; }
    float worldY(size_t i) const { return m_y[i]; }

private:
    void stepBatched();
    void moveFish(size_t i);
    // First fish of chunk c of the parallel passes (c = chunk count: one past the last fish).
    size_t chunkBegin(int c) const { return size_t(m_def.count) * size_t(c) / m_chunkStamping.size(); }

    FishSwarmDef m_def;
    interaction::RippleField m_field;
    interaction::FootprintCache m_cache;
    interaction::StampBatch m_batch;
    interaction::BoundingSphere m_sphere;
    float m_dt, m_depth, m_launchSpeed;
    // Fish, structure of arrays: grid position (cells), horizontal velocity (cells/s),
    // height (m) and vertical velocity (m/s).
    std::vector<float> m_gx, m_gz, m_vx, m_vz, m_y, m_vy;
    std::vector<interaction::SphereContact> m_contacts;
    // Per step scratch: surface seen, centre cell, Table 2 verdict (bit 1
    // first contact if it stamps, bit 2 rising); per chunk: its stamping fish, the index of its
    // first stamp, its first contacts as (stamp, fish).
    std::vector<float> m_surface;
    std::vector<int> m_cx, m_cz;
    std::vector<uint8_t> m_verdict;
    std::vector<std::vector<uint32_t>> m_chunkStamping;
    std::vector<size_t> m_chunkFirst;
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> m_chunkFirstContacts;
    Timings m_timings;
    int m_lastStamps = 0;
};

} // namespace ob::game
