// The composite surface (docs/references.md#composite-ocean, [Lee2007] §2.3, §3.5) as a WaterQuery: Gerstner (analytic) +
// every FFT cascade (bilinear on the CPU maps) + a ripple hook, inverted to world (x, z).
#pragma once
#include "ocean/gerstner.h"
#include "water/water_query.h"

#include <array>
#include <functional>
#include <span>
#include <vector>

namespace ob::ocean {
class OceanFftCpu;
}

namespace ob::water {

/// The ripple layer's entry point (the layer itself lives in engine/interaction): a height
/// field in world space, added at world (x, z) without horizontal displacement.
struct RippleHook {
    std::function<float(float x, float z)> height;     ///< metres; empty = no ripple layer
    std::function<float(float x, float z)> rate;       ///< ∂height/∂t, m/s; empty = 0
    std::function<glm::vec2(float x, float z)> slope;  ///< (∂h/∂x, ∂h/∂z); empty = central differences of height
    float slopeStep = 0.05f;                           ///< step of those differences, metres
    /// The layer's horizontal particle velocity at its surface (x, z), m/s; empty = 0 (a
    /// height field without a velocity law: its vertical velocity only).
    std::function<glm::vec2(float x, float z)> horizontalVelocity;
    /// The wavenumber (rad/m) the layer's velocity decays with below the surface, e^{−k·depth}; empty = 0.
    std::function<float()> wavenumber;
};

/// The surface current layer's entry point (engine/currents): its horizontal velocity at world
/// (x, z), m/s, the same over the layer's depth.
using CurrentHook = std::function<glm::vec2(float x, float z)>;

/// How sample() inverts the displacement and forms the normal.
struct CompositeSettings {
    /// Newton: α ← α − J⁻¹(α + D(α) − x), J = I + ∂D/∂α from the analytic Gerstner terms and
    /// the gradient of the bilinear FFT displacement (quadratic convergence inside a cell),
    /// with a plain fixed-point step where det J < 0.1 (near folds). FixedPoint: α ← x − D(α),
    /// linear with rate ≈ ‖∂D/∂α‖ (≤ Σ k·a for Gerstner).
    enum class Inversion { Newton, FixedPoint };
    /// SlopeSum (docs/references.md#composite-ocean, what the renderer does): slope = Gerstner world slope (−n.xz/n.y of
    /// its analytic normal) + the FFT slope maps ∂h/∂X at the rest point + ripple slope.
    /// Exact: the normal of the displaced parametric surface, slope = J^-T ∇_α y (differs from
    /// SlopeSum where the FFT is choppy or rides on a steep Gerstner wave).
    enum class Normal { SlopeSum, Exact };

    Inversion inversion = Inversion::Newton;  ///< see Inversion
    int maxIterations = 8;                    ///< evaluations per query at most, [1, 64]
    float tolerance = 1e-4f;                  ///< metres: stop when |α + D(α) − x| is below max(tolerance, 4e-7·|x|)
    Normal normal = Normal::SlopeSum;         ///< see Normal
};

/// Result of inverting the horizontal displacement at one world point.
struct RestPoint {
    glm::vec2 rest{0.0f};   ///< (α, β), metres, whose displaced position is (x, z)
    int iterations = 0;     ///< evaluations used
    float residual = 0.0f;  ///< |α + D(α) − (x, z)|, metres, at the returned rest point
};

/// Gerstner + FFT cascades + ripples. A rest point (α, β) moves to
///   (α + Dg(α, β) + λ·Σc Dc(α, β),  yg(α, β) + Σc hc(α, β),  β + …)
/// (Dg, yg: Gerstner; Dc, hc: cascade c's maps sampled bilinearly at the rest point, tile side
/// patchSize(c), periodic), and the ripple height is added at the displaced (x, z). sample()
/// finds the rest point under (x, z) (CompositeSettings::Inversion), reads everything there.
/// Vertical velocity is ∂height/∂t at the fixed world (x, z) (Eulerian): with y the height and
/// D the horizontal displacement of the rest point, ∂height/∂t = ∂y/∂t − s·∂D/∂t, s = J^-T ∇_α y
/// the world slope of the surface as sampled (FFT part: gradients of the bilinear maps, so
/// it is the time derivative of sample().height; on a cell edge the bilinear surface has a
/// kink and the one-sided value of the cell the rest point is in is returned). Gerstner rates
/// are analytic; the FFT's come from the maps of the last three update()s (3-point backward
/// difference, second order, error ≈ (ω·Δt)²/3 relative: 0.3% for ω = 6 rad/s at 60 Hz;
/// first order with two updates, 0 with one: see primeAt()). Inversion, measured on
/// [Min2023]'s 8 waves (Σ k·a = 0.68) + the default 256² cascade over 20 000 points: Newton is at
/// float precision (~1e-5 m) after 4 evaluations everywhere, mean 3.1 to reach 1e-4 m; fixed
/// point needs ~6 (median) to 12+ (near folds).
/// The normal uses the FFT's analytic slope maps (smooth), not the bilinear gradients.
/// Zero latency: sample() reads the FFT's maps of its latest update() directly.
class CompositeWater final : public WaterQuery {
public:
    /// waves under gravity (m/s²); fft: the CPU ocean to add (not owned, may be null), which
    /// must outlive this object. Call update() before the first query.
    CompositeWater(std::span<const ocean::GerstnerWave> waves, float gravity,
                   const ocean::OceanFftCpu* fft = nullptr, CompositeSettings settings = {});

    /// Points the query at another CPU ocean of the same resolution and cascades (the double
    /// buffer of a prefetched step); update() then records its maps.
    void setFft(const ocean::OceanFftCpu* fft) { m_fft = fft; }
    /// Replaces the Gerstner waves (a live change's cross-fade), keeping the time; gravity m/s².
    void setWaves(std::span<const ocean::GerstnerWave> waves, float gravity);
    /// Sets the ripple layer (replaces any earlier hook).
    void setRipple(RippleHook hook);
    /// Sets the current layer (replaces any earlier hook; empty = no current).
    void setCurrent(CurrentHook hook);
    /// Sets the time, seconds, and records the FFT's new maps for its rates. Call once per
    /// step after fft->update(t), with the same t.
    void update(double t);
    /// Time of the last update(), seconds.
    double time() const { return m_gerstner.time(); }
    /// Order of the FFT rate estimate now: 0 (one update seen), 1 or 2.
    int fftRateOrder() const;

    using WaterQuery::sample;
    /// Left-out layers add nothing (the Newton inversion then moves only by the ones kept).
    /// velocity: Gerstner's particle velocity + the cascades' (∂D/∂t, ∂h/∂t) at the rest point
    /// (choppiness 1: the waves' orbital motion, whatever λ the drawn surface uses) + the
    /// ripple hook's + the current's. It is a particle's velocity, so it stays bounded where
    /// the surface folds (det J → 0), where verticalVelocity (Eulerian) does not.
    WaterSample sample(float x, float z, WaterLayers layers) const override;
    void sampleBatch(std::span<const glm::vec2> points, std::span<WaterSample> out) const override;

    using WaterQuery::velocityAt;
    /// The velocity at world point p, `depth` = (surface of the layers asked) − p.y ≥ 0 below the
    /// surface above it: Gerstner exact per wave (e^{−k·depth} on each orbit: GerstnerField::velocity);
    /// each cascade per band of |K|, band b × e^{−k_b·depth} (ocean/velocity_bands.h: 1 m down a
    /// mode's own e^{−k·depth} within 3 %, docs/velocity_bands.md), or × e^{k_c·z} (k_c
    /// cascadeWavenumber) above the mean level and while the FFT makes no band maps; the ripples
    /// by e^{−k_r·depth} (RippleHook::wavenumber);
    /// the current the same at every depth of its layer.
    glm::vec3 velocityAt(glm::vec3 p, WaterLayers layers) const override;
    /// sample() and velocityAt() from one inversion.
    WaterSample sampleBelow(glm::vec3 p, WaterLayers layers) const override;
    /// k_c of cascade c, rad/m: Σ k·ω²·|h̃0|² / Σ ω²·|h̃0|² over its modes (the wavenumber its
    /// velocity variance is centred on), from the spectrum at the last measureWavenumbers(): the
    /// cascade's one decay factor above its mean level and without band maps.
    float cascadeWavenumber(int c) const { return m_cascades[size_t(c)].k; }
    /// Measures every k_c again from the FFT's spectra (after h̃0 changed: a sea's fade, a test's
    /// hand-set modes); the constructor measures them once. O(N²) per cascade.
    void measureWavenumbers();

    /// Horizontal velocity (m/s, world x and z) of the surface above each world (x, z) point:
    /// ∂(x, z)/∂t of the particle displaced there (its rest point found as sample() finds it),
    /// Gerstner Σ K̂·a·ω·cos θ (analytic) plus the cascades' λ·∂D/∂t (the rates behind the
    /// vertical velocity; 0 until two updates), plus the ripple hook's horizontal velocity and the
    /// current's: the one velocity the foam and the bodies are carried by.
    /// out.size() must equal points.size().
    void horizontalVelocityBatch(std::span<const glm::vec2> points, std::span<glm::vec2> out) const;
    /// The same from a guess of each point's rest point (rest[i]: in, the guess; out, the rest
    /// point used), accepted once |α + D(α) − x| ≤ tolerance (metres; at least the settings'):
    /// the velocity is then a particle's up to `tolerance` from the point, off by |∂u/∂x| times
    /// it at most. A guess from a recent step's rest point needs fewer evaluations than the point.
    void horizontalVelocityBatch(std::span<const glm::vec2> points, std::span<glm::vec2> out, std::span<glm::vec2> rest,
                                 float tolerance) const;

    /// The rest point under world (x, z) and how the inversion went.
    RestPoint restPoint(float x, float z) const;
    /// Forward map: world position (x, y, z) of rest point (α, β), ripples included.
    glm::vec3 displace(float alpha, float beta) const;

    /// The Gerstner layer.
    const ocean::GerstnerField& gerstner() const { return m_gerstner; }
    /// The settings.
    const CompositeSettings& settings() const { return m_settings; }

    /// FFT layer at a rest point, all cascades summed, displacement terms multiplied by λ.
    /// Two sets of derivatives: the FFT's analytic maps (smooth; the normals use them) and the
    /// gradient of the bilinear interpolant actually sampled (Newton and the vertical velocity
    /// use them, so that it is the time derivative of sample().height).
    struct FftTerms {
        float h = 0, sx = 0, sz = 0;          ///< height m, analytic slope ∂h/∂X (eq. 6)
        float dx = 0, dz = 0;                 ///< λ·D, metres
        float dxx = 0, dxz = 0, dzz = 0;      ///< analytic λ·∂Dx/∂x, λ·∂Dx/∂z (= λ·∂Dz/∂x), λ·∂Dz/∂z
        float hx = 0, hz = 0;                 ///< gradient of the bilinear h
        float jxx = 0, jxz = 0, jzx = 0, jzz = 0; ///< gradient of the bilinear λ·D: ∂Dx/∂α, ∂Dx/∂β, ∂Dz/∂α, ∂Dz/∂β
        float ht = 0, dxt = 0, dzt = 0;       ///< ∂h/∂t, λ·∂Dx/∂t, λ·∂Dz/∂t (m/s)
        float ut = 0, vt = 0;                 ///< ∂Dx/∂t, ∂Dz/∂t (m/s): the orbital velocity, choppiness 1
    };
    /// FFT terms at rest point (α, β) (zero without an FFT).
    FftTerms fftTerms(float alpha, float beta) const;

private:
    struct Eval {
        ocean::GerstnerSums g;
        FftTerms f;
    };
    struct Cascade {
        float invCell = 0.0f;                      // N / patch size, 1/m
        float k = 0.0f;                            // velocity-weighted mean wavenumber, rad/m (cascadeWavenumber)
        std::array<std::vector<float>, 3> frames;  // (h, Dx, Dz) planar per frame, ring of 3
        std::vector<float> rate;                   // (∂h/∂t, ∂Dx/∂t, ∂Dz/∂t, 0) per point
    };
    struct Bilinear;
    float lambda(WaterLayers layers) const;
    void addDisplacement(float alpha, float beta, FftTerms& t, float lambda) const;
    void addSurface(float alpha, float beta, FftTerms& t, float lambda) const;
    bool step(const Eval& e, float x, float z, glm::vec2& rest, float& residual, float tolerance = 0.0f) const;
    WaterSample finish(const Eval& e, float x, float z, WaterLayers layers = {}) const;
    glm::vec3 velocityBelow(const Eval& e, float alpha, float beta, glm::vec3 p, WaterLayers layers) const;
    glm::vec3 cascadeVelocity(int c, float alpha, float beta, float z) const;
    template <class Done>
    void invert(float x, float z, WaterLayers layers, Done&& done) const;
    void recordFrame();
    template <class Finish>
    void invertBatch(std::span<const glm::vec2> points, Finish&& finish, const glm::vec2* guess = nullptr,
                     float tolerance = 0.0f) const;

    ocean::GerstnerField m_gerstner;
    const ocean::OceanFftCpu* m_fft = nullptr;
    CompositeSettings m_settings;
    RippleHook m_ripple;
    CurrentHook m_current;
    std::vector<Cascade> m_cascades;
    std::array<double, 3> m_frameTimes{};
    int m_newest = -1;      // ring slot of the newest frame
    int m_frameCount = 0;   // frames recorded, ≤ 3
};

/// Brings fft (may be null) and water to time t with two earlier updates at t − 2·step and
/// t − step, so the FFT rates are second order from the first query (tools, tests). water
/// must have been made with this fft.
void primeAt(ocean::OceanFftCpu* fft, CompositeWater& water, double t, double step = 1.0 / 60.0);

} // namespace ob::water
