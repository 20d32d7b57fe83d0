// The surface current layer (docs/currents.md): one CurrentLayer::step at N² cells, open water
// (FFT projection) or with a wall across it (FFT, then MIC(0)-PCG from the last step's φ), still
// or with a moving hull, by worker count, with the periodic or the open edge. A source drives a jet and a body's impulse lands every step, so the flow is
// never still; 600 steps (10 s) run before the timing, so the jet has reached the wall's gap.
#include "core/parallel.h"
#include "currents/current_layer.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

constexpr float DT = 1.0f / 60.0f;

// Args: N, wall (0 open water; 1 a wall across the patch with a gap of 0.1·N cells; 2 that wall and
// a 20 m × 6 m hull crossing a cell every step, so the mask and the preconditioner change each
// step), workers, edge (0 periodic, 1 open: the sine pair through the real FFT).
void BM_CurrentStep(benchmark::State& state) {
    const int n = int(state.range(0));
    const int kind = int(state.range(1));
    const bool wall = kind != 0;
    ob::setWorkerCount(int(state.range(2)));
    ob::currents::CurrentsDef def;
    def.resolution = n;
    def.cell_size = 2.0f;
    def.sources.push_back({{-0.5f * float(n), 0.0f}, 12.0f, {1.0f, 0.0f}, 2.0f});
    def.edge = state.range(3) != 0 ? ob::currents::CurrentEdge::Open : ob::currents::CurrentEdge::Periodic;
    ob::currents::CurrentLayer layer(def, 1025.0f);
    layer.setWind({8.0f, 3.0f});
    std::vector<ob::interaction::ObstacleShape> shapes;
    if (wall) {
        ob::interaction::ObstacleShape a, b;
        a.centre = {0.0f, 0.7f * float(n)};
        a.half = {3.0f, 0.6f * float(n)};
        b.centre = {0.0f, -0.7f * float(n)};
        b.half = {3.0f, 0.6f * float(n)};
        shapes = {a, b};
        layer.setWalls(shapes);
    }
    for (int s = 0; s < 600; ++s) {
        layer.addImpulse({float(s % 50), 5.0f}, {2e5f, -1e5f}, 6.0f);
        layer.step(DT);
    }
    int64_t iterations = 0, steps = 0;
    float hullX = -60.0f;
    for (auto _ : state) {
        if (kind == 2) {
            hullX = hullX > 60.0f ? -60.0f : hullX + 2.0f;
            ob::interaction::ObstacleShape hull;
            hull.kind = ob::interaction::ObstacleShape::Kind::Ellipse;
            hull.centre = {hullX, -30.0f};
            hull.half = {10.0f, 3.0f};
            std::vector<ob::interaction::ObstacleShape> all = shapes;
            all.push_back(hull);
            layer.setWalls(all);
        }
        layer.addImpulse({float(steps % 50), 5.0f}, {2e5f, -1e5f}, 6.0f);
        layer.step(DT);
        iterations += layer.lastWallSolve().iterations;
        ++steps;
        benchmark::DoNotOptimize(layer.uField().data());
    }
    if (!layer.finite()) state.SkipWithError("the layer is not finite");
    state.counters["cg_iterations"] = steps ? double(iterations) / double(steps) : 0.0;
    state.SetItemsProcessed(state.iterations() * int64_t(n) * n);
    ob::setWorkerCount(0);
}
BENCHMARK(BM_CurrentStep)
    ->ArgNames({"n", "wall", "workers", "open"})
    ->ArgsProduct({{128, 256}, {0, 1, 2}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
