#pragma once

namespace game {

// The whole program: parses the command line, runs a subcommand, maps every error
// to one message on stderr and an exit code.
int run_cli(int argc, char** argv);

}  // namespace game
