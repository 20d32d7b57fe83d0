// One function per subcommand: each adds its flags to the app and, when it is the one
// parsed, sets `action` to the work it runs (docs/references.md#contracts). runCli (cli.cpp) parses and maps errors.
#pragma once
#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace ob::game {

using CommandAction = std::function<int()>;

void addPlayCommand(CLI::App& app, CommandAction& action);
void addRunCommand(CLI::App& app, CommandAction& action);
void addDumpCommand(CLI::App& app, CommandAction& action);
void addRippleCommand(CLI::App& app, CommandAction& action);
void addSoakCommand(CLI::App& app, CommandAction& action);
void addMakeModelsCommand(CLI::App& app, CommandAction& action);
/// bench and its four kinds (game/bench/cmd_bench.cpp); `commandLine`, the whole command as
/// typed, goes into the reports.
void addBenchCommand(CLI::App& app, CommandAction& action, const std::string& commandLine);

} // namespace ob::game
