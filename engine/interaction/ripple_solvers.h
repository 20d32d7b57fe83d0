// The registration table of the ripple solvers: one line per solver (its name, Def, checks,
// factory and GPU move, all in its own folder). Adding a solver: its folder and one line below.
#pragma once
#include "interaction/ewave/ewave_def.h"
#include "interaction/kang2008/kang2008_def.h"

#include <array>
#include <cstddef>
#include <string>
#include <tuple>

namespace ob::interaction {

/// A check of a [ripples] table across keys that failed: the key to name and why.
struct RippleDefError {
    std::string key;      ///< the [ripples] key the message is about ("boundary")
    std::string message;  ///< what is wrong and what to do
};

/// A list of solver registrations. Each Model has: NAME (ripples.model's word), Def (its own
/// keys of [ripples], with describe()), KNOB (the key a live panel offers), validate(const
/// RippleDef&), make(const RippleDef&) (the CPU solver), moveToGpu(RippleSolver&) (defined
/// in its gpu/ folder, in the GL library) and stepArrays(RippleArrays&) (the `ripple` tool).
template <class... Models> struct RippleModelList {
    static constexpr std::size_t COUNT = sizeof...(Models);
    static constexpr std::array<const char*, COUNT> NAMES{Models::NAME...};
    /// Every model's Def in one struct: RippleDef derives from it, so that each model's keys
    /// are plain fields of [ripples] (ripples.damping), read whatever the model.
    struct Defs : Models::Def... {};
    /// f.template operator()<Model>() for each model, in the table's order.
    template <class F> static void forEach(F&& f) { (f.template operator()<Models>(), ...); }
    /// f.template operator()<Model>() for the model at `index` (< COUNT); its result.
    template <class F> static auto visit(std::size_t index, F&& f) {
        using Result = decltype(f.template operator()<std::tuple_element_t<0, std::tuple<Models...>>>());
        Result result{};
        std::size_t k = 0;
        ((k++ == index ? void(result = f.template operator()<Models>()) : void()), ...);
        return result;
    }
};

// --- the registration table: every solver is one entry of this line (and its _def.h include
// above). A new one goes at the end: RippleModel is the index into this list.
using RippleModels = RippleModelList<Kang2008Model, EWaveModel>;

} // namespace ob::interaction
