#include "game/cli/Cli.h"

int main(int argc, char** argv) { return game::run_cli(argc, argv); }
