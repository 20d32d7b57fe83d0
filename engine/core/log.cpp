// Logging to stderr.
#include "core/log.h"

#include <cstdarg>
#include <cstdio>

namespace ob {

static bool s_quiet = false;

static void vlog(const char* tag, const char* fmt, va_list args) {
    std::fprintf(stderr, "oceanbox: %s", tag);
    std::vfprintf(stderr, fmt, args);
    std::fputc('\n', stderr);
}

void logInfo(const char* fmt, ...) {
    if (s_quiet) return;
    va_list args;
    va_start(args, fmt);
    vlog("", fmt, args);
    va_end(args);
}

void logWarn(const char* fmt, ...) {
    va_list args;
    va_start(args, fmt);
    vlog("warning: ", fmt, args);
    va_end(args);
}

void setLogQuiet(bool quiet) { s_quiet = quiet; }

} // namespace ob
