// The foam map's parts on their own (engine/foam): the transport conserves foam under pure
// advection and decays it as e^(−t/τ); the flow's nodes reproduce a linear velocity field
// exactly at every sample on a scrolled map; the whitecap source adds its law's amount.
#include "foam/foam_flow.h"
#include "foam/foam_sources.h"
#include "foam/foam_transport.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <vector>

using namespace ob;
using foam::FoamFlow;

namespace {

constexpr float DT = 1.0f / 60.0f;

// A Gaussian blob of peak 0.9, σ = sigma metres, at world (x, z), on the grid's samples.
std::vector<float> blob(const ScrollingGrid& g, float x, float z, float sigma) {
    std::vector<float> f(size_t(g.n) * size_t(g.n));
    const glm::vec2 o = g.origin();
    for (int j = 0; j < g.n; ++j)
        for (int i = 0; i < g.n; ++i) {
            const float dx = o.x + float(i) * g.cell - x, dz = o.y + float(j) * g.cell - z;
            f[size_t(j) * size_t(g.n) + size_t(i)] = 0.9f * std::exp(-(dx * dx + dz * dz) / (2 * sigma * sigma));
        }
    return f;
}

double total(const std::vector<float>& f) { return std::accumulate(f.begin(), f.end(), 0.0); }

} // namespace

TEST_CASE("the transport conserves foam under pure advection and decays its total as exp(−t/τ)", "[foam]") {
    // A blob far from the edges moved by a uniform velocity: linear interpolation's weights sum
    // to 1, so with no decay the total is kept (to float rounding); with decay τ it is
    // total(0)·e^(−t/τ) whatever the flow. Every path: the uniform stencil, the per-sample split
    // passes, and the nodes' one sweep (0.08, 0.04 cells a step) or split passes (0.5 s steps).
    const ScrollingGrid grid = ScrollingGrid::centredOn({0.0f, 0.0f}, 0.25f, 128);
    const glm::vec2 v(1.3f, -0.7f);
    for (float decayS : {1e30f, 2.0f})
        for (int path = 0; path < 4; ++path) {
            const float dt = path == 3 ? 0.5f : DT;
            FoamFlow flow(grid, 16);
            if (path == 0) flow.setUniform(v);
            if (path == 1) {
                std::span<float> ux = flow.velocityX(), uz = flow.velocityZ();
                std::fill(ux.begin(), ux.end(), v.x);
                std::fill(uz.begin(), uz.end(), v.y);
            }
            if (path >= 2) flow.setNodes(std::vector<glm::vec2>(flow.nodePositions().size(), v));
            std::vector<float> f = blob(grid, -3.0f, 3.0f, 0.8f);
            const double before = total(f);
            foam::FoamTransport transport;
            const int steps = int(std::lround(3.0f / dt));
            for (int s = 0; s < steps; ++s) transport.step(f, grid, flow, decayS, dt);
            const double expected = before * std::exp(-double(steps) * dt / decayS);
            INFO("path " << path << ", τ " << decayS << " s: total " << total(f) << ", expected " << expected);
            CHECK(total(f) == Approx(expected).epsilon(1e-5));
        }
}

TEST_CASE("the flow's nodes give a linear velocity field exactly at every sample, after the map scrolled", "[foam]") {
    // u(x, z) = (0.3 + 0.02·x − 0.01·z, −0.2 + 0.015·x + 0.03·z) set at the nodes is bilinear
    // between them, so at every sample it is the field itself: by either path (lerp along z then
    // x, or expand the node rows along x then lerp along z).
    const auto field = [](glm::vec2 p) { return glm::vec2(0.3f + 0.02f * p.x - 0.01f * p.y, -0.2f + 0.015f * p.x + 0.03f * p.y); };
    ScrollingGrid grid = ScrollingGrid::centredOn({1.3f, -0.6f}, 0.25f, 64);
    FoamFlow flow(grid, 8);
    std::vector<glm::vec2> nodes = flow.nodePositions();
    for (glm::vec2& p : nodes) p = field(p);
    flow.setNodes(nodes);
    // Scroll 3 samples along x, −2 along z: onto the next node column (8 samples = 2 m apart),
    // the nodes shifted by one (the column scrolled onto copies its neighbour, but this map
    // does not reach it), and within the node rows along z (the offset into them moves).
    grid.centreOn({1.3f + 0.75f, -0.6f - 0.5f});
    flow.follow(grid);
    const int n = grid.n, m = flow.nodesPerSide();
    std::vector<float> row(static_cast<size_t>(n)), scratch(static_cast<size_t>(m)), e0(row), e1(row);
    double worst = 0.0;
    for (int j = 0; j < n; ++j)
        for (int c = 0; c < 2; ++c) {
            flow.nodeRow(j, c, row.data(), scratch.data());
            int l = 0;
            const float t = flow.nodeRowWeight(j, l);
            flow.expandNodeRow(l, c, e0.data(), scratch.data());
            flow.expandNodeRow(l + 1, c, e1.data(), scratch.data());
            for (int i = 0; i < n; ++i) {
                const glm::vec2 p = grid.origin() + glm::vec2(float(i), float(j)) * grid.cell;
                const double want = field(p)[c];
                worst = std::max({worst, std::abs(row[size_t(i)] - want), std::abs(e0[size_t(i)] * (1 - t) + e1[size_t(i)] * t - want)});
            }
        }
    INFO("worst |u − field| " << worst << " m/s");
    CHECK(flow.nodeOrigin() != glm::ivec2(-4, -5));  // the nodes did move
    CHECK(worst < 1e-5);
}

TEST_CASE("the whitecap source adds whitecap_weight·max(0, J_0 − J)·dt of the share still open, J bilinear in the tile", "[foam]") {
    // J linear in the tile's columns and rows (so bilinear interpolation is exact): J = 0.1 +
    // 0.01·X/Δt + 0.005·Z/Δt over a 32 m tile of 64 samples (Δt = 0.5 m), the map inside it.
    const int tn = 64;
    const float tile = 32.0f;
    std::vector<float> jac(size_t(tn) * tn);
    for (int j = 0; j < tn; ++j)
        for (int i = 0; i < tn; ++i) jac[size_t(j) * tn + size_t(i)] = 0.1f + 0.01f * float(i) + 0.005f * float(j);
    foam::FoamDef def;
    def.whitecap_from_wind = false;
    def.whitecap_weight = 2.0f;
    def.whitecap_jacobian = 0.5f;
    const float dt = 0.1f;
    const ScrollingGrid grid = ScrollingGrid::centredOn({12.0f, 12.0f}, 0.25f, 64);  // x, z ∈ [4, 20) m
    const foam::RowSources sources(def, grid, foam::FoamInputs{jac, tn, tile}, dt);
    std::vector<float> f(size_t(grid.n) * size_t(grid.n), 0.6f);
    sources.addTo(f);
    double worst = 0.0;
    int fed = 0;
    for (int j = 0; j < grid.n; ++j)
        for (int i = 0; i < grid.n; ++i) {
            const glm::vec2 p = grid.origin() + glm::vec2(float(i), float(j)) * grid.cell;
            const double J = 0.1 + 0.01 * p.x / 0.5 + 0.005 * p.y / 0.5;
            const double want = 0.6 + 2.0 * std::max(0.0, 0.5 - J) * dt * (1.0 - 0.6);
            worst = std::max(worst, std::abs(f[size_t(j) * size_t(grid.n) + size_t(i)] - want));
            fed += J < 0.5;
        }
    INFO(fed << " samples below J_0; worst error " << worst);
    CHECK(fed > 100);
    CHECK(fed < grid.n * grid.n);
    CHECK(worst < 1e-6);
}
