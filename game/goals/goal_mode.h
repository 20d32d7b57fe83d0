// What every goal mode's registration struct (goals/<mode>/<mode>_def.h) has, and the list
// type goal_modes.h registers them with.
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace ob::game {

class Goal;
struct GoalSetup;

/// Reports a problem with a [game] key the reader cannot find: the key ("target_prefix",
/// "gates[1].port") and what is wrong.
using GoalError = std::function<void(const std::string& key, const std::string& message)>;

/// A list of goal modes. Each Mode has: NAME (game.mode's word), Def (its own keys of [game],
/// with describe(); read only in that mode), check(const GoalSetup&, const GoalError&) (what
/// the reader cannot check: the objects it names exist and suit it) and make(const GoalSetup&)
/// (its Goal, once the scene's objects exist). Mode 0, "none", is a scene without a goal.
template <class... Modes> struct GoalModeList {
    static constexpr std::size_t COUNT = sizeof...(Modes);
    /// game.mode's words: "none", then each mode's NAME in the list's order.
    static constexpr std::array<const char*, COUNT + 1> WORDS{"none", Modes::NAME...};
    /// Every mode's Def in one struct: GameDef derives from it, so each mode's keys are plain
    /// fields of [game] (game.zone_radius).
    struct Defs : Modes::Def... {};
    /// f.template operator()<Mode>() for each mode, in the list's order.
    template <class F> static void forEach(F&& f) { (f.template operator()<Modes>(), ...); }
    /// f.template operator()<Mode>() for the mode at `index` (< COUNT).
    template <class F> static void visit(std::size_t index, F&& f) {
        std::size_t k = 0;
        ((k++ == index ? void(f.template operator()<Modes>()) : void()), ...);
    }
};

} // namespace ob::game
