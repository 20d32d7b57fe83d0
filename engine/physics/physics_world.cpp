// Bullet discrete dynamics world.
#include "physics/physics_world.h"

#include <btBulletDynamicsCommon.h>
#include <vector>

namespace ob::physics {

namespace {
btVector3 bt(const glm::vec3& v) { return {v.x, v.y, v.z}; }
glm::vec3 gl(const btVector3& v) { return {float(v.x()), float(v.y()), float(v.z())}; }
} // namespace

struct PhysicsWorld::Impl {
    PhysicsDef def;
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    struct Body {
        std::unique_ptr<btCollisionShape> shape;
        std::unique_ptr<btDefaultMotionState> motion;
        std::unique_ptr<btRigidBody> body;
    };
    std::vector<Body> bodies;  // index = BodyId; removed bodies keep an empty slot

    BodyId add(std::unique_ptr<btCollisionShape> shape, float mass, const BodyState& s) {
        btVector3 inertia(0, 0, 0);
        if (mass > 0.0f) shape->calculateLocalInertia(mass, inertia);
        btTransform t(btQuaternion(s.rotation.x, s.rotation.y, s.rotation.z, s.rotation.w), bt(s.position));
        Body b;
        b.motion = std::make_unique<btDefaultMotionState>(t);
        btRigidBody::btRigidBodyConstructionInfo info(mass, b.motion.get(), shape.get(), inertia);
        b.body = std::make_unique<btRigidBody>(info);
        b.body->setLinearVelocity(bt(s.linearVelocity));
        b.body->setAngularVelocity(bt(s.angularVelocity));
        b.body->setActivationState(DISABLE_DEACTIVATION);  // the water never lets a body sleep
        b.body->setUserIndex(int(bodies.size()));          // its BodyId, for ray casts
        b.shape = std::move(shape);
        world.addRigidBody(b.body.get());
        bodies.push_back(std::move(b));
        return BodyId(uint32_t(bodies.size() - 1));
    }
    btRigidBody* get(BodyId id) const {
        size_t i = size_t(id);
        return i < bodies.size() ? bodies[i].body.get() : nullptr;
    }
};

PhysicsWorld::PhysicsWorld(const PhysicsDef& def) : m_impl(std::make_unique<Impl>()) {
    m_impl->def = def;
    m_impl->world.setGravity(btVector3(0, -def.gravity, 0));
}

PhysicsWorld::~PhysicsWorld() {
    for (auto& b : m_impl->bodies)
        if (b.body) m_impl->world.removeRigidBody(b.body.get());
}

BodyId PhysicsWorld::addSphere(float radius, float mass, const BodyState& start) {
    return m_impl->add(std::make_unique<btSphereShape>(radius), mass, start);
}

BodyId PhysicsWorld::addBox(const glm::vec3& halfExtents, float mass, const BodyState& start) {
    return m_impl->add(std::make_unique<btBoxShape>(bt(halfExtents)), mass, start);
}

void PhysicsWorld::remove(BodyId id) {
    btRigidBody* body = m_impl->get(id);
    if (!body) return;
    m_impl->world.removeRigidBody(body);
    m_impl->bodies[size_t(id)] = {};
}

void PhysicsWorld::applyForce(BodyId id, const glm::vec3& force, const glm::vec3& worldPoint) {
    if (btRigidBody* body = m_impl->get(id)) body->applyForce(bt(force), bt(worldPoint) - body->getCenterOfMassPosition());
}

void PhysicsWorld::setLinearVelocity(BodyId id, const glm::vec3& velocity) {
    if (btRigidBody* body = m_impl->get(id)) body->setLinearVelocity(bt(velocity));
}

void PhysicsWorld::setState(BodyId id, const BodyState& s) {
    btRigidBody* body = m_impl->get(id);
    if (!body) return;
    btTransform t;
    t.setOrigin(bt(s.position));
    t.setRotation(btQuaternion(s.rotation.x, s.rotation.y, s.rotation.z, s.rotation.w));
    body->setWorldTransform(t);
    body->getMotionState()->setWorldTransform(t);
    body->setLinearVelocity(bt(s.linearVelocity));
    body->setAngularVelocity(bt(s.angularVelocity));
}

std::optional<RayHit> PhysicsWorld::rayCast(const glm::vec3& from, const glm::vec3& to) const {
    btCollisionWorld::ClosestRayResultCallback closest(bt(from), bt(to));
    m_impl->world.rayTest(bt(from), bt(to), closest);
    if (!closest.hasHit() || !closest.m_collisionObject) return std::nullopt;
    RayHit hit;
    hit.id = BodyId(uint32_t(closest.m_collisionObject->getUserIndex()));
    hit.point = gl(closest.m_hitPointWorld);
    hit.normal = gl(closest.m_hitNormalWorld.normalized());
    hit.fraction = float(closest.m_closestHitFraction);
    return hit;
}

void PhysicsWorld::dampAngular(BodyId id, float factor) {
    if (btRigidBody* body = m_impl->get(id)) body->setAngularVelocity(body->getAngularVelocity() * factor);
}

void PhysicsWorld::step(float dt) {
    const int substeps = m_impl->def.substeps;
    m_impl->world.stepSimulation(dt, substeps, dt / float(substeps));
    m_impl->world.clearForces();
}

BodyState PhysicsWorld::state(BodyId id) const {
    BodyState s;
    const btRigidBody* body = m_impl->get(id);
    if (!body) return s;
    const btTransform& t = body->getCenterOfMassTransform();
    btQuaternion q = t.getRotation();
    s.position = gl(t.getOrigin());
    s.rotation = glm::quat(float(q.w()), float(q.x()), float(q.y()), float(q.z()));
    s.linearVelocity = gl(body->getLinearVelocity());
    s.angularVelocity = gl(body->getAngularVelocity());
    return s;
}

float PhysicsWorld::mass(BodyId id) const {
    const btRigidBody* body = m_impl->get(id);
    return body && body->getInvMass() > 0 ? float(1.0 / body->getInvMass()) : 0.0f;
}

int PhysicsWorld::bodyCount() const {
    int n = 0;
    for (const auto& b : m_impl->bodies) n += b.body ? 1 : 0;
    return n;
}

} // namespace ob::physics
