// Nested ripple levels (docs/ewave.md#levels): coarser grids around the patch's own, each a
// solver of the patch's model (RippleSolver::makeLevel) of the same N with cells 4^L times the
// patch's, stepping every 4^L-th frame over 4^L frames' time and read through a cubic Hermite
// in time between its last two states; and the composite, which takes the finest level that
// covers a point and cross-fades to the next coarser one over a band inside its border (C¹: no
// seam). It knows the models only through the solver interface.
#pragma once
#include "core/hash.h"
#include "core/scrolling_grid.h"
#include "interaction/obstruction.h"
#include "interaction/ripple_def.h"
#include "interaction/ripple_solver.h"

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <vector>

namespace ob::interaction {

/// The composite's weight of a level at its grid position g (cells, centres at integers) on an
/// n-cell grid with an absorbing band of `sponge` cells: per axis, with d the distance to the
/// nearer outer cell centre, 0 for d ≤ sponge (the band damps what the level holds there),
/// 1 for d ≥ 2·sponge, and the smoothstep 3s² − 2s³ of s = (d − sponge)/sponge between; the
/// product of both axes. C¹, |∇w| ≤ √2·1.5/sponge per cell (docs/ewave.md#levels).
float levelWeight(glm::vec2 g, int n, int sponge);

/// A coarse level as the renderer draws it: its last two states, copied when it stepped or moved
/// (RippleLevels::publish), and the cubic's weights at the frame drawn. The shader's height is
/// weights · (h0, h1, v0, v1) per cell (shaders/ripple_levels.comp), as RippleLevels::height.
struct LevelDraw {
    std::span<const float> h0, h1, v0, v1;  ///< rows·cols row-major, m and m/s
    uint64_t version = 0;                    ///< changes whenever the states do (upload then)
    glm::vec4 weights{0.0f};                 ///< (h00, h01, h10·S, h11·S) of the cubic at the frame drawn
    std::array<glm::vec2, 4> extremes{};     ///< (min, max) of h0, h1, v0, v1
    glm::vec2 origin{0.0f};                  ///< world (x, z) of cell (0, 0)'s centre for these states, m
    float cellSize = 1.0f;                   ///< m
};

/// Levels 1..K−1 of a ripple patch whose level 0 is the patch's own solver (ripples.levels = K).
/// Level L: n × n cells of cellSize·4^L metres, centred on the patch's centre within one of its
/// cells (it scrolls in whole cells of its own); it steps when the patch's frame count passes
/// its state's frame b, from b to b + 4^L over 4^L·dt (level L first at frame L + 1, so the
/// levels' steps fall on different frames), and between steps reads as the Hermite cubic
/// through (h, v) of its last two states.
class RippleLevels {
public:
    /// Each level's cells are this many times its finer neighbour's, its step as many frames.
    static constexpr int RATIO = 4;

    /// Levels 1..def.levels − 1 of a checked Def, each made by `fine` (the patch's solver, whose
    /// levelRefusal() is null: makeLevel), centred on def.center.
    RippleLevels(const RippleDef& def, const RippleSolver& fine);
    ~RippleLevels();

    /// The patch's levels, 1 + the coarse ones here.
    int count() const { return int(m_levels.size()) + 1; }
    /// Level L's placement (1 ≤ L < count()).
    const ScrollingGrid& grid(int L) const { return level(L).grid; }
    /// Level L's solver (its state at frame b, not interpolated).
    const RippleSolver& solver(int L) const { return *level(L).solver; }
    /// Level L's solver, writable (tests that set a level's state: what the composite reads follows
    /// from its next step on, the Hermite's both ends from the one after).
    RippleSolver& solver(int L) { return *m_levels[size_t(L - 1)].solver; }
    /// Level L's solver as its concrete type, or null (tests that write a model's own state).
    template <class S> S* solverAs(int L) { return dynamic_cast<S*>(&solver(L)); }
    /// Level L's height at the patch's last step, interpolated in time, rows·cols row-major, m
    /// (the renderer's upload; made on the first call after a step, so not to be called from
    /// several threads at once: the queries below read pointwise and may).
    std::span<const float> height(int L) const;
    /// Copies every level's states for the renderer where they changed since the last call
    /// (on the thread that steps, never while step() runs elsewhere).
    void publish();
    /// Level L as publish() last copied it, with the cubic's weights at patch frame `frame` (the
    /// phase held in [0, 1]: a level whose step is still running shows its last finished state).
    /// Reads only what publish() wrote: safe while step() runs on another thread.
    LevelDraw draw(int L, int64_t frame) const;
    /// Whether the levels step on a GPU twin (then on the thread that holds the GL context).
    bool onGpu() const { return !m_levels.empty() && m_levels.front().solver->onGpu(); }
    /// Whether the next step() steps some level (else it only moves the frame on).
    bool stepDue() const {
        for (const Level& lv : m_levels)
            if (m_frame + 1 > lv.b) return true;
        return false;
    }
    /// The absorbing band of every level, cells (as the fields clamp it): the composite's fade band.
    int sponge() const { return m_sponge; }
    /// Frames between level L's steps (4^L).
    int stride(int L) const { return level(L).stride; }

    /// Moves every level so its centre is its cell nearest `world` (m), scrolling its data.
    void centerOn(glm::vec2 world);
    /// The finest level ≥ 1 whose composite weight at `world` (m) is > 0; count() − 1 at most.
    int finestAt(glm::vec2 world) const;
    /// Queues a source made on a finer level (centre world m, applied radius m, accel m/s² over
    /// one frame) on every level ≥ `from`: on level L with radius max(radius, cell_L) and accel
    /// scaled so that ∫accel·w dA, the source's long-wave content, is the same.
    void pushSource(glm::vec2 centre, float radius, float accel, int from);
    /// A splash drop's crater of `volume` m³ (< 0: a hollow) at world (x, z), on every level ≥
    /// `from` whose grid holds it: at the level's next step, spread bilinearly over the four
    /// cells round it (its centre kept) as RippleSolver::addHeight (the volume taken back as the
    /// k = 0 mode), so every level gets the same long-wave content, volume·e^{−ik·x}. False:
    /// no level holds it.
    bool addCrater(glm::vec2 world, double volume, int from);
    /// Table 2 for a sphere that level 0 does not cover: stamped on level finestAt(centre),
    /// the source then pushed to the coarser ones. `motion`'s grid position is set here.
    bool stampSphere(const BoundingSphere& sphere, SphereContact& contact, SphereMotion motion, glm::vec2 centre);
    /// One patch frame of dt s: the levels whose turn it is step (sources, obstacles on their
    /// grids, the exact step over stride·dt); the others only move on in their Hermite.
    void step(float dt, std::span<const ObstacleShape> obstacles);

    /// Level L's height at world (x, z): the Hermite of its two states' bilinear heights and
    /// velocities (equal to bilinear on height(L)); 0 off the grid, m.
    float heightAt(int L, glm::vec2 world) const;
    /// Level L's vertical velocity at world (x, z): the Hermite's time derivative, m/s.
    float velocityAt(int L, glm::vec2 world) const;
    /// Level L's horizontal surface velocity at world (x, z), (x, z) in m/s: the Hermite's time
    /// derivative of its two states' horizontal displacement ξ and velocity u (LevelState; for
    /// ewave the Riesz transform of velocityAt's v); 0 for a model without them.
    glm::vec2 horizontalVelocityAt(int L, glm::vec2 world) const;
    /// Level L's composite weight at world (x, z) (1 everywhere on the coarsest level).
    float weightAt(int L, glm::vec2 world) const;
    /// The composite value at `world` given level 0's value and weight there: each level takes
    /// its weight of what the finer ones left, value(L, world) for L ≥ 1 (float, or a vec2's
    /// components alike).
    template <class T, class Value> T composite(glm::vec2 world, T value0, float weight0, Value&& value) const {
        T sum = weight0 * value0;
        float rest = 1.0f - weight0;
        for (int L = 1; L < count() && rest > 0.0f; ++L) {
            const float w = weightAt(L, world);
            if (w > 0.0f) sum += rest * w * value(L, world);
            rest *= 1.0f - w;
        }
        return sum;
    }
    /// Every level takes the Def's live keys (the model's, as RippleSolver::retune) from its next step on.
    void retune(const RippleDef& def) {
        for (Level& lv : m_levels) lv.solver->retune(def);
    }
    /// Every level's state, its frames and its queued sources (the state hash).
    void hashState(StateHasher& h) const;

private:
    struct WorldSource {
        glm::vec2 centre;  // m
        float radius;      // applied radius, m
        float strength;    // accel·radius², m³/s² (what each level keeps)
    };
    struct WorldCrater {
        glm::vec2 centre;  // m
        double volume;     // m³
    };
    struct Level {
        ScrollingGrid grid;
        std::unique_ptr<RippleSolver> solver;
        int stride = 1;                         // frames per step
        int64_t a = 0, b = 0;                   // frames of the two states kept (b = the solver's)
        LevelState s0, s1;                      // the states at frames a and b (keepLevelState)
        mutable std::vector<float> shown;       // Hermite height at frame shownFrame, m (height())
        mutable int64_t shownFrame = -1;
        std::vector<WorldSource> queued;        // sources since its last step
        std::vector<WorldCrater> craters;       // craters since its last step
        std::vector<ObstructionCell> obstruction;  // its cells at its last step
        uint64_t version = 1;                   // counts the changes of s0, s1 (steps, scrolls)
        struct {
            std::vector<float> h0, h1, v0, v1;  // s0, s1's h and v as last published
            int64_t a = 0;                      // their frames a, a + stride
            float seconds = 0.0f;               // S = stride·dt then, s
            glm::vec2 origin{0.0f};             // the grid's origin then, m
            std::array<glm::vec2, 4> extremes{};  // (min, max) of h0, h1, v0, v1
            uint64_t version = 0;               // `version` then (0: never)
        } drawn;
    };
    const Level& level(int L) const { return m_levels[size_t(L - 1)]; }
    void stepLevel(Level& lv, float dt, std::span<const ObstacleShape> obstacles);
    static void keepState(Level& lv);
    float phase(const Level& lv) const { return float(m_frame - lv.a) / float(lv.stride); }

    std::vector<Level> m_levels;  // levels 1..K−1
    RippleBoundary m_boundary;    // every level's (a crater's volume taken back unless Fixed)
    int m_sponge;                 // absorbing band, cells (every level)
    float m_cell0;                // level 0's cell, m
    int64_t m_frame = 0;          // patch frames stepped
    float m_dt = 1.0f / 60.0f;    // the last frame's dt, s (the Hermite's step is stride·m_dt)
};

} // namespace ob::interaction
