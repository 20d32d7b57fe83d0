// The goal system: the mode's Goal made from [game] and the spawned objects, the checks the
// reader cannot make, the goal clock and the fixed-step judge (docs/games.md has the rules).
#include "goals/goals.h"

#include "ecs/components.h"
#include "goals/goal.h"
#include "sim/objects.h"

#include <cstdio>

namespace ob::game {

namespace {

constexpr size_t EVENTS_KEPT = 32;  // goal events the view keeps for its cues

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

// The goal clock: it runs from the first step, or from the player's first input acting in the world.
bool runClock(GameState& game, const ecs::Tick& tick, bool playerActed) {
    if (!game.started) {
        game.started = !game.waitsForPlayer || playerActed;
        game.startedAt = tick.time;
        if (!game.started) return false;
    }
    game.time = tick.end - game.startedAt;
    return true;
}

} // namespace

void GoalEvents::add(ecs::World& world, ecs::Entity entity, MarkState state, double time) {
    const ecs::Transform* t = world.find<ecs::Transform>(entity);
    if (!t) return;
    m_events.push_back({t->position, time, state});
    if (m_events.size() > EVENTS_KEPT) m_events.erase(m_events.begin());
}

std::vector<const ObjectDef*> objectsNamed(const std::vector<ObjectDef>& objects, const std::string& prefix) {
    std::vector<const ObjectDef*> found;
    if (prefix.empty()) return found;
    for (const ObjectDef& o : objects)
        if (o.name.compare(0, prefix.size(), prefix) == 0) found.push_back(&o);
    return found;
}

void checkFloatingShapes(const std::vector<const ObjectDef*>& named, const std::string& key, const std::string& what,
                         const std::function<void(const std::string&, const std::string&)>& error) {
    for (const ObjectDef* o : named)
        if (o->type != ObjectType::Sphere && o->type != ObjectType::Box)
            error(key, "'" + o->name + "' is a " + enumName(o->type) + " (" + what + " are spheres or boxes)");
}

std::vector<Tool> allowedTools(const GameDef& game) {
    if (!game.tools.empty()) return game.tools;
    std::vector<Tool> all;
    for (size_t t = 0; t < enumNames<Tool>.size(); ++t)
        if (game.mode == GameMode::None || (Tool(t) != Tool::Grab && Tool(t) != Tool::Drop)) all.push_back(Tool(t));
    return all;
}

std::vector<std::pair<std::string, std::string>> gameKeysNotReadBy(GameMode mode) {
    std::vector<std::pair<std::string, std::string>> refused;
    size_t m = 0;
    GoalModes::forEach([&]<class Mode>() {
        if (++m == size_t(mode)) return;  // mode m is 1 + its index
        for (const std::string& key : keysOf<typename Mode::Def>())
            refused.push_back({key, std::string("a ") + enumName(mode) + " game has no '" + key + "' (a " + Mode::NAME +
                                        " game's key)"});
    });
    return refused;
}

std::vector<std::string> validateGame(const GameDef& game, const std::vector<ObjectDef>& objects,
                                      const std::function<std::string(const std::string&)>& where) {
    std::vector<std::string> errors;
    if (game.mode == GameMode::None) return errors;
    const GoalError error = [&](const std::string& key, const std::string& message) {
        errors.push_back(where("game." + key) + ": game." + key + ": " + message);
    };
    const GoalSetup setup{nullptr, game, objects};
    GoalModes::visit(size_t(game.mode) - 1, [&]<class Mode>() { Mode::check(setup, error); });
    return errors;
}

void addGame(ecs::World& world, const GameDef& def, const std::vector<ObjectDef>& objects, float endTime) {
    auto& game = world.setResource(std::make_unique<GameState>());
    game.def = def;
    game.endTime = endTime;
    if (def.mode == GameMode::None) return;
    const GoalSetup setup{&world, def, objects};
    GoalModes::visit(size_t(def.mode) - 1, [&]<class Mode>() { game.goal = Mode::make(setup); });
}

void gameStep(ecs::World& world, const ecs::Tick& tick, bool playerActed) {
    auto* game = world.resource<GameState>();
    if (!game || game->over()) return;

    // --- the mode's judge, on the poses of the last physics step, once the goal clock runs
    Verdict verdict;
    const bool running = runClock(*game, tick, playerActed);
    if (game->goal) {
        game->goal->prepare(world, running);
        if (running) verdict = game->goal->judge(world, game->time, game->events);
    }

    // --- the clock: the time limit, then [sim] end_time end what is undecided
    const double eps = 1e-9;
    if (running && verdict.result == GameResult::Running && game->goal && game->def.time_limit > 0.0f &&
        game->time >= double(game->def.time_limit) - eps)
        verdict = {GameResult::Lost, "time is up"};
    if (verdict.result == GameResult::Running && game->endTime > 0.0f && tick.end >= double(game->endTime) - eps)
        verdict = {game->goal ? GameResult::Lost : GameResult::Ended, "the scene's end_time"};
    game->result = verdict.result;
    if (!verdict.reason.empty()) game->reason = verdict.reason;
    if (game->over())
        if (auto* control = world.resource<ecs::SimControl>()) control->stopped = true;
}

const GameState* gameState(ecs::World& world) { return world.resource<GameState>(); }

void goalClockWaitsForPlayer(ecs::World& world) {
    if (auto* game = world.resource<GameState>(); game && !game->started) game->waitsForPlayer = true;
}

} // namespace ob::game
