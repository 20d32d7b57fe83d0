// The player's tools: picking at the cursor, then grab (a critically damped spring), stir (a
// moving source sphere through the bodies' stamp path), drop, erase and the cannon's aim.
#include "world/tools.h"

#include "assets/model.h"
#include "behaviours/cannon.h"
#include "behaviours/fish.h"
#include "behaviours/spawning.h"
#include "behaviours/step_input.h"
#include "core/log.h"
#include "ecs/components.h"
#include "interaction/sphere_set.h"
#include "physics/buoyancy.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/camera.h"
#include "world/picking.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ob::game {

namespace {

constexpr float PICK_DISTANCE_M = 3000.0f;   // farther than this the cursor points at nothing
constexpr float WHEEL_FACTOR = 1.1f;         // one wheel step scales a radius or distance by this
constexpr float THROW_SMOOTHING_S = 0.08f;   // the throw's velocity: the cursor's over about this long
constexpr float MAX_THROW_M_S = 60.0f;
constexpr float MAX_GRAB_ACCEL = 60.0f;      // m/s² the grab's spring gives at most (about 6 g)
constexpr glm::vec3 TOOL_MARKER_COLOR{1.0f, 0.85f, 0.2f};
constexpr glm::vec3 RING_COLOR{0.3f, 0.9f, 1.0f};

const water::WaterQuery* waterOf(ecs::World& world) {
    const OceanState* ocean = world.resource<OceanState>();
    return ocean && ocean->water ? ocean->water.get() : nullptr;
}

// The scene's gravity (environment.gravity, copied into [physics] when the world is built).
float gravityOf(ecs::World& world) { return physicsDef(world).gravity; }

// The ray under the cursor from the camera as it is now.
std::optional<Ray> cursorRay(ecs::World& world, const PlayerTools& tools, glm::vec2 cursor) {
    if (!tools.cursorKnown || world.pool<CameraRig>().size() == 0) return std::nullopt;
    const auto* viewport = world.resource<Viewport>();
    const glm::ivec2 size = viewport ? viewport->size : Viewport{}.size;
    return pixelRay(cameraView(world, size), size, cursor);
}

// --- grab: a spring of natural frequency f, critically damped, pulls the held point to the
// target; gravity is held up (buoyancy still adds where the body is wet).
void pullGrabbed(ecs::World& world, PlayerTools& tools, float dt) {
    Body* body = world.find<Body>(tools.grabbed);
    auto* physicsWorld = world.resource<physics::PhysicsWorld>();
    if (!body || !physicsWorld) {
        tools.grabbed = ecs::Entity::None;
        return;
    }
    const physics::BodyState s = physicsWorld->state(body->id);
    const float mass = physicsWorld->mass(body->id);
    const glm::vec3 point = s.position + s.rotation * tools.grabLocal;
    const glm::vec3 pointVelocity = s.linearVelocity + glm::cross(s.angularVelocity, point - s.position);
    const float omega = 2.0f * float(M_PI) * tools.def.grab_frequency_hz;
    // The spring cannot be stiffer than the step resolves (ω·dt ≤ 1 keeps it stable).
    const float w = std::min(omega, 1.0f / std::max(dt, 1e-6f));
    glm::vec3 accel = w * w * (tools.target - point) - 2.0f * w * (pointVelocity - tools.targetVelocity);
    // A hand, not a crane: a body taken far from the cursor is not flung there.
    if (glm::length(accel) > MAX_GRAB_ACCEL) accel *= MAX_GRAB_ACCEL / glm::length(accel);
    body->forces.push_back({mass * (accel + glm::vec3(0.0f, gravityOf(world), 0.0f)), point});
    physicsWorld->dampAngular(body->id, std::exp(-dt / 0.5f));  // a held body stops spinning in about 0.5 s
}

void release(ecs::World& world, PlayerTools& tools) {
    if (Body* body = world.find<Body>(tools.grabbed))
        if (auto* physicsWorld = world.resource<physics::PhysicsWorld>()) {
            glm::vec3 v = tools.targetVelocity;
            if (glm::length(v) > MAX_THROW_M_S) v *= MAX_THROW_M_S / glm::length(v);
            physicsWorld->setLinearVelocity(body->id, v);
            ++tools.throws;
        }
    tools.grabbed = ecs::Entity::None;
}

// The momentum a sphere of radius r moving at `velocity` through the water puts into the current
// layer over dt (a hand's drag, ½ρ·C_d·A·|v − u|·(v − u) on its wet cross-section A), taken
// implicitly on the water it sweeps (ρ·V: it can bring that water to its own speed, not past it,
// so a cursor's jump pushes no more than a steady stroke).
void pushWater(ecs::World& world, glm::vec3 centre, glm::vec3 velocity, float r, float dt) {
    auto* impulses = world.resource<WaterImpulses>();
    const OceanState* ocean = world.resource<OceanState>();
    const physics::PhysicsDef* def = findPhysicsDef(world);
    if (!impulses || !ocean || !def || dt <= 0.0f) return;
    const water::WaterSample s = ocean->water->sample(centre.x, centre.z);
    const float volume = physics::submergedSphereVolume(r, s.height - centre.y);
    if (volume <= 0.0f) return;
    const glm::vec3 relative = velocity - ocean->water->velocityAt(centre);
    const float area = float(M_PI) * r * r * volume / (4.0f / 3.0f * float(M_PI) * r * r * r);
    float c = 0.5f * def->water_density * def->quadratic_drag * area * glm::length(relative);
    c /= 1.0f + c * dt / (def->water_density * volume);
    impulses->react(-c * relative, centre, dt, r);
}

// --- stir: a source sphere held at stir_depth under the water point, moving with the cursor
void stir(ecs::World& world, PlayerTools& tools, glm::vec3 waterPoint, float dt) {
    const float r = tools.def.stir_radius;
    const glm::vec3 centre = waterPoint - glm::vec3(0.0f, tools.def.stir_depth, 0.0f);
    if (tools.stirrer == ecs::Entity::None || !world.has<ecs::Transform>(tools.stirrer)) {
        tools.stirrer = world.create();
        world.add<ecs::Transform>(tools.stirrer, {centre});
        const float density = physicsDef(world).water_density;
        world.add<ecs::Motion>(tools.stirrer, {glm::vec3(0.0f), density * 4.0f / 3.0f * float(M_PI) * r * r * r});
        interaction::BoundingSphere sphere;  // a hand pushed through the water: it pushes it down
        sphere.radius = r;
        sphere.direction = interaction::SphereDirection::Down;
        world.add<interaction::SphereSet>(tools.stirrer, {{sphere}, {}, false});
    }
    ecs::Transform& t = world.get<ecs::Transform>(tools.stirrer);
    const glm::vec3 velocity = (centre - t.position) / std::max(dt, 1e-6f);
    world.get<ecs::Motion>(tools.stirrer).velocity = velocity;
    t.position = centre;
    world.get<interaction::SphereSet>(tools.stirrer).spheres[0].radius = r;
    pushWater(world, centre, velocity, r, dt);
}

void stopStirring(ecs::World& world, PlayerTools& tools) {
    if (tools.stirrer != ecs::Entity::None) world.destroy(tools.stirrer);
    tools.stirrer = ecs::Entity::None;
}

} // namespace

ObjectDef dropDef(const PlayerTools& tools, glm::vec3 at, float yawDeg) {
    ObjectDef o;
    o.position = at + glm::vec3(0.0f, tools.def.drop_height, 0.0f);
    const auto box = [&](glm::vec3 size, float density, glm::vec3 color, const char* model) {
        o.type = ObjectType::Box;
        o.box.size = size;
        o.box.density = density;
        o.color = color;
        o.model = assets::projectModel(model);
    };
    switch (tools.def.drop) {
    case DropKind::Ball:
        o.type = ObjectType::Sphere;
        o.sphere.radius = tools.def.ball_radius;
        o.sphere.density = tools.def.ball_density;
        o.color = {0.8f, 0.25f, 0.1f};
        o.model = assets::projectModel("ball");
        break;
    case DropKind::Crate: box({1.0f, 1.0f, 1.0f}, 450.0f, {0.55f, 0.38f, 0.2f}, "crate"); break;
    case DropKind::Barrel: box({0.6f, 0.9f, 0.6f}, 550.0f, {0.35f, 0.2f, 0.1f}, "barrel"); break;
    case DropKind::Buoy:
        o.type = ObjectType::Sphere;
        o.sphere.radius = 0.45f;
        o.sphere.density = 250.0f;
        o.color = {0.9f, 0.1f, 0.05f};
        o.model = assets::projectModel("buoy");
        break;
    case DropKind::Raft: box({3.0f, 0.35f, 2.2f}, 500.0f, {0.6f, 0.5f, 0.3f}, "raft"); break;
    case DropKind::FishSchool:
        o = tools.fishTemplate;
        o.position = at;
        break;
    case DropKind::Ship:
        o = tools.shipTemplate;
        o.position = at + glm::vec3(0.0f, tools.def.drop_height, 0.0f);
        o.ship.yaw_deg = yawDeg;
        break;
    }
    o.name = std::string(enumName(tools.def.drop)) + "_" + std::to_string(tools.drops + 1);
    return o;
}

namespace {

// The body to erase: a fish's school, a ball, a ship... (not the player's cannon, which is not a body).
void erase(ecs::World& world, PlayerTools& tools, ecs::Entity e) {
    if (e == tools.grabbed) tools.grabbed = ecs::Entity::None;
    if (world.has<Body>(e)) destroyBody(world, e);
    else world.destroy(e);
    ++tools.erased;
}

// The player's cannon (or the first one): aimed at the point on the low arc, muzzle speed kept.
void fireAt(ecs::World& world, PlayerTools& tools, glm::vec3 point) {
    auto& cannons = world.pool<Cannon>();
    size_t pick = cannons.size();
    for (size_t i = 0; i < cannons.size() && pick == cannons.size(); ++i)
        if (cannons.components()[i].def.player) pick = i;
    if (pick == cannons.size() && cannons.size() > 0) pick = 0;
    if (pick == cannons.size()) {
        tools.message = "no cannon in this scene";
        return;
    }
    Cannon& c = cannons.components()[pick];
    const glm::vec3 pivot = world.get<ecs::Transform>(cannons.entities()[pick]).position;
    const glm::vec2 d(point.x - pivot.x, point.z - pivot.z);
    c.yawDeg = glm::degrees(std::atan2(d.x, d.y));
    // The ball leaves the barrel's end, which moves with the elevation: three rounds settle it.
    float elevation = c.elevationDeg;
    bool reachable = true;
    // The low arc, or the high one where the low would need the barrel below its lowest.
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 muzzle = pivot + cannonAim(c.yawDeg, elevation) * CANNON_BARREL;
        std::optional<float> e = ballisticElevationDeg(muzzle, point, c.def.muzzle_speed, gravityOf(world), false);
        if (e && *e < cannonElevationLimits().min) e = ballisticElevationDeg(muzzle, point, c.def.muzzle_speed, gravityOf(world), true);
        reachable = e.has_value();
        elevation = e ? *e : 45.0f;  // out of reach: the farthest shot
    }
    c.elevationDeg = clampElevationDeg(elevation);
    c.fireRequested = true;
    ++tools.shots;
    tools.message = reachable ? "" : "out of the cannon's reach: fired as far as it goes";
}

// Keys 1–5 choose the tool (the one held or stirring is let go); 3 again: the next object.
void chooseTool(ecs::World& world, PlayerTools& tools, const StepInput& input) {
    using platform::Key;
    constexpr Key NUMBER_KEYS[] = {Key::Num1, Key::Num2, Key::Num3, Key::Num4, Key::Num5};
    for (size_t k = 0; k < std::size(NUMBER_KEYS); ++k) {
        int presses = input.pressCount(NUMBER_KEYS[k]);
        if (presses == 0) continue;
        if (std::find(tools.allowed.begin(), tools.allowed.end(), Tool(k)) == tools.allowed.end()) {
            // Refused: the tool stays; the overlay says why.
            std::string list;
            for (Tool t : tools.allowed) list += std::string(list.empty() ? "" : ", ") + enumName(t);
            tools.message = std::string(enumName(Tool(k))) + " is off in this scene (its goal allows " + list + ")";
            continue;
        }
        if (tools.def.tool != Tool(k)) {
            if (tools.grabbed != ecs::Entity::None) release(world, tools);
            stopStirring(world, tools);
            tools.def.tool = Tool(k);
            tools.message = "";
            if (tools.def.tool == Tool::Cannon && world.pool<Cannon>().size() == 0) tools.message = "no cannon in this scene";
            --presses;
        }
        // 3 again: the next object to drop.
        if (tools.def.tool == Tool::Drop)
            tools.def.drop = DropKind((size_t(tools.def.drop) + size_t(presses)) % enumNames<DropKind>.size());
    }
}

// The grab tool this step: a click takes the body under the cursor; while held, the wheel
// moves it nearer or farther and the spring pulls it to the cursor's ray; let go, it is thrown.
void grabTool(ecs::World& world, PlayerTools& tools, StepInput& input, const std::optional<BodyPick>& body,
              const std::optional<Ray>& ray, float dt) {
    if (input.wasClicked(platform::MouseButton::Left) && tools.grabbed == ecs::Entity::None && body && world.has<Body>(body->entity)) {
        const ecs::Transform& t = world.get<ecs::Transform>(body->entity);
        tools.grabbed = body->entity;
        tools.grabLocal = glm::inverse(t.rotation) * (body->point - t.position);
        tools.holdDistance = body->distance;
        tools.target = body->point;
        tools.targetVelocity = glm::vec3(0.0f);
    }
    if (tools.grabbed == ecs::Entity::None || !ray) return;
    tools.holdDistance = std::clamp(tools.holdDistance * std::pow(WHEEL_FACTOR, input.scroll), 1.0f, 500.0f);
    input.scroll = 0.0f;  // the wheel is the hold distance's, not the camera's
    const glm::vec3 target = ray->at(tools.holdDistance);
    const float blend = 1.0f - std::exp(-dt / THROW_SMOOTHING_S);
    tools.targetVelocity += ((target - tools.target) / std::max(dt, 1e-6f) - tools.targetVelocity) * blend;
    tools.target = target;
    if (input.isDown(platform::MouseButton::Left)) pullGrabbed(world, tools, dt);
    else release(world, tools);
}

// The stir tool this step: while held, the wheel sizes the sphere (Shift: its depth, each within
// its key's range) and the sphere follows the water point.
void stirTool(ecs::World& world, PlayerTools& tools, StepInput& input, float dt) {
    const bool held = input.isDown(platform::MouseButton::Left);
    if (held && (input.scroll != 0.0f)) {
        const bool depth = input.isDown(platform::Key::Shift);
        float& value = depth ? tools.def.stir_depth : tools.def.stir_radius;
        const Limits limits = keyLimits<ToolsDef>(depth ? "stir_depth" : "stir_radius");
        value = std::clamp(depth ? value + 0.1f * input.scroll : value * std::pow(WHEEL_FACTOR, input.scroll), float(limits.min),
                           float(limits.max));
        input.scroll = 0.0f;
    }
    if (held && tools.waterPoint) stir(world, tools, *tools.waterPoint, dt);
    else stopStirring(world, tools);
}

} // namespace

std::optional<float> ballisticElevationDeg(glm::vec3 from, glm::vec3 to, float speed, float g, bool high) {
    const float x = std::hypot(to.x - from.x, to.z - from.z), y = to.y - from.y;
    const float v2 = speed * speed;
    if (x < 1e-4f) return y >= 0.0f ? 89.0f : -89.0f;
    if (g <= 0.0f) return glm::degrees(std::atan2(y, x));
    const float disc = v2 * v2 - g * (g * x * x + 2.0f * y * v2);
    if (disc < 0.0f) return std::nullopt;
    return glm::degrees(std::atan((v2 + (high ? 1.0f : -1.0f) * std::sqrt(disc)) / (g * x)));
}

void addPlayerTools(ecs::World& world, const ToolsDef& def, glm::ivec2 viewportSize, const ObjectDef& fishTemplate,
                    const ObjectDef& shipTemplate) {
    auto& tools = world.setResource(std::make_unique<PlayerTools>());
    tools.def = def;
    for (size_t t = 0; t < enumNames<Tool>.size(); ++t) tools.allowed.push_back(Tool(t));
    tools.fishTemplate = fishTemplate;
    tools.shipTemplate = shipTemplate;
    world.setResource(std::make_unique<Viewport>()).size = viewportSize;
}

void allowTools(ecs::World& world, const std::vector<Tool>& allowed) {
    auto* tools = world.resource<PlayerTools>();
    if (!tools || allowed.empty()) return;
    tools->allowed = allowed;
    if (std::find(allowed.begin(), allowed.end(), tools->def.tool) == allowed.end()) tools->def.tool = allowed.front();
}

void toolsSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* tools = world.resource<PlayerTools>();
    auto* input = world.resource<StepInput>();
    if (!tools || !input) return;
    const float dt = float(tick.dt);

    chooseTool(world, *tools, *input);

    // --- what the cursor points at
    tools->cursorKnown = input->cursorKnown;
    tools->waterPoint.reset();
    tools->hoverBody = ecs::Entity::None;
    const std::optional<Ray> ray = cursorRay(world, *tools, input->cursor);
    std::optional<BodyPick> body;
    if (ray) {
        if (const water::WaterQuery* water = waterOf(world)) tools->waterPoint = pickWater(*water, *ray, PICK_DISTANCE_M);
        // Bodies in front of the water, or just under it (a ball floating low).
        const float reach = tools->waterPoint ? glm::length(*tools->waterPoint - ray->origin) + 1.0f : PICK_DISTANCE_M;
        body = pickBody(world, *ray, reach);
        if (body) tools->hoverBody = body->entity;
    }
    const bool clicked = input->wasClicked(platform::MouseButton::Left);

    // --- the tool acts
    switch (tools->def.tool) {
    case Tool::Grab: grabTool(world, *tools, *input, body, ray, dt); break;
    case Tool::Stir: stirTool(world, *tools, *input, dt); break;
    case Tool::Drop:
        if (clicked && tools->waterPoint && world.resource<physics::PhysicsWorld>()) {
            const float yaw = ray ? glm::degrees(std::atan2(ray->direction.x, ray->direction.z)) : 0.0f;
            spawnObject(world, dropDef(*tools, *tools->waterPoint, yaw), tick.step * 7919ull + uint64_t(tools->drops));
            ++tools->drops;
        }
        break;
    case Tool::Erase:
        if (clicked && body) erase(world, *tools, body->entity);
        break;
    case Tool::Cannon:
        if (clicked && tools->waterPoint) fireAt(world, *tools, *tools->waterPoint);
        break;
    }
}

ecs::Entity highlightedBody(ecs::World& world) {
    const auto* tools = world.resource<PlayerTools>();
    if (!tools) return ecs::Entity::None;
    if (tools->grabbed != ecs::Entity::None) return tools->grabbed;
    const bool acts = tools->def.tool == Tool::Grab || tools->def.tool == Tool::Erase;
    return acts ? tools->hoverBody : ecs::Entity::None;
}

void appendToolDraws(ecs::World& world, std::vector<gfx::ObjectDraw>& draws, glm::vec3 eye) {
    const auto* tools = world.resource<PlayerTools>();
    if (!tools) return;
    if (tools->waterPoint) {
        // A marker a few pixels wide at any distance: 0.6 % of its distance.
        const glm::vec3 p = *tools->waterPoint;
        const float r = std::max(0.04f, 0.006f * glm::length(p - eye));
        draws.push_back({gfx::MeshKind::Sphere, glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(r, 0.35f * r, r)), TOOL_MARKER_COLOR, ""});
        if (tools->def.tool == Tool::Stir) {
            const float ring = tools->def.stir_radius;
            draws.push_back({gfx::MeshKind::Ring, glm::scale(glm::translate(glm::mat4(1.0f), p), glm::vec3(ring)), RING_COLOR, ""});
        }
    }
}

} // namespace ob::game
