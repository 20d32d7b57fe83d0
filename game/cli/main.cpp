// oceanbox entry point.
#include "cli/cli.h"

int main(int argc, char** argv) { return ob::game::runCli(argc, argv); }
