// Whitecaps from the wind: the Jacobian threshold and gain of foam source (a) derived so that the
// stationary whitecap coverage is Monahan & O'Muircheartaigh's (1980) W(U10) (docs/splash_foam.md §2.1).
//
// The sea breaks where its surface folds: the Jacobian J of X → X + λ·D drops (Tessendorf 2001,
// Dupuy & Bruneton 2012). J − 1 is, to first order, a Gaussian field (λ·(∂Dx/∂x + ∂Dz/∂z), a
// linear filter of the heights) of standard deviation σ; a sample breaks while J < J_b = J̄ − a·σ.
// Foam source (a) covers a breaking sample's open share, f ← f + S·Δt·(1 − f); an episode of x
// times the mean's depth × duration leaves c = 1 − e^(−2x), which then decays as e^(−t/τ) and
// stays over ½ for τ·ln(2c) after its last breaking; x exponential of mean 1, t½ = 0.35·τ on average. For a Gaussian process at one point (Rice 1944) the share
// of time spent breaking is P = Φ(−a) and the breaking episodes start at a rate
// ν = (ω̄/2π)·e^(−a²/2), ω̄ = σ_J̇/σ the process's mean angular frequency. Episodes being rare and
// independent (Poisson), the share of the sea with coverage over ½ is
//     W(a) = 1 − exp(−(P + ν·t½)),
// and a is the root of W(a) = W_M(U10) = 3.84·10⁻⁶·U10^3.41 (capped at MAX_WHITECAP_FRACTION).
// ω̄ is read from the field itself: deep water ω² = g·k, so ω̄² = g·k̄ with k̄ the J-weighted mean
// wavenumber, which we take as σ_∇J/σ (the rms wavenumber; exact for one wavenumber).
// The gain fills an average episode twice over: rate = 2 / (mean depth below J_b × mean duration),
// with depth σ·(φ(a)/Φ(−a) − a) and duration P/ν, so its foam follows the depth of breaking: soft
// edges, no flat plateau at 1.
#pragma once
#include <span>

namespace ob::foam {

/// Whitecap fraction W = 3.84e-6 · U10^3.41 (Monahan & O'Muircheartaigh 1980, eq. 5), U10 in m/s.
double monahanFraction(double windSpeed);
/// The most W can be asked for (the fit is for U10 < ~25 m/s; beyond, the sea is not white all over).
constexpr double MAX_WHITECAP_FRACTION = 0.5;

/// Statistics of a periodic n×n Jacobian map over a tile of side `tile` metres.
struct JacobianStats {
    double mean = 1.0;        ///< J̄
    double sigma = 0.0;       ///< σ, the standard deviation of J
    double gradSigma = 0.0;   ///< σ_∇J, the rms |∇J| (1/m), central differences
};
JacobianStats jacobianStats(std::span<const float> jacobian, int n, float tile);

/// Source (a)'s law: S = rate · max(0, j0 − J).
struct WhitecapLaw {
    float j0 = 0.0f;    ///< J_b, the breaking threshold
    float rate = 0.0f;  ///< 1/s per unit of J below it
    double a = 0.0;     ///< J_b = J̄ − a·σ
};

/// The modelled stationary coverage W(a) above (P + ν·t½ under 1 − exp), for a sea whose J has
/// mean angular frequency omega (rad/s), foam decay time decayS.
double whitecapCoverage(double a, double omega, double decayS);
/// J_b and the gain for wind U10 (m/s), gravity g (m/s²), foam decay τ (s); rate 0 for a sea
/// whose J does not vary (σ ≈ 0) or no wind.
/// For a view without the map's history (the renderer's far sea): the J below which the wind's
/// whitecap share W_M of a sea with these statistics lies at one moment, J̄ − a_W·σ with
/// Φ(−a_W) = W_M; −∞ (none) for no wind or σ ≈ 0.
double instantWhitecapJacobian(const JacobianStats& stats, double windSpeed);
WhitecapLaw deriveWhitecapLaw(const JacobianStats& stats, double windSpeed, double gravity, double decayS);

} // namespace ob::foam
