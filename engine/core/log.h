// Logging: one line per message on stderr, prefixed "oceanbox: ".
#pragma once

namespace ob {

/// printf-style informational line on stderr (suppressed by setLogQuiet(true)).
void logInfo(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
/// printf-style warning line on stderr (never suppressed).
void logWarn(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
/// Silences logInfo (tests, benchmarks).
void setLogQuiet(bool quiet);

} // namespace ob
