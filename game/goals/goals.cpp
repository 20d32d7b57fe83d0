// The goal system: set-up from [game] and the spawned objects, the checks the reader cannot
// make, and the fixed-step judge (docs/games.md has the rules in words).
#include "goals/goals.h"

#include "assets/model.h"
#include "behaviours/cannon.h"
#include "behaviours/ship.h"
#include "ecs/components.h"
#include "goals/goal_geometry.h"
#include "sim/objects.h"
#include "world/controls.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ob::game {

namespace {

// A goal state's look: `color` for a built-in mesh, `tint` over a model's own colours (bright
// multipliers, so a red-and-white buoy turns yellow, green or red where it is white).
struct StateLook {
    glm::vec3 color, tint;
};
constexpr StateLook HIT_LOOK{{0.25f, 0.25f, 0.25f}, {0.22f, 0.22f, 0.25f}};    // a target hit: spent, dark grey
constexpr StateLook NEXT_LOOK{{1.0f, 0.75f, 0.05f}, {1.7f, 1.3f, 0.1f}};      // the gate to pass next: bright yellow
constexpr StateLook PASSED_LOOK{{0.1f, 0.6f, 0.15f}, {0.2f, 1.4f, 0.3f}};     // a gate passed, a crate in the zone: green
constexpr StateLook MISSED_LOOK{{0.8f, 0.05f, 0.05f}, {1.7f, 0.12f, 0.08f}};  // a gate missed: red
constexpr glm::vec3 OUTSIDE_TINT{0.5f, 0.8f, 1.7f};                         // a herded crate outside the zone: blue
constexpr glm::vec3 MARKER_COLOR{1.0f, 0.45f, 0.05f};   // the herd zone's edge: orange
constexpr size_t EVENTS_KEPT = 32;                      // goal events the view keeps for its cues
constexpr float MARKER_RADIUS = 0.5f;                   // m
constexpr float TOUCH_SLACK = 0.05f;                    // m a ball may stay off a target and still touch it (Bullet's contact margin)

bool startsWith(const std::string& name, const std::string& prefix) {
    return !prefix.empty() && name.compare(0, prefix.size(), prefix) == 0;
}

// The keys a describe() visits, in order.
struct KeyLister {
    std::vector<std::string> keys;
    template <class T, class... Rest> void field(const char* key, T&, Rest&&...) { keys.push_back(key); }
    template <class T> void list(const char* key, T&, const char*) { keys.push_back(key); }
};

template <class Def> std::vector<std::string> keysOf() {
    KeyLister lister;
    Def def;
    describe(lister, def);
    return lister.keys;
}

void show(ecs::World& world, ecs::Entity e, const StateLook& look) {
    if (Renderable* r = world.find<Renderable>(e)) {
        r->color = look.color;
        r->modelTint = look.tint;
    }
}

// An event the view marks on the water (a ring where it happened).
void addEvent(ecs::World& world, GameState& game, ecs::Entity e, glm::vec3 color, double now) {
    const ecs::Transform* t = world.find<ecs::Transform>(e);
    if (!t) return;
    game.events.push_back({t->position, now, color});
    if (game.events.size() > EVENTS_KEPT) game.events.erase(game.events.begin());
}

glm::vec2 xz(glm::vec3 p) { return {p.x, p.z}; }

// --- the modes' judges: each returns the result this step reached (Running while undecided)

GameResult judgeTargets(ecs::World& world, GameState& game, double now) {
    auto& balls = world.pool<Cannonball>();
    for (size_t i = 0; i < balls.size(); ++i) {
        const ecs::Entity ball = balls.entities()[i];
        const glm::vec3 position = world.get<ecs::Transform>(ball).position;
        BallTrace* trace = world.find<BallTrace>(ball);
        if (!trace) {
            // Fired since the last step: its path starts where it is now.
            world.add<BallTrace>(ball, {position});
            trace = world.find<BallTrace>(ball);
        }
        const float r = world.get<Body>(ball).probes[0].radius + TOUCH_SLACK;
        for (GameTarget& target : game.targets) {
            const ecs::Transform* t = target.hit ? nullptr : world.find<ecs::Transform>(target.entity);
            if (!t) continue;
            const bool touched = target.sphere ? sweptSphereTouchesSphere(trace->last, position, r, t->position, target.radius)
                                               : sweptSphereTouchesBox(trace->last, position, r, t->position, t->rotation, target.half);
            if (!touched) continue;
            target.hit = true;
            target.hitTime = now;
            ++game.score;
            show(world, target.entity, HIT_LOOK);
            addEvent(world, game, target.entity, HIT_LOOK.color, now);
        }
        trace->last = position;
    }
    if (game.score == int(game.targets.size())) {
        game.reason = "all " + std::to_string(game.targets.size()) + " targets hit";
        return GameResult::Won;
    }
    return GameResult::Running;
}

void showNextGate(ecs::World& world, const GameState& game) {
    if (game.nextGate >= game.gates.size()) return;
    show(world, game.gates[game.nextGate].port, NEXT_LOOK);
    show(world, game.gates[game.nextGate].starboard, NEXT_LOOK);
}

GameResult judgeRace(ecs::World& world, GameState& game, double now) {
    const ecs::Transform* ship = world.find<ecs::Transform>(game.racer);
    if (!ship) return GameResult::Running;
    const glm::vec2 from = game.racerLast, to = xz(ship->position);
    game.racerLast = to;
    // The first gate ahead (from the next one on) that the path crosses the right way: the
    // gates before it are missed.
    for (size_t g = game.nextGate; g < game.gates.size(); ++g) {
        GameGate& gate = game.gates[g];
        const ecs::Transform* port = world.find<ecs::Transform>(gate.port);
        const ecs::Transform* starboard = world.find<ecs::Transform>(gate.starboard);
        if (!port || !starboard || gateCrossing(xz(port->position), xz(starboard->position), from, to) <= 0) continue;
        for (size_t m = game.nextGate; m < g; ++m) {
            game.gates[m].state = GateState::Missed;
            game.gates[m].time = now;
            ++game.missed;
            show(world, game.gates[m].port, MISSED_LOOK);
            show(world, game.gates[m].starboard, MISSED_LOOK);
            addEvent(world, game, game.gates[m].port, MISSED_LOOK.color, now);
            game.lastMissed = "gate " + std::to_string(m + 1) + " missed";
            game.lastMissedTime = now;
        }
        gate.state = GateState::Passed;
        gate.time = now;
        ++game.score;
        show(world, gate.port, PASSED_LOOK);
        show(world, gate.starboard, PASSED_LOOK);
        addEvent(world, game, game.racer, PASSED_LOOK.color, now);
        game.nextGate = g + 1;
        showNextGate(world, game);
        break;
    }
    if (game.missed > 0 && game.def.race.missed_gate == MissedGate::Lose) {
        game.reason = game.lastMissed;
        return GameResult::Lost;
    }
    if (game.nextGate < game.gates.size()) return GameResult::Running;
    char text[96];
    const double limit = game.def.time_limit;
    if (limit > 0.0 && game.raceTime() > limit) {
        std::snprintf(text, sizeof text, "finished in %.1f s with penalties, over the %.0f s limit", game.raceTime(), limit);
        game.reason = text;
        return GameResult::Lost;
    }
    std::snprintf(text, sizeof text, "all %zu gates in %.1f s", game.gates.size(), game.raceTime());
    game.reason = text;
    return GameResult::Won;
}

GameResult judgeHerd(ecs::World& world, GameState& game, double now) {
    const glm::vec2 centre = game.def.herd.zone_center;
    const float radius = game.def.herd.zone_radius;
    game.score = 0;
    for (size_t i = 0; i < game.crates.size(); ++i) {
        const ecs::Transform* t = world.find<ecs::Transform>(game.crates[i]);
        const bool in = t && glm::dot(xz(t->position) - centre, xz(t->position) - centre) <= radius * radius;
        if (in != game.inside[i]) {
            // Green inside, its own colour (a model: blue) again outside.
            show(world, game.crates[i], in ? PASSED_LOOK : StateLook{game.crateColors[i], OUTSIDE_TINT});
            addEvent(world, game, game.crates[i], in ? PASSED_LOOK.color : OUTSIDE_TINT, now);
            game.inside[i] = in;
        }
        game.score += in ? 1 : 0;
    }
    if (game.score >= game.needed) {
        game.reason = std::to_string(game.score) + " " + game.def.herd.herd_prefix + "s in the ring";
        return GameResult::Won;
    }
    return GameResult::Running;
}

// Moorings: a critically damped horizontal spring to the anchor, for the next physics step,
// taken implicitly (backward Euler of x'' = −ω²x − 2ωx' over dt): stable at any period, so
// the stiffest legal mooring (1 ms) holds its body rather than throwing it.
void pullMoorings(ecs::World& world, const GameState& game, float dt) {
    if (game.def.mooring_period <= 0.0f) return;
    const float omega = 2.0f * float(M_PI) / game.def.mooring_period;
    const float implicit = 1.0f + 2.0f * omega * dt + omega * omega * dt * dt;
    for (const Mooring& m : game.moorings) {
        Body* body = world.find<Body>(m.entity);
        if (!body) continue;
        const glm::vec3 p = world.get<ecs::Transform>(m.entity).position;
        const ecs::Motion& motion = world.get<ecs::Motion>(m.entity);
        glm::vec3 force = -motion.mass * (omega * omega * (p - m.anchor) + (2.0f * omega + omega * omega * dt) * motion.velocity) / implicit;
        force.y = 0.0f;
        body->forces.push_back({force, p});
    }
}

// The zone's edge floats ride the surface (drawn only: nothing collides with them).
void floatMarkers(ecs::World& world, const GameState& game) {
    const OceanState* ocean = world.resource<OceanState>();
    if (!ocean || !ocean->water) return;
    for (ecs::Entity e : game.markers) {
        glm::vec3& p = world.get<ecs::Transform>(e).position;
        p.y = ocean->water->sample(p.x, p.z, {.ripples = false}).height;
    }
}

// The goal clock: it runs from the first step, or from the player's first input acting in the
// world (the ship's racer position is kept fresh while it waits, so no crossing is seen later).
bool runClock(ecs::World& world, GameState& game, const ecs::Tick& tick) {
    if (!game.started) {
        const auto* input = world.resource<StepInput>();
        game.started = !game.waitsForPlayer || (input && actsInWorld(*input));
        game.startedAt = tick.time;
        if (!game.started) {
            if (const ecs::Transform* ship = world.find<ecs::Transform>(game.racer)) game.racerLast = xz(ship->position);
            return false;
        }
    }
    game.time = tick.end - game.startedAt;
    return true;
}

} // namespace

double GameState::raceTime() const {
    return time + (def.race.missed_gate == MissedGate::Penalty ? double(missed) * double(def.race.miss_penalty) : 0.0);
}

std::vector<Tool> allowedTools(const GameDef& game) {
    if (!game.tools.empty()) return game.tools;
    std::vector<Tool> all;
    for (size_t t = 0; t < enumNames<Tool>.size(); ++t)
        if (game.mode == GameMode::None || (Tool(t) != Tool::Grab && Tool(t) != Tool::Drop)) all.push_back(Tool(t));
    return all;
}

std::vector<std::pair<std::string, std::string>> gameKeysNotReadBy(GameMode mode) {
    const std::vector<std::string> modeKeys[] = {{}, keysOf<TargetsGameDef>(), keysOf<RaceGameDef>(), keysOf<HerdGameDef>()};
    static_assert(std::size(modeKeys) == enumNames<GameMode>.size(), "one settings struct per mode");
    std::vector<std::pair<std::string, std::string>> refused;
    for (size_t m = 0; m < std::size(modeKeys); ++m) {
        if (m == size_t(mode)) continue;
        for (const std::string& key : modeKeys[m])
            refused.push_back({key, std::string("a ") + enumName(mode) + " game has no '" + key + "' (a " +
                                        enumNames<GameMode>[m] + " game's key)"});
    }
    return refused;
}

std::vector<std::string> validateGame(const SceneDef& scene, const std::function<std::string(const std::string&)>& where) {
    const GameDef& game = scene.game;
    std::vector<std::string> errors;
    auto error = [&](const std::string& key, const std::string& message) {
        errors.push_back(where("game." + key) + ": game." + key + ": " + message);
    };
    auto named = [&](const std::string& prefix) {
        std::vector<const ObjectDef*> found;
        for (const ObjectDef& o : scene.objects)
            if (startsWith(o.name, prefix)) found.push_back(&o);
        return found;
    };
    auto count = [&](ObjectType type) {
        return std::count_if(scene.objects.begin(), scene.objects.end(), [type](const ObjectDef& o) { return o.type == type; });
    };
    switch (game.mode) {
    case GameMode::None: break;
    case GameMode::Targets: {
        const auto targets = named(game.targets.target_prefix);
        if (targets.empty())
            error("target_prefix", "no object's name starts with '" + game.targets.target_prefix + "' (the targets)");
        for (const ObjectDef* o : targets)
            if (o->type != ObjectType::Sphere && o->type != ObjectType::Box)
                error("target_prefix", "target '" + o->name + "' is a " + enumName(o->type) + " (targets are spheres or boxes)");
        if (count(ObjectType::Cannon) == 0) error("mode", "a targets game needs a cannon in [[objects]]");
        break;
    }
    case GameMode::Race: {
        if (game.race.gates.empty()) error("mode", "a race needs [[game.gates]]");
        if (count(ObjectType::Ship) == 0) error("mode", "a race needs a ship in [[objects]]");
        for (size_t g = 0; g < game.race.gates.size(); ++g) {
            const GateDef& gate = game.race.gates[g];
            const std::string at = "gates[" + std::to_string(g) + "].";
            for (const auto& [key, name] : {std::pair{"port", gate.port}, std::pair{"starboard", gate.starboard}}) {
                const std::string& wanted = name;  // a structured binding cannot be captured (C++17; clang refuses it)
                const bool exists = std::any_of(scene.objects.begin(), scene.objects.end(), [&](const ObjectDef& o) {
                    return !wanted.empty() && o.name == wanted && (o.type == ObjectType::Sphere || o.type == ObjectType::Box);
                });
                if (!exists) error(at + key, "no sphere or box object is named '" + name + "'");
            }
            if (gate.port == gate.starboard && !gate.port.empty()) error(at + "starboard", "the same object as port");
        }
        break;
    }
    case GameMode::Herd: {
        const auto crates = named(game.herd.herd_prefix);
        if (crates.empty()) error("herd_prefix", "no object's name starts with '" + game.herd.herd_prefix + "' (the crates)");
        for (const ObjectDef* o : crates)
            if (o->type != ObjectType::Sphere && o->type != ObjectType::Box)
                error("herd_prefix", "'" + o->name + "' is a " + enumName(o->type) + " (herded objects are spheres or boxes)");
        if (game.herd.herd_count > int(crates.size()))
            error("herd_count", std::to_string(game.herd.herd_count) + " crates to win, but the scene has " +
                                    std::to_string(crates.size()));
        break;
    }
    }
    return errors;
}

void addGame(ecs::World& world, const SceneDef& scene) {
    auto& game = world.setResource(std::make_unique<GameState>());
    game.def = scene.game;
    game.endTime = scene.sim.end_time;
    const GameDef& def = scene.game;
    auto moor = [&](ecs::Entity e) {
        if (const ecs::Transform* t = world.find<ecs::Transform>(e); t && world.has<Body>(e)) game.moorings.push_back({e, t->position});
    };
    switch (def.mode) {
    case GameMode::None: break;
    case GameMode::Targets:
        for (const ObjectDef& o : scene.objects) {
            if (!startsWith(o.name, def.targets.target_prefix)) continue;
            GameTarget target;
            target.entity = findObject(world, o.name);
            target.name = o.name;
            target.sphere = o.type == ObjectType::Sphere;
            target.radius = o.sphere.radius;
            target.half = 0.5f * o.box.size;
            game.targets.push_back(target);
            moor(target.entity);
        }
        break;
    case GameMode::Race: {
        auto& ships = world.pool<Ship>();
        for (size_t i = 0; i < ships.size() && game.racer == ecs::Entity::None; ++i)
            if (ships.components()[i].def.player) game.racer = ships.entities()[i];
        if (game.racer == ecs::Entity::None && ships.size() > 0) game.racer = ships.entities()[0];
        if (const ecs::Transform* t = world.find<ecs::Transform>(game.racer)) game.racerLast = xz(t->position);
        for (const GateDef& g : def.race.gates) {
            game.gates.push_back({findObject(world, g.port), findObject(world, g.starboard)});
            moor(game.gates.back().port);
            moor(game.gates.back().starboard);
        }
        showNextGate(world, game);
        break;
    }
    case GameMode::Herd: {
        for (const ObjectDef& o : scene.objects)
            if (startsWith(o.name, def.herd.herd_prefix)) {
                game.crates.push_back(findObject(world, o.name));
                game.crateColors.push_back(o.color);
                show(world, game.crates.back(), {o.color, OUTSIDE_TINT});
            }
        game.inside.assign(game.crates.size(), false);
        game.needed = def.herd.herd_count > 0 ? def.herd.herd_count : int(game.crates.size());
        const glm::vec2 c = def.herd.zone_center;
        for (int k = 0; k < def.herd.zone_markers; ++k) {
            const float a = 2.0f * float(M_PI) * float(k) / float(def.herd.zone_markers);
            const ecs::Entity e = world.create();
            world.add<ecs::Transform>(e, {glm::vec3(c.x + def.herd.zone_radius * std::cos(a), 0.0f,
                                                    c.y + def.herd.zone_radius * std::sin(a))});
            world.add<Renderable>(e, {gfx::MeshKind::Sphere, glm::vec3(MARKER_RADIUS), MARKER_COLOR, assets::projectModel("buoy")});
            game.markers.push_back(e);
        }
        break;
    }
    }
}

void gameSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* game = world.resource<GameState>();
    if (!game || game->over()) return;

    // --- moorings pull (this step's physics), the zone's floats ride the waves
    pullMoorings(world, *game, float(tick.dt));
    floatMarkers(world, *game);

    // --- the mode's judge, on the poses of the last physics step, once the goal clock runs
    GameResult result = GameResult::Running;
    const bool running = runClock(world, *game, tick);
    if (running) switch (game->def.mode) {
        case GameMode::None: break;
        case GameMode::Targets: result = judgeTargets(world, *game, game->time); break;
        case GameMode::Race: result = judgeRace(world, *game, game->time); break;
        case GameMode::Herd: result = judgeHerd(world, *game, game->time); break;
        }

    // --- the clock: the time limit, then [sim] end_time end what is undecided
    const double eps = 1e-9;
    if (running && result == GameResult::Running && game->def.mode != GameMode::None && game->def.time_limit > 0.0f &&
        game->time >= double(game->def.time_limit) - eps) {
        result = GameResult::Lost;
        game->reason = "time is up";
    }
    if (result == GameResult::Running && game->endTime > 0.0f && tick.end >= double(game->endTime) - eps) {
        result = game->def.mode == GameMode::None ? GameResult::Ended : GameResult::Lost;
        game->reason = "the scene's end_time";
    }
    game->result = result;
    if (game->over())
        if (auto* control = world.resource<ecs::SimControl>()) control->stopped = true;
}

const GameState* gameState(ecs::World& world) { return world.resource<GameState>(); }

void goalClockWaitsForPlayer(ecs::World& world) {
    if (auto* game = world.resource<GameState>(); game && !game->started) game->waitsForPlayer = true;
}

} // namespace ob::game
