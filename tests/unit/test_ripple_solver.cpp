// The ripple patch through the solver interface only: a fake solver whose height is a known
// plane and that records every call shows that the patch places, scrolls, samples and stamps by
// world position and nothing else; then every registered solver keeps a feature put in the
// world when the patch scrolls, and splash craters reach any solver through the interface.
#include "core/scrolling_grid.h"
#include "interaction/ripple_patch.h"
#include "interaction/ripple_solver.h"
#include "splash/splash_particles.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace ob::interaction;

// A solver that is not a ripple model: its height is the plane a·x + b·z + c of the cell
// (x, z) it holds in the world, kept as data that scrolls with scrollCells (cells from outside
// take the plane's value there, so the plane stays whole), and it records every call.
class RecordingSolver final : public RippleSolver {
public:
    static constexpr float A = 0.01f, B = -0.02f, C = 0.5f;  // m per cell, m per cell, m

    RecordingSolver(int n, glm::ivec2 originCell) : m_n(n), m_origin(originCell), m_height(size_t(n) * size_t(n)) { fill(); }

    struct Added {
        int x, z;
        double dh;
    };
    std::vector<SphereMotion> spheres;
    std::vector<Added> heights;
    std::vector<glm::ivec2> shifts;
    std::vector<float> steps;
    std::vector<float> dampings;  // retune's damping key, per call
    std::vector<std::vector<ObstructionCell>> obstructions;  // setObstruction's cells, per call

    int rows() const override { return m_n; }
    int cols() const override { return m_n; }
    bool addSphere(const BoundingSphere&, SphereContact&, const SphereMotion& motion) override {
        spheres.push_back(motion);
        return true;
    }
    void addHeight(int x, int z, double dh) override { heights.push_back({x, z, dh}); }
    void step(float dt) override { steps.push_back(dt); }
    void setObstruction(std::span<const ObstructionCell> cells) override { obstructions.emplace_back(cells.begin(), cells.end()); }
    void scroll(glm::ivec2 shift) override {
        shifts.push_back(shift);
        ob::scrollCells(m_height.data(), m_n, m_n, shift, std::nanf(""));
        m_origin += shift;
        for (int z = 0; z < m_n; ++z)  // the cells that came from outside
            for (int x = 0; x < m_n; ++x)
                if (std::isnan(at(x, z))) at(x, z) = plane(x, z);
    }
    void clear() override {}
    std::span<const float> height() const override { return m_height; }
    float velocityAt(glm::vec2 g, float dt) const override { return g.x + 1000.0f * g.y + dt; }  // echoes its inputs
    std::vector<RippleLevel> levels() const override { return {{"h", m_height}}; }
    void hashState(ob::StateHasher& h) const override { h.f32s(m_height.data(), m_height.size()); }
    void retune(const RippleDef& def) override { dampings.push_back(def.damping); }
    bool onGpu() const override { return false; }
    const char* backendName() const override { return "test"; }

private:
    float plane(int x, int z) const { return A * float(m_origin.x + x) + B * float(m_origin.y + z) + C; }
    float& at(int x, int z) { return m_height[size_t(z) * size_t(m_n) + size_t(x)]; }
    void fill() {
        for (int z = 0; z < m_n; ++z)
            for (int x = 0; x < m_n; ++x) at(x, z) = plane(x, z);
    }

    int m_n;
    glm::ivec2 m_origin;  // world cell of cell (0, 0): the fake's own bookkeeping, to check the patch's
    std::vector<float> m_height;
};

// The patch of 32 cells of 0.5 m centred on (10.2, −3.9): origin cell round(c / Δ) − 16.
RippleDef fakeDef() {
    RippleDef def;
    def.resolution = 32;
    def.cell_size = 0.5f;
    def.center = {10.2f, -3.9f};
    return def;
}
const glm::ivec2 FAKE_ORIGIN{20 - 16, -8 - 16};

// The plane the fake holds, at world (x, z) in m: a·x/Δ + b·z/Δ + c (cell centres at integers).
float planeAt(glm::vec2 world) {
    return RecordingSolver::A * world.x / 0.5f + RecordingSolver::B * world.y / 0.5f + RecordingSolver::C;
}

} // namespace

TEST_CASE("the ripple patch places, samples and stamps through the solver interface only", "[ripple][solver]") {
    const RippleDef def = fakeDef();
    auto owned = std::make_unique<RecordingSolver>(def.resolution, FAKE_ORIGIN);
    RecordingSolver& fake = *owned;
    RipplePatch patch(def, std::move(owned));
    REQUIRE(patch.solverAs<RecordingSolver>() == &fake);
    CHECK(patch.origin() == glm::vec2(FAKE_ORIGIN) * 0.5f);

    SECTION("height is the solver's level, bilinear at the world point (exact for a plane), 0 off the patch") {
        for (glm::vec2 w : {glm::vec2(10.2f, -3.9f), glm::vec2(3.3f, -11.1f), glm::vec2(16.9f, 2.7f)})
            CHECK(patch.heightAt(w) == Approx(planeAt(w)).margin(1e-5));
        CHECK(patch.heightAt({-40.0f, 0.0f}) == 0.0f);
        CHECK(patch.rows() == 32);
        CHECK(patch.height().data() == fake.height().data());
    }
    SECTION("velocity asks the solver at the grid point of the world point") {
        const glm::vec2 g = glm::vec2(12.0f, -1.0f) / 0.5f - glm::vec2(FAKE_ORIGIN);
        CHECK(patch.velocityAt({12.0f, -1.0f}, 0.25f) == Approx(g.x + 1000.0f * g.y + 0.25f));
    }
    SECTION("a sphere reaches the solver in grid coordinates with its motion") {
        BoundingSphere sphere;
        SphereContact contact;
        CHECK(patch.stampSphere(sphere, contact, {11.0f, 0.7f, -2.5f}, {3.0f, -4.0f, 0.0f}, 7.0f, 0.1f));
        REQUIRE(fake.spheres.size() == 1);
        const SphereMotion& m = fake.spheres[0];
        CHECK(m.gridX == Approx(11.0f / 0.5f - float(FAKE_ORIGIN.x)));
        CHECK(m.gridZ == Approx(-2.5f / 0.5f - float(FAKE_ORIGIN.y)));
        CHECK(m.centreY == 0.7f);
        CHECK(m.verticalVelocity == -4.0f);  // velocity.y
        CHECK(m.speed == Approx(5.0f));
        CHECK(m.mass == 7.0f);
        CHECK(m.surfaceY == 0.1f);
    }
    SECTION("centerOn scrolls by whole cells, and what the solver holds stays put in the world") {
        const glm::vec2 probe(12.3f, -2.2f);
        const float before = patch.heightAt(probe);
        patch.centerOn({10.2f - 0.1f, -3.9f + 0.1f});  // the same nearest cell: no scroll
        CHECK(fake.shifts.empty());
        patch.centerOn({10.2f + 3.0f * 0.5f, -3.9f - 2.0f * 0.5f});
        REQUIRE(fake.shifts.size() == 1);
        CHECK(fake.shifts[0] == glm::ivec2(3, -2));
        CHECK(patch.origin() == glm::vec2(FAKE_ORIGIN + glm::ivec2(3, -2)) * 0.5f);
        CHECK(patch.heightAt(probe) == Approx(before).margin(1e-5));
        CHECK(patch.heightAt(probe) == Approx(planeAt(probe)).margin(1e-5));
    }
    SECTION("step and the live keys are forwarded") {
        patch.step(1.0f / 60.0f);
        CHECK(fake.steps == std::vector<float>{1.0f / 60.0f});
        ob::interaction::RippleDef live = patch.def();
        live.damping = 0.9f;
        live.decay_time = 5.0f;
        patch.retune(live);
        CHECK(fake.dampings == std::vector<float>{0.9f});
        CHECK(patch.def().damping == 0.9f);
        CHECK(patch.def().decay_time == 5.0f);
    }
    SECTION("splash craters reach the solver as addHeight of −√(2E / (ρ g Δ²)) at the landing's cell") {
        ob::splash::Landing drop;
        drop.position = {11.0f, 0.0f, -2.0f};
        drop.velocity = {0.0f, -4.0f, 0.0f};
        drop.mass = 0.002f;
        ob::splash::Landing outside = drop;
        outside.position = {-40.0f, 0.0f, 0.0f};
        const ob::splash::Landing drops[] = {drop, outside};
        const double energy = ob::splash::stampLandings(patch, drops, 0.5f);
        const double e = 0.5 * 0.5 * 0.002 * 16.0;  // ε·½·m·s², J
        CHECK(energy == Approx(e));
        REQUIRE(fake.heights.size() == 1);
        CHECK(fake.heights[0].x == 22 - FAKE_ORIGIN.x);
        CHECK(fake.heights[0].z == -4 - FAKE_ORIGIN.y);
        CHECK(fake.heights[0].dh == Approx(-std::sqrt(2.0 * e / (1025.0 * 9.81 * 0.25))));
    }
}

TEST_CASE("every registered solver keeps a crater put in the world when the patch scrolls", "[ripple][solver]") {
    RippleModels::forEach([]<class Model>() {
        INFO(Model::NAME);
        RippleDef def;
        def.model = rippleModel(Model::NAME);
        def.resolution = 32;
        def.cell_size = 0.5f;
        def.boundary = RippleBoundary::Fixed;
        REQUIRE(validate(def).empty());
        RipplePatch patch(def);
        REQUIRE(patch.rows() == 32);
        REQUIRE(patch.cols() == 32);
        const glm::vec2 crater(2.0f, -1.5f);  // a cell centre: world cell (4, −3)
        const glm::vec2 g = patch.toGrid(crater);
        patch.solver().addHeight(int(g.x), int(g.y), -0.1);
        CHECK(patch.heightAt(crater) == Approx(-0.1f));
        patch.centerOn({3.0f, -2.5f});  // 6 cells in x, −5 in z
        CHECK(patch.heightAt(crater) == Approx(-0.1f));
        CHECK(patch.heightAt(crater + glm::vec2(0.5f, 0.0f)) == 0.0f);
        patch.solver().clear();
        CHECK(patch.heightAt(crater) == 0.0f);
    });
}

TEST_CASE("a model's own cross-key check comes from its registration", "[ripple][solver][scene]") {
    RippleDef def;
    def.boundary = RippleBoundary::Periodic;
    def.model = rippleModel("kang2008");
    const std::vector<RippleDefError> errors = validate(def);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].key == "boundary");
    def.model = rippleModel("ewave");
    CHECK(validate(def).empty());
    CHECK(ob::enumName(rippleModel("ewave")) == std::string("ewave"));
}
