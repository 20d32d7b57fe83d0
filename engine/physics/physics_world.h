// The rigid-body world: Bullet's discrete dynamics world behind a small facade (Bullet's
// headers stay in physics_world.cpp). Bodies are addressed by BodyId.
#pragma once
#include "physics/physics_def.h"

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>

namespace ob::physics {

/// A body of the world (index; never reused within a world).
enum class BodyId : uint32_t { None = ~0u };

/// A body's pose and motion.
struct BodyState {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 linearVelocity{0.0f};   ///< m/s
    glm::vec3 angularVelocity{0.0f};  ///< rad/s
};

/// Where a ray first meets a body.
struct RayHit {
    BodyId id = BodyId::None;
    glm::vec3 point{0.0f};       ///< world m
    glm::vec3 normal{0, 1, 0};   ///< the body's outward unit normal there
    float fraction = 1.0f;       ///< of the way from the ray's start to its end
};

class PhysicsWorld {
public:
    explicit PhysicsWorld(const PhysicsDef& def);
    ~PhysicsWorld();
    PhysicsWorld(const PhysicsWorld&) = delete;
    PhysicsWorld& operator=(const PhysicsWorld&) = delete;

    /// A solid sphere of `radius` m and `mass` kg (0: static).
    BodyId addSphere(float radius, float mass, const BodyState& start);
    /// A solid box of `halfExtents` m and `mass` kg (0: static).
    BodyId addBox(const glm::vec3& halfExtents, float mass, const BodyState& start);
    /// Removes a body (its id stays retired).
    void remove(BodyId id);

    /// Adds a force (N) at a world point for the next step.
    void applyForce(BodyId id, const glm::vec3& force, const glm::vec3& worldPoint);
    /// Sets a body's linear velocity (m/s), as a throw does.
    void setLinearVelocity(BodyId id, const glm::vec3& velocity);
    /// Puts a body at a pose with the given motion (a righted ship, a test's start).
    void setState(BodyId id, const BodyState& state);
    /// The first body the segment from `from` to `to` (world m) meets, if any.
    std::optional<RayHit> rayCast(const glm::vec3& from, const glm::vec3& to) const;
    /// Multiplies the angular velocity by `factor` (water damping).
    void dampAngular(BodyId id, float factor);
    /// Advances by dt seconds (def.substeps fixed sub-steps); forces are cleared after.
    void step(float dt);

    BodyState state(BodyId id) const;
    float mass(BodyId id) const;
    int bodyCount() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ob::physics
