// The level stack through the solver interface only: a model that is not registered (a fake
// defined here, whose state is a known standing wave) runs nested in levels, and the patch's
// composite height and velocity match the wave's closed form everywhere the levels reach (the
// fine grid, the coarse ones alone, the fade bands); a model that cannot be nested is refused
// with the reason it gives (kang2008 through the table, a fake through the patch).
#include "core/scrolling_grid.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_levels.h"
#include "interaction/ripple_patch.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace ob::interaction;

constexpr float DT = 1.0f / 60.0f;  // s per frame
constexpr int N = 16;               // cells a side, every level
constexpr float CELL = 1.0f;        // level 0's cell, m
constexpr int SPONGE = 2;           // the fake's absorbing band, cells: the composite's fade band
constexpr double AMPLITUDE = 0.3;   // m
constexpr double OMEGA = 2.0;       // rad/s
const glm::dvec2 K{2.0 * std::numbers::pi / 400.0, 2.0 * std::numbers::pi / 900.0};  // rad/m

// The standing wave h = A·sin(K·x)·sin(ωt) and its rate, at world x (m) and time t (s).
double waveHeight(glm::dvec2 x, double t) { return AMPLITUDE * std::sin(glm::dot(K, x)) * std::sin(OMEGA * t); }
double waveRate(glm::dvec2 x, double t) { return AMPLITUDE * OMEGA * std::sin(glm::dot(K, x)) * std::cos(OMEGA * t); }

// A third ripple model, known only here: its cells hold the standing wave at their centres at its
// clock's time. Placed as the patch and the stack place grids (centred on the Def's centre); a
// coarse level's clock starts at frame L, as the stack counts a level's still water
// (ripple_levels.h), so every level holds the same wave at the frame the stack says.
class StandingWaveSolver final : public RippleSolver {
public:
    StandingWaveSolver(glm::vec2 centre, float cell, double clock, const char* refusal = nullptr)
        : m_centre(centre), m_grid(ob::ScrollingGrid::centredOn(centre, cell, N)), m_clock(clock), m_refusal(refusal),
          m_h(size_t(N) * N), m_v(size_t(N) * N) {
        fill();
    }
    float cell() const { return m_grid.cell; }

    int rows() const override { return N; }
    int cols() const override { return N; }
    bool addSphere(const BoundingSphere&, SphereContact&, const SphereMotion&) override { return false; }
    void addHeight(int, int, double) override {}
    void step(float dt) override {
        m_clock += double(dt);
        fill();
    }
    void setObstruction(std::span<const ObstructionCell>) override {}
    void scroll(glm::ivec2 shift) override {
        m_grid.originCell += shift;
        fill();
    }
    void clear() override {}
    std::span<const float> height() const override { return m_h; }
    float velocityAt(glm::vec2 g, float) const override { return bilinear<float>(m_v, N, N, g); }
    std::vector<RippleLevel> levels() const override { return {{"h", m_h}}; }
    void hashState(ob::StateHasher& h) const override { h.f32s(m_h.data(), m_h.size()); }
    void retune(const RippleDef&) override {}
    bool onGpu() const override { return false; }
    const char* backendName() const override { return "test"; }

    const char* levelRefusal() const override { return m_refusal; }
    std::unique_ptr<RippleSolver> makeLevel(float cellSize) const override {
        const int L = int(std::lround(std::log(double(cellSize / m_grid.cell)) / std::log(double(RippleLevels::RATIO))));
        return std::make_unique<StandingWaveSolver>(m_centre, cellSize, double(L) * double(DT));
    }
    int spongeCells() const override { return SPONGE; }
    void keepLevelState(LevelState& out) const override {
        out.h = m_h;
        out.v = m_v;
    }

private:
    void fill() {
        for (int z = 0; z < N; ++z)
            for (int x = 0; x < N; ++x) {
                const glm::dvec2 w = glm::dvec2(m_grid.originCell + glm::ivec2(x, z)) * double(m_grid.cell);
                m_h[size_t(z) * N + size_t(x)] = float(waveHeight(w, m_clock));
                m_v[size_t(z) * N + size_t(x)] = float(waveRate(w, m_clock));
            }
    }

    glm::vec2 m_centre;
    ob::ScrollingGrid m_grid;
    double m_clock;  // s
    const char* m_refusal;
    std::vector<float> m_h, m_v;
};

RippleDef nestedDef(int levels) {
    RippleDef def;
    def.resolution = N;
    def.cell_size = CELL;
    def.levels = levels;
    def.center = {0.3f, -0.2f};
    return def;
}

} // namespace

TEST_CASE("a model the table does not list runs nested in levels: the composite is its wave wherever the levels reach",
          "[ripple][levels][solver]") {
    const RippleDef def = nestedDef(3);
    RipplePatch patch(def, std::make_unique<StandingWaveSolver>(def.center, CELL, 0.0));
    REQUIRE(patch.levels() != nullptr);
    REQUIRE(patch.levelCount() == 3);
    for (int L = 1; L < 3; ++L) {
        const auto* level = dynamic_cast<const StandingWaveSolver*>(&patch.levels()->solver(L));
        REQUIRE(level != nullptr);  // made by the model's own makeLevel
        CHECK(level->cell() == CELL * std::pow(4.0f, float(L)));
    }
    CHECK(patch.fadeCells() == SPONGE);

    // Level 2 (16 m cells, 256 m) steps every 16 frames, first at frame 3: from frame 36 on both
    // ends of its cubic in time are real states. Along a line from the fine grid out through
    // both fade bands to level 2 alone: the bilinear error on 16 m cells is (|K|·16 m)²/8 of A
    // (0.9 %), the cubic's (ω·16·dt)⁴/384 (2e-4); 3 % of A and of Aω. Reading each level's last
    // state instead (no cubic) is off by up to ω·16·dt = 53 %.
    double worstH = 0.0, worstV = 0.0;
    for (int frame = 1; frame <= 60; ++frame) {
        patch.step(DT);
        if (frame < 36) continue;
        const double t = double(frame) * double(DT);
        for (float x = -110.0f; x <= 110.0f; x += 0.73f) {  // level 2's cell centres: −128 m to 112 m
            const glm::vec2 w(x, 3.1f + 0.21f * x);
            worstH = std::max(worstH, std::abs(double(patch.heightAt(w)) - waveHeight(w, t)));
            worstV = std::max(worstV, std::abs(double(patch.velocityAt(w, DT)) - waveRate(w, t)));
        }
    }
    INFO("worst height error " << worstH << " m, velocity " << worstV << " m/s");
    CHECK(worstH < 0.03 * AMPLITUDE);
    CHECK(worstV < 0.03 * AMPLITUDE * OMEGA);
    CHECK(patch.horizontalVelocityAt({90.0f, 10.0f}) == glm::vec2(0.0f));  // no ξ, u: none
    CHECK(patch.heightAt({300.0f, 0.0f}) == 0.0f);                         // off every level
    // What the renderer gets of level 2: its two states and the cubic's weights at this frame
    // (shaders/ripple_levels.comp evaluates them), the heights the composite reads.
    const LevelDraw draw = patch.levelDraw(2);
    const glm::vec4 w = draw.weights;
    const size_t cell = size_t(5 * N + 7);
    CHECK(w.x * draw.h0[cell] + w.y * draw.h1[cell] + w.z * draw.v0[cell] + w.w * draw.v1[cell] ==
          Approx(patch.levels()->height(2)[cell]).margin(1e-6));
}

TEST_CASE("a model that cannot be nested is refused with its own reason", "[ripple][levels][solver]") {
    SECTION("a fake's refusal, from the patch") {
        const RippleDef def = nestedDef(2);
        auto make = [&] { RipplePatch patch(def, std::make_unique<StandingWaveSolver>(def.center, CELL, 0.0, "no coarse grids here")); };
        CHECK_THROWS_WITH(make(), Catch::Contains("no coarse grids here") && Catch::Contains("levels"));
        RipplePatch one(nestedDef(1), std::make_unique<StandingWaveSolver>(def.center, CELL, 0.0, "no coarse grids here"));
        CHECK(one.levelCount() == 1);
    }
    SECTION("kang2008's, through the table's check of the Def") {
        RippleDef def = nestedDef(2);
        def.model = rippleModel("kang2008");
        const std::vector<RippleDefError> errors = validate(def);
        REQUIRE(errors.size() == 1);
        CHECK(errors[0].key == "levels");
        CHECK(errors[0].message.find(Kang2008Solver::LEVEL_REFUSAL) != std::string::npos);
        def.levels = 1;
        CHECK(std::string(Kang2008Model::make(def)->levelRefusal()) == Kang2008Solver::LEVEL_REFUSAL);
    }
}
