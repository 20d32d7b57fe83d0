// Checks of command-line values that several subcommands share (CLI11 validators).
#pragma once
#include "core/printable.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <charconv>
#include <climits>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <string>

namespace ob::game {

/// A number that is finite once stored in a float (every float and double flag: NaN, inf and
/// 1e39 are refused; a value that is no number is left to the flag's own conversion).
inline const CLI::Validator FINITE_NUMBER(
    [](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(begin, &end);
        if (end == begin || *end != '\0') return "";
        if (!std::isfinite(v) || std::fabs(v) > double(FLT_MAX) || (errno == ERANGE && std::fabs(v) > 1.0))
            return "must be a finite number (|x| <= 3.4e38), got '" + text + "'";
        return "";
    },
    "FINITE");

/// A whole number >= 0 (seeds, frame counts), named in the message as given: CLI11's own
/// NonNegativeNumber prints its upper bound, DBL_MAX, in 309 digits.
inline const CLI::Validator NON_NEGATIVE(
    [](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end != begin && *end == '\0' && v < 0.0) return "must be >= 0, got " + text;
        return "";
    },
    "NONNEGATIVE");

/// A whole number in [lo, hi], read as the integer it is: a value beyond the flag's type (a
/// seed of 23 digits) is refused naming the flag, never wrapped, saturated or rounded.
inline CLI::Validator integerIn(long long lo, long long hi) {
    const std::string range = hi == LLONG_MAX ? ">= " + std::to_string(lo) : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            long long v = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, v);
            if (error == std::errc::result_out_of_range)
                return "must be an integer " + range + ", got " + clipped(text) + " (beyond a 64-bit integer)";
            if (error != std::errc() || stop != end) return "must be an integer " + range + ", got " + quotedValue(text);
            if (v < lo || v > hi) return "must be " + range + ", got " + text;
            return "";
        },
        "INT " + range);
}

/// A seed: sim.seed's range, a TOML integer >= 0.
inline const CLI::Validator SEED = integerIn(0, LLONG_MAX);

/// An output or input path given on the command line: an empty one is an error, not "none".
inline const CLI::Validator NON_EMPTY_PATH(
    [](std::string& text) -> std::string { return text.empty() ? "the path is empty (give a file name)" : ""; }, "PATH");

} // namespace ob::game
