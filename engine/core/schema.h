// Def schema: every Def struct lists its keys once, in a `describe(Visitor&, Def&)` beside it.
// The same list drives the TOML loader (core/toml_reader), the TOML writer (core/toml_writer)
// and the ImGui editor (gfx/ui_overlay).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob {

/// Accepted range of a numeric key (inclusive), and extra constraints. The one place a key's
/// range is written: the loader, a live `set`, the editor's sliders and the messages read it.
struct Limits {
    double min = -std::numeric_limits<double>::infinity(); ///< smallest accepted value
    double max = std::numeric_limits<double>::infinity();  ///< largest accepted value
    bool powerOfTwo = false;                               ///< integer keys: must be 2^k
    bool nonZero = false;                                  ///< vectors: must not be all zero
    bool orZero = false;                                   ///< 0 is accepted too (a key whose 0 means "auto")
};

/// Limits [lo, hi].
constexpr Limits range(double lo, double hi) { return Limits{lo, hi, false, false, false}; }
/// A power of two in [lo, hi].
constexpr Limits powerOfTwo(int lo, int hi) { return Limits{double(lo), double(hi), true, false, false}; }
/// 0 ("auto") or a value in [lo, hi].
constexpr Limits autoOrRange(double lo, double hi) { return Limits{lo, hi, false, false, true}; }
/// Any non-zero vector (a direction).
constexpr Limits direction() { return Limits{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), false, true, false}; }
/// No constraint.
constexpr Limits any() { return Limits{}; }

/// Whether `value` is within `l`'s range (its power-of-two and non-zero rules aside).
constexpr bool inRange(const Limits& l, double value) { return (value >= l.min && value <= l.max) || (l.orZero && value == 0.0); }

/// A number as a range shows it: integers without a fraction, others in %g.
inline std::string rangeNumber(double v) {
    char buf[32];
    if (v == double(int64_t(v)) && v > -1e15 && v < 1e15) std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
    else std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

/// The range as messages and help print it: "in [16, 2048]", ">= 0", "0 (auto) or in [16, 2048]"
/// ("" when unbounded).
inline std::string rangeText(const Limits& l) {
    const bool lo = l.min > -std::numeric_limits<double>::infinity(), hi = l.max < std::numeric_limits<double>::infinity();
    std::string text = lo && hi ? "in [" + rangeNumber(l.min) + ", " + rangeNumber(l.max) + "]"
                       : lo     ? ">= " + rangeNumber(l.min)
                       : hi     ? "<= " + rangeNumber(l.max)
                                : "";
    return l.orZero ? "0 (auto) or " + text : text;
}

/// When a change of a key reaches the running world. Live keys are those a `set` event, the
/// UI and an input script's [[set]] may change while the world runs; the rest are read once
/// when the world is built (a change needs a restart).
enum class Change : uint8_t {
    AtStart,  ///< read once at start
    Live,     ///< may change while the world runs (the systems that use it poll its section's version)
};
/// The mark a describe() puts last on a live key's line: `v.field("exposure", d.exposure, range(0.01, 16), "...", LIVE);`
inline constexpr Change LIVE = Change::Live;

namespace detail {
/// The visitor keyLimits() walks a describe() with.
struct KeyLimitsFinder {
    std::string_view key;
    Limits found{};
    template <class T> void field(const char* k, T&, Limits l, const char*, Change = {}) {
        if (key == k) found = l;
    }
    template <class T> void field(const char*, T&, const char*, Change = {}) {}
    template <class D> void section(const char*, D&) {}
    template <class D> void fields(D&) {}
    template <class I> void list(const char*, std::vector<I>&, const char*) {}
};
} // namespace detail

/// The Limits a Def's describe() gives its key `key` (any() where it has no such number): the
/// editor's sliders and the clamps of the code that moves a key read its range here, so the
/// range stays written once, in describe().
template <class Def> Limits keyLimits(std::string_view key) {
    detail::KeyLimitsFinder find{key};
    Def def{};
    describe(find, def);
    return find.found;
}

/// A key that takes one of a fixed set of words is an enum with its words declared beside it,
/// in the enum's order, by a function `names` found by argument-dependent lookup:
///
///   enum class Fresnel : uint8_t { Schlick, Exact };
///   constexpr std::array<const char*, 2> names(Fresnel) { return {"schlick", "exact"}; }
template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E e) { names(e); };

/// The words of E's values, in order.
template <NamedEnum E> inline constexpr auto enumNames = names(E{});

/// The word of one value ("exact").
template <NamedEnum E> constexpr const char* enumName(E value) { return enumNames<E>[std::size_t(value)]; }

/// The value whose word is `word`; false when none is.
template <NamedEnum E> bool enumFromName(std::string_view word, E& value) {
    for (std::size_t i = 0; i < enumNames<E>.size(); ++i)
        if (word == enumNames<E>[i]) return value = E(i), true;
    return false;
}

/// An enum's words as visitors take them (a visitor's non-template `choice` member does the
/// work once for every enum).
using Words = std::span<const char* const>;

/// The visitor interface a describe() function is written against (documentation only:
/// describe() is a template, any type with these members works). Every `field` takes a last
/// `Change` argument (default Change::AtStart): LIVE marks a key that may change while the
/// world runs; a visitor that does not care declares it unnamed, `Change = {}`.
///   void field(const char* key, bool& value, const char* doc);
///   void field(const char* key, int& value, Limits, const char* doc);
///   void field(const char* key, uint64_t& value, const char* doc);
///   void field(const char* key, float& value, Limits, const char* doc);
///   void field(const char* key, glm::vec2& / glm::vec3& value, Limits, const char* doc);
///   void field(const char* key, std::string& value, const char* doc);             // free text
///   template <NamedEnum E> void field(const char* key, E& value, const char* doc);  // one of E's words
///   void field(const char* key, std::vector<glm::vec2>& points, Limits, const char* doc);  // [[x, z], ...]
///   template <class Def> void section(const char* key, Def& def);
///   template <class Def> void fields(Def& def);  // another Def's keys in this table (an object type's settings)
///   template <class Item> void list(const char* key, std::vector<Item>& items, const char* doc);
/// and, optionally (the loader has it):
///   void refuse(const char* key, const std::string& why);  // a key this Def does not read as it stands

} // namespace ob
