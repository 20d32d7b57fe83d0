// The command line: one subcommand per file in this folder (commands.h), parsed here,
// errors mapped to exit codes (docs/references.md#contracts).
#include "cli/cli.h"

#include "cli/commands.h"
#include "core/error.h"
#include "core/printable.h"

#include <CLI/CLI.hpp>
#include <cstdio>

namespace ob::game {

int runCli(int argc, char** argv) {
    CLI::App app{"oceanbox: an interactive water sandbox (Tessendorf FFT ocean, Gerstner waves, "
                 "interactive ripples, buoyant bodies)",
                 "oceanbox"};
    app.require_subcommand(1);
    app.footer("Outputs (--stats, --screenshot, --out) are written whole to a regular file at the path given: a device, "
               "a named pipe, a folder or a symbolic link there (/dev/null, /dev/stdout) is refused with exit 2 before the "
               "run, and so is an output that names one of the run's inputs (the scene, its models, --input) or another output. "
               "Inputs must be regular files. A scene's screenshot events write only in its own folder or below.");
    app.fallthrough(false);
    CommandAction action;
    std::string commandLine = "oceanbox";
    for (int i = 1; i < argc; ++i) commandLine += std::string(" ") + argv[i];
    addPlayCommand(app, action);
    addRunCommand(app, action);
    addBenchCommand(app, action, commandLine);
    addDumpCommand(app, action);
    addRippleCommand(app, action);
    addSoakCommand(app, action);
    addMakeModelsCommand(app, action);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string what = e.what();
        // A first word that is no option and no subcommand: say which word, and the valid ones.
        if (argc > 1 && argv[1][0] != '-' && app.get_subcommands([&](CLI::App* sub) { return sub->check_name(argv[1]); }).empty()) {
            std::string names;
            for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
                names += (names.empty() ? "" : ", ") + sub->get_name();
            what = "unknown subcommand " + quotedValue(argv[1]) + " (the subcommands: " + names + ")";
        }
        std::fprintf(stderr, "oceanbox: %s\nRun 'oceanbox --help' (or 'oceanbox SUBCOMMAND --help') for usage.\n",
                     printableMessage(what).c_str());
        return EXIT_BAD_INPUT;
    }

    // Every message is printed inert and cut (core/printable.h): it may repeat a file's text.
    try {
        return action ? action() : EXIT_BAD_INPUT;
    } catch (const InputError& e) {
        std::fprintf(stderr, "oceanbox: error: %s\n", printableMessage(e.what()).c_str());
        return EXIT_BAD_INPUT;
    } catch (const RuntimeError& e) {
        std::fprintf(stderr, "oceanbox: failed: %s\n", printableMessage(e.what()).c_str());
        return EXIT_FAILURE_RUNTIME;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "oceanbox: failed: out of memory (std::bad_alloc): the scene's grids, bodies or particles "
                             "need more memory than this machine gives the process (lower their sizes)\n");
        return EXIT_FAILURE_RUNTIME;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "oceanbox: failed: %s\n", printableMessage(e.what()).c_str());
        return EXIT_FAILURE_RUNTIME;
    }
}

} // namespace ob::game
