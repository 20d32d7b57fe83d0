// Def schema: every Def struct lists its keys once, in a `describe(Visitor&, Def&)` beside it.
// The same list drives the TOML loader (core/toml_reader), the TOML writer (core/toml_writer)
// and the ImGui editor (gfx/ui_overlay).
#pragma once
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ob {

/// Accepted range of a numeric key (inclusive), and extra constraints.
struct Limits {
    double min = -std::numeric_limits<double>::infinity(); ///< smallest accepted value
    double max = std::numeric_limits<double>::infinity();  ///< largest accepted value
    bool powerOfTwo = false;                               ///< integer keys: must be 2^k
    bool nonZero = false;                                  ///< vectors: must not be all zero
};

/// Limits [lo, hi].
constexpr Limits range(double lo, double hi) { return Limits{lo, hi, false, false}; }
/// A power of two in [lo, hi].
constexpr Limits powerOfTwo(int lo, int hi) { return Limits{double(lo), double(hi), true, false}; }
/// Any non-zero vector (a direction).
constexpr Limits direction() { return Limits{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), false, true}; }
/// No constraint.
constexpr Limits any() { return Limits{}; }

/// String keys that take one of a fixed set of words.
using Choices = std::initializer_list<const char*>;

/// The visitor interface a describe() function is written against (documentation only:
/// describe() is a template, any type with these members works).
///   void field(const char* key, bool& value, const char* doc);
///   void field(const char* key, int& value, Limits, const char* doc);
///   void field(const char* key, uint64_t& value, const char* doc);
///   void field(const char* key, float& value, Limits, const char* doc);
///   void field(const char* key, glm::vec2& / glm::vec3& value, Limits, const char* doc);
///   void field(const char* key, std::string& value, Choices, const char* doc);
///   void field(const char* key, std::vector<glm::vec2>& points, Limits, const char* doc);  // [[x, z], ...]
///   template <class Def> void section(const char* key, Def& def);
///   template <class Item> void list(const char* key, std::vector<Item>& items, const char* doc);

} // namespace ob
