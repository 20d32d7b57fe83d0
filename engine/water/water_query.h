// WaterQuery: the one interface through which physics and gameplay read the water surface
// (after Crest's CollProvider / CollProviderNull), and FlatWater, its still-plane stub for tests.
#pragma once
#include <cstddef>
#include <span>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob::water {

/// The surface above one world position (x, z) at the query's current time.
struct WaterSample {
    float height = 0.0f;             ///< y of the surface, metres
    glm::vec3 normal{0, 1, 0};       ///< unit normal, y up
    float verticalVelocity = 0.0f;   ///< ∂height/∂t at the fixed world (x, z), m/s: how fast the drawn surface rises there
    /// The water's own velocity at the surface there (x, y, z), m/s: the particle velocity of
    /// the waves (orbital: Gerstner, cascades, ripples) plus the current. Unlike
    /// verticalVelocity (Eulerian: ∂h/∂t = w − u·∇h) it stays bounded where the surface folds.
    glm::vec3 velocity{0.0f};
};

/// Which layers of the surface a query includes; a left-out layer reads as flat, still
/// water. Buoyancy, for one, asks for everything but the ripples (it reads the ripples round
/// a body apart, so that a body does not float on its own crater).
struct WaterLayers {
    bool gerstner = true;  ///< the Gerstner swell
    bool fft = true;       ///< the FFT cascades
    bool ripples = true;   ///< the interactive ripple layer
    bool currents = true;  ///< the surface current layer (velocity only: it has no height)
    /// The FFT cascades displaced by at most the waves' own orbits (choppiness ≤ 1, a linear
    /// wave's Lagrangian surface): above 1 the choppiness sharpens the drawn crests only, a
    /// look, and folds the surface in a steep sea. What floating bodies ride (physics).
    bool orbital = false;
};

/// Reads the composite water surface at world positions. Implementations are immutable
/// between their owner's updates, so any number of threads may query at once.
class WaterQuery {
public:
    virtual ~WaterQuery() = default;

    /// The surface above world (x, z), metres: every layer.
    WaterSample sample(float x, float z) const { return sample(x, z, WaterLayers{}); }
    /// The surface of the given layers only above world (x, z).
    virtual WaterSample sample(float x, float z, WaterLayers layers) const = 0;

    /// sample() at every point (world x, z); out.size() must equal points.size(). The default
    /// loops over sample(); implementations override it with a vectorised path.
    virtual void sampleBatch(std::span<const glm::vec2> points, std::span<WaterSample> out) const;

    /// The water's velocity (m/s, x y z) at world point p on or under the surface of the given
    /// layers: each wave part decays with depth below the local surface as e^{k·z} (deep-water
    /// potential flow; see the implementation for the k each part uses); the current is a slab.
    /// A point above the surface reads the surface's. The default: sample()'s velocity, no decay.
    virtual glm::vec3 velocityAt(glm::vec3 p, WaterLayers layers) const { return sample(p.x, p.z, layers).velocity; }
    glm::vec3 velocityAt(glm::vec3 p) const { return velocityAt(p, WaterLayers{}); }
    /// The surface above world point p (sample()'s height, normal and vertical velocity) with
    /// `velocity` the water's at p itself (velocityAt): what a body's probe reads, in one query.
    virtual WaterSample sampleBelow(glm::vec3 p, WaterLayers layers) const {
        WaterSample s = sample(p.x, p.z, layers);
        s.velocity = velocityAt(p, layers);
        return s;
    }
};

/// A still, flat sea at height h0: normal up, no motion.
class FlatWater final : public WaterQuery {
public:
    /// The plane y = height (metres).
    explicit FlatWater(float height = 0.0f) : m_height(height) {}

    using WaterQuery::sample;
    WaterSample sample(float x, float z, WaterLayers layers) const override;
    void sampleBatch(std::span<const glm::vec2> points, std::span<WaterSample> out) const override;

private:
    float m_height;
};

} // namespace ob::water
