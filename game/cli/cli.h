// The command line: play, run, bench, dump, ripple, soak, make-models (docs/references.md#contracts).
#pragma once

namespace ob::game {

/// Parses argv and runs the subcommand; returns the exit code (0 ok, 1 failure, 2 bad input).
int runCli(int argc, char** argv);

} // namespace ob::game
