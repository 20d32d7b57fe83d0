// Error kinds and their exit codes: bad user input (exit 2) versus runtime failure (exit 1).
#pragma once
#include <stdexcept>
#include <string>

namespace ob {

/// Bad input from the user (flag, scene file, asset): exit code 2. what() is the whole
/// message, one line per problem, each naming file:line:column and key where there is one.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A failure that is not the user's input (no GL context, a shader that fails): exit code 1.
struct RuntimeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr int EXIT_OK = 0;
constexpr int EXIT_FAILURE_RUNTIME = 1;
constexpr int EXIT_BAD_INPUT = 2;

} // namespace ob
