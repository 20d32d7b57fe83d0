// The wind's part of the foam's motion (docs/splash_foam.md §2.2, foam/foam_flow.h WindFlow): the
// surface drift carries foam down-wind at wind_drift·U10 plus the Stokes drift, the streak cells
// gather it into lines along the wind at γ = 2π·V/L without losing any, and a steady wind over
// breaking patches leaves the foam longer along the wind than across it. Also the measure:
// the autocorrelation length of a Gaussian blob.
#include "foam/foam_map.h"
#include "foam/foam_streaks.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

using namespace ob;

namespace {

constexpr float DT = 1.0f / 60.0f;
const glm::vec2 WIND_DIR = glm::normalize(glm::vec2(1.0f, 0.6f));

// Adds a Gaussian blob of peak `peak`, σ = sigma metres, at world (x, z) to the map (at most 1).
void addBlob(foam::FoamMap& map, glm::vec2 at, float sigma, float peak) {
    const ScrollingGrid& g = map.grid();
    const glm::vec2 o = g.origin();
    std::span<float> f = map.coverage();
    const glm::vec2 lo = (at - o) / g.cell - 6.0f * sigma / g.cell, hi = (at - o) / g.cell + 6.0f * sigma / g.cell;  // ±6σ
    for (int j = std::max(0, int(lo.y)); j < std::min(g.n, int(hi.y) + 1); ++j)
        for (int i = std::max(0, int(lo.x)); i < std::min(g.n, int(hi.x) + 1); ++i) {
            const glm::vec2 d = o + glm::vec2(float(i), float(j)) * g.cell - at;
            const float v = peak * std::exp(-glm::dot(d, d) / (2 * sigma * sigma));
            float& c = f[size_t(j) * size_t(g.n) + size_t(i)];
            c = std::min(1.0f, c + v);
        }
}

struct Moments {
    double total = 0.0;
    glm::dvec2 centre{0.0};
    double alongVar = 0.0, acrossVar = 0.0;  // m², about the centre
};

Moments moments(const foam::FoamMap& map) {
    const ScrollingGrid& g = map.grid();
    const glm::dvec2 w(WIND_DIR), c(-w.y, w.x);
    Moments m;
    glm::dvec2 sum(0.0);
    std::span<const float> f = map.coverage();
    for (int j = 0; j < g.n; ++j)
        for (int i = 0; i < g.n; ++i) {
            const double v = f[size_t(j) * size_t(g.n) + size_t(i)];
            m.total += v;
            sum += v * (glm::dvec2(g.origin()) + glm::dvec2(i, j) * double(g.cell));
        }
    m.centre = sum / m.total;
    for (int j = 0; j < g.n; ++j)
        for (int i = 0; i < g.n; ++i) {
            const double v = f[size_t(j) * size_t(g.n) + size_t(i)];
            const glm::dvec2 d = glm::dvec2(g.origin()) + glm::dvec2(i, j) * double(g.cell) - m.centre;
            m.alongVar += v * glm::dot(d, w) * glm::dot(d, w);
            m.acrossVar += v * glm::dot(d, c) * glm::dot(d, c);
        }
    m.alongVar /= m.total, m.acrossVar /= m.total;
    return m;
}

foam::FoamInputs windInputs(float windSpeed, glm::vec2 stokes = glm::vec2(0.0f)) {
    foam::FoamInputs in;  // no sea, no ripples: the wind alone moves the foam
    in.windSpeed = windSpeed;
    in.windDirection = glm::vec2(1.0f, 0.6f);
    in.stokesDrift = stokes;
    return in;
}

} // namespace

TEST_CASE("the wind drifts foam down-wind at wind_drift·U10 plus the Stokes drift", "[foam][wind]") {
    foam::FoamDef def;
    def.resolution = 128;
    def.decay_s = 1e4f;
    def.streak_speed = 0.0f;  // the drift alone (uniform: the blob keeps its shape)
    foam::FoamMap map(def, 25.6f);
    addBlob(map, {-3.0f, -2.0f}, 0.8f, 0.9f);
    const Moments before = moments(map);
    const glm::vec2 stokes(0.05f, -0.02f);
    for (int s = 0; s < 120; ++s) map.update(windInputs(20.0f, stokes), DT);
    const Moments after = moments(map);
    const glm::dvec2 expected = (0.03 * 20.0 * glm::dvec2(WIND_DIR) + glm::dvec2(stokes)) * 2.0;
    const glm::dvec2 moved = after.centre - before.centre;
    INFO("moved (" << moved.x << ", " << moved.y << ") m, expected (" << expected.x << ", " << expected.y << ")");
    CHECK(glm::length(moved - expected) < 0.01);  // a twentieth of a cell
    CHECK(after.total == Approx(before.total * std::exp(-2.0 / 1e4)).epsilon(1e-5));
}

TEST_CASE("the streak cells' gathering is the continuity equation of their velocity", "[foam][wind]") {
    // 1 − dt·∇·u_w (windGatherRow, from the rolls' closed form) against the divergence of the
    // velocity windRow gives, by central differences over 5 cm cells (error ~ (k·Δ)²/6 < 0.2%
    // of the finest roll's), over a 12.8 m map: the same within 1% of its largest value.
    foam::FoamDef def;
    def.resolution = 256;
    foam::FoamMap map(def, 12.8f);
    foam::FoamFlow& flow = map.flow();
    flow.setWind(map.windFlow(20.0f, {1.0f, 0.6f}, {0.05f, 0.0f}));
    flow.setWindTime(37.0);
    const int n = 256;
    const float cell = 0.05f, dt = 1.0f;
    std::vector<float> ux(3 * n), uz(3 * n), gather(n);
    double worst = 0.0, largest = 0.0;
    for (int j = 1; j < n - 1; j += 17) {
        for (int r = 0; r < 3; ++r) flow.windRow(j - 1 + r, 0, &ux[size_t(r) * n]), flow.windRow(j - 1 + r, 1, &uz[size_t(r) * n]);
        flow.windGatherRow(j, dt, gather.data());
        for (int i = 1; i < n - 1; ++i) {
            const double div = (ux[size_t(n) + i + 1] - ux[size_t(n) + i - 1]) / (2.0 * cell) + (uz[size_t(2 * n) + i] - uz[size_t(i)]) / (2.0 * cell);
            worst = std::max(worst, std::abs((1.0 - gather[size_t(i)]) - div));
            largest = std::max(largest, std::abs(div));
        }
    }
    INFO("largest |∇·u_w| " << largest << " /s, worst difference " << worst);
    CHECK(largest > 0.1);
    CHECK(worst < 0.01 * largest);
}

TEST_CASE("the streak cells gather foam into a line along the wind at their convergence and keep it", "[foam][wind]") {
    // A narrow blob (σ0 = 0.25 m) on the strongest convergence within 2 m of the origin, U10 =
    // 20 m/s (V = 0.16 m/s). There the surface converges across the wind as dη/dt = −γ·η, γ =
    // −∂u_c/∂η by central differences of the velocity, so the blob's width across falls as
    // σ0·e^(−γt) (its tails, where the rolls curve, a little slower); along it the jets carry it
    // at u_w·ŵ there, stretched by its strain ∂u_w/∂ξ (the slanted rolls); and the gathering keeps the foam's total (no decay, nothing reaches 1).
    // The transport's linear resampling smooths as it moves (docs/splash_foam.md §2: a variance
    // α(1 − α)·Δ² a step and axis, α the step's fraction of a cell, from the local velocity): a
    // diffusivity D per direction, so across σ² = σ0²·e^(−2γt) + (D/γ)·(1 − e^(−2γt)), along
    // σ² = σ0²·e^(2st) + (D/s)·(e^(2st) − 1), s the strain (the field's change over the blob's
    // path: within 6% and 5%).
    foam::FoamDef def;
    def.resolution = 256;
    def.decay_s = 1e4f;
    def.wind_drift = 0.0f;
    foam::FoamMap map(def, 12.8f);  // 5 cm cells
    const int n = 256;
    const float cell = 0.05f;
    foam::FoamFlow& flow = map.flow();
    flow.setWind(map.windFlow(20.0f, {1.0f, 0.6f}, {0.0f, 0.0f}));
    const glm::vec2 w = WIND_DIR, c(-w.y, w.x), o = map.grid().origin();
    // The velocity over the map; the line: the sample within 2 m of the origin where u_c ≈ 0
    // (|u_c| < 5 mm/s, the blob stays on it) converging fastest.
    std::vector<glm::vec2> u(size_t(n) * size_t(n));
    std::vector<float> ux(n), uz(n);
    for (int j = 0; j < n; ++j) {
        flow.windRow(j, 0, ux.data()), flow.windRow(j, 1, uz.data());
        for (int i = 0; i < n; ++i) u[size_t(j) * size_t(n) + size_t(i)] = glm::vec2(ux[size_t(i)], uz[size_t(i)]);
    }
    const auto at2 = [&](int i, int j) { return u[size_t(j) * size_t(n) + size_t(i)]; };
    const auto gradient = [&](int i, int j, glm::vec2 d) {  // the directional derivative of u along d, 1/s
        return ((at2(i + 1, j) - at2(i - 1, j)) * d.x + (at2(i, j + 1) - at2(i, j - 1)) * d.y) / (2.0f * cell);
    };
    int bi = 0, bj = 0;
    double gamma = 0.0;  // −∂u_c/∂η
    for (int j = n / 2 - 40; j <= n / 2 + 40; ++j)
        for (int i = n / 2 - 40; i <= n / 2 + 40; ++i) {
            const double g = -double(glm::dot(c, gradient(i, j, c)));
            if (std::abs(glm::dot(at2(i, j), c)) < 0.005f && g > gamma) gamma = g, bi = i, bj = j;
        }
    const glm::vec2 u0 = at2(bi, bj);
    const double strain = double(glm::dot(w, gradient(bi, bj, w)));  // ∂u_w/∂ξ
    const glm::vec2 at = o + glm::vec2(float(bi), float(bj)) * cell;
    const float sigma0 = 0.25f;
    addBlob(map, at, sigma0, 0.2f);
    const Moments before = moments(map);
    const double t = 3.0;
    for (int s = 0; s < int(t * 60.0); ++s) map.update(windInputs(20.0f), DT);
    const Moments after = moments(map);
    const auto smoothing = [&](glm::dvec2 dir) {  // D along unit dir, m²/s
        double d = 0.0;
        for (int axis = 0; axis < 2; ++axis) {
            const double a = std::abs(double(u0[axis])) * double(DT) / cell;
            d += a * (1 - a) * double(cell) * double(cell) / (2.0 * double(DT)) * dir[axis] * dir[axis];
        }
        return d;
    };
    const double s0 = double(sigma0) * double(sigma0), e = std::exp(-2.0 * gamma * t);
    const double acrossExpected = std::sqrt((s0 * e + smoothing(glm::dvec2(c)) / gamma * (1.0 - e)) / s0);
    const double es = std::exp(2.0 * strain * t);
    const double alongExpected = std::sqrt((s0 * es + smoothing(glm::dvec2(w)) / strain * (es - 1.0)) / s0);
    const double acrossW = std::sqrt(after.acrossVar / before.acrossVar), alongW = std::sqrt(after.alongVar / before.alongVar);
    INFO("γ " << gamma << " /s; across width ×" << acrossW << " (law " << acrossExpected << "; e^(−γt) = " << std::exp(-gamma * t)
              << "), along ×" << alongW << " (law " << alongExpected << "), strain " << strain << " /s, total " << after.total / before.total);
    CHECK(gamma > 0.2);
    CHECK(acrossW == Approx(acrossExpected).epsilon(0.06));
    CHECK(alongW == Approx(alongExpected).epsilon(0.05));
    // Kept within 5% (the resampling of a line two cells wide by then); advected without the
    // gathering the blob keeps only its peak on a fraction of its width.
    CHECK(after.total == Approx(before.total).epsilon(0.05));
}

TEST_CASE("the autocorrelation length of a Gaussian blob is 2σ along any direction", "[foam][wind]") {
    // f = e^(−r²/2σ²): its autocorrelation is e^(−s²/4σ²), 1/e at s = 2σ (the map's mean, small
    // on a map 20σ wide, shifts it by under 1%).
    foam::FoamDef def;
    def.resolution = 256;
    foam::FoamMap map(def, 51.2f);
    addBlob(map, {0.0f, 0.0f}, 1.2f, 0.8f);
    for (glm::vec2 d : {glm::vec2(1.0f, 0.0f), glm::vec2(1.0f, 0.6f), glm::vec2(-0.3f, 1.0f)}) {
        const float l = foam::autocorrelationLength(map.coverage(), 256, 0.2f, d, 20.0f);
        CHECK(l == Approx(2.4).epsilon(0.03));
    }
}

TEST_CASE("under a steady wind foam from breaking patches lies along the wind: autocorrelation 2× longer along than across",
          "[foam][wind]") {
    // Round breaking patches (σ0 = 1 m, peak 0.9) at random places, one every 0.05 s over a
    // 51.2 m map, U10 = 20 m/s, foam decaying with τ = 6 s; measured after 20 s (stationary).
    // Without streak cells every patch keeps its round shape (the drift moves them all alike):
    // the lengths along and across are the same, 2σ0 = 2 m (a Gaussian's autocorrelation falls
    // to 1/e at 2σ). With them a patch's width across the wind falls as e^(−γt) toward the
    // cells' lines (γ = 2π·0.16/3 = 0.335 /s on the finer row's lines, ±0.128 from the coarser:
    // the foam's life τ = 6 s is about 2/γ), and its foam piles up there rather than sinking: a
    // patch of age t is e^(γt) as dense on 1/e^(γt) the width, so it weighs
    // e^(−2t/τ)·e^(2γt)·e^(−γt) = e^((γ − 2/τ)·t) ≈ 1 in the autocorrelation: the old foam, gathered
    // into lines as narrow as the transport's smoothing keeps them (σ ≈ sqrt(D/γ) ≈ 0.4 m for its
    // D ≈ 0.06 m²/s at 0.6 m/s over 0.2 m cells), weighs as much as the young. Across, then,
    // about 2·0.4 m for most of the foam; along, still the patches' 2σ0 = 2 m, more where the
    // lines' jets (±V) shear a patch off them. So the ratio should be 2–3; the test asks at least
    // 2, and that the same run without streak cells is round (which it fails).
    const auto ratio = [](float streakSpeed) {
        foam::FoamDef def;
        def.resolution = 256;
        def.streak_speed = streakSpeed;
        foam::FoamMap map(def, 51.2f);
        uint64_t state = 12345;
        const auto uniform = [&] {  // splitmix64 → [0, 1)
            uint64_t z = (state += 0x9E3779B97F4A7C15ull);
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            return float((z ^ (z >> 31)) >> 40) / float(1 << 24);
        };
        for (int s = 0; s < 1200; ++s) {
            if (s % 3 == 0) addBlob(map, {51.2f * (uniform() - 0.5f), 51.2f * (uniform() - 0.5f)}, 1.0f, 0.9f);
            map.update(windInputs(20.0f), DT);
        }
        const float along = foam::autocorrelationLength(map.coverage(), 256, 0.2f, WIND_DIR, 20.0f);
        const float across = foam::autocorrelationLength(map.coverage(), 256, 0.2f, {-WIND_DIR.y, WIND_DIR.x}, 20.0f);
        return glm::vec2(along, across);
    };
    const glm::vec2 streaks = ratio(0.008f), round = ratio(0.0f);
    INFO("along, across: " << streaks.x << ", " << streaks.y << " m with streak cells; " << round.x << ", " << round.y
                           << " m without");
    CHECK(streaks.x >= 2.0f * streaks.y);
    CHECK(round.x / round.y == Approx(1.0f).epsilon(0.2));
}

namespace {

// The convergence −∇·u_w of the streak cells over a 256 m map of 0.5 m cells (windGatherRow of
// dt = 1 s, minus 1), at time t, for a wind of 20 m/s along WIND_DIR and no drift.
std::vector<float> streakConvergence(double t) {
    foam::FoamDef def;
    def.resolution = 512;
    foam::FoamMap map(def, 256.0f);
    foam::FoamFlow& flow = map.flow();
    flow.setWind(map.windFlow(20.0f, WIND_DIR, {0.0f, 0.0f}));
    flow.setWindTime(t);
    std::vector<float> g(size_t(512) * 512);
    for (int j = 0; j < 512; ++j) {
        flow.windGatherRow(j, 1.0f, &g[size_t(j) * 512]);
        for (int i = 0; i < 512; ++i) g[size_t(j) * 512 + size_t(i)] -= 1.0f;
    }
    return g;
}

// The largest autocorrelation across the wind at lags from the first where it turns negative to
// 60 m (every 0.25 m): a grating's secondary peak.
float secondaryPeak(std::span<const float> g) {
    const glm::vec2 across(-WIND_DIR.y, WIND_DIR.x);
    float peak = -1.0f;
    bool negative = false;
    for (float r = 0.25f; r <= 60.0f; r += 0.25f) {
        const float c = foam::autocorrelation(g, 512, 0.5f, across, r);
        negative = negative || c < 0.0f;
        if (negative) peak = std::max(peak, c);
    }
    return peak;
}

} // namespace

TEST_CASE("the streak cells' lines are not a grating: no secondary peak across the wind, long along it, renewing in minutes",
          "[foam][wind]") {
    // Windrows wander, merge and part; their spacing spreads over a few metres to tens. The
    // convergence of a grating of two rolls (the spacings L and φ²·L = 3 m and 7.85 m, the
    // reference below) correlates with itself again wherever both fit a whole number of times
    // (24 m: 0.99); a field whose spacings spread over a band has no such peak: its
    // autocorrelation decays like the Fourier transform of the band (a band of 3–12 m: under
    // 0.3 beyond its first zero, bar the sampling of a finite map). Along the wind the lines run
    // on: 1/e there at least 3× as far as across. In time the lines move across the wind at
    // their own speeds (up to a spacing in STREAK_LIFE_S = 120 s): 10 s on the field still
    // correlates over 0.8 with itself, 4 minutes on under 0.3.
    const std::vector<float> now = streakConvergence(100.0);
    const float peak = secondaryPeak(now);
    std::vector<float> grating(now.size());
    const glm::vec2 across(-WIND_DIR.y, WIND_DIR.x);
    for (int j = 0; j < 512; ++j)
        for (int i = 0; i < 512; ++i) {
            const float eta = glm::dot(glm::vec2(float(i), float(j)) * 0.5f, across), k0 = 2.0f * float(M_PI) / 3.0f;
            grating[size_t(j) * 512 + size_t(i)] = k0 * std::cos(k0 * eta) + k0 / 2.618034f * std::cos(k0 / 2.618034f * eta);
        }
    const float gratingPeak = secondaryPeak(grating);
    const float along = foam::autocorrelationLength(now, 512, 0.5f, WIND_DIR, 100.0f);
    const float acrossLength = foam::autocorrelationLength(now, 512, 0.5f, across, 100.0f);
    const auto correlation = [&](std::span<const float> a, std::span<const float> b) {
        double ab = 0.0, aa = 0.0, bb = 0.0;
        for (size_t k = 0; k < a.size(); ++k) ab += double(a[k]) * b[k], aa += double(a[k]) * a[k], bb += double(b[k]) * b[k];
        return ab / std::sqrt(aa * bb);
    };
    const double soon = correlation(now, streakConvergence(110.0)), later = correlation(now, streakConvergence(340.0));
    INFO("secondary peak " << peak << " (two rolls: " << gratingPeak << "); 1/e at " << along << " m along, " << acrossLength
                           << " m across; correlation with itself 10 s on " << soon << ", 240 s on " << later);
    CHECK(gratingPeak > 0.9);
    CHECK(peak < 0.3);
    CHECK(along >= 3.0f * acrossLength);
    CHECK(soon > 0.8);
    CHECK(std::abs(later) < 0.3);
}
