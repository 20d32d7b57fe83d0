// Shared test helpers: run the oceanbox executable, temporary files.
#pragma once
#include <functional>
#include <optional>
#include <string>

namespace ob::test {

/// True in the ThreadSanitizer build, whose steps are 5-15x slower: its determinism runs take
/// fewer steps, enough for every thread to have run its part several times.
#if defined(__SANITIZE_THREAD__)
inline constexpr bool THREAD_SANITIZER = true;
#else
inline constexpr bool THREAD_SANITIZER = false;
#endif

struct ProcessResult {
    int exitCode = -1;   ///< process exit status (-1 if it did not exit normally)
    std::string output;  ///< stdout and stderr together
    double wallSeconds = 0.0;  ///< how long it ran
};

/// Runs build/bin/oceanbox with the given argument string (shell-quoted by the caller),
/// from the repository root.
ProcessResult runOceanbox(const std::string& args);

/// Runs a shell command line from the repository root; `$OCEANBOX` in it names the
/// executable (build/bin/oceanbox).
ProcessResult runShell(const std::string& command);

/// "ASAN_OPTIONS=detect_leaks=0 " under AddressSanitizer, else "": the prefix of a `play`
/// child whose exit crashes LeakSanitizer's own tracer when a test starts it ("Tracer caught
/// signal 11", google/sanitizers#1353; not a leak). Its leaks are checked by the other runs.
std::string withoutLeakCheck();

/// Runs `load` on a thread of its own: the ob::InputError message it throws ("" when it
/// returns, "not an InputError: ..." for another exception), or nullopt when it has not
/// returned after `seconds` (a hang: the thread is left blocked, the test fails instead).
std::optional<std::string> inputErrorWithin(double seconds, std::function<void()> load);

/// A fresh path under the system temp folder (the file does not exist yet).
std::string tempPath(const std::string& name);

/// Writes text to a file (overwriting); returns the path.
std::string writeFile(const std::string& path, const std::string& text);

} // namespace ob::test
