// The `edgeland` command: parses the command line and runs the chosen subcommand.
// The subcommands are listed in commands.hpp, one file each.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <vector>

#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace edgeland::cli;
  CLI::App app{"edgeland: exact integer polygons for games.", "edgeland"};
  app.set_version_flag("--version", "edgeland " EDGELAND_VERSION);
  app.require_subcommand(1);
  app.footer("Run `edgeland SUBCOMMAND --help` for the options of a subcommand.");

  std::vector<Command> commands;
#define EDGELAND_CLI_ADD_COMMAND(name) commands.push_back(add_##name##_command(app));
  EDGELAND_CLI_COMMANDS(EDGELAND_CLI_ADD_COMMAND)
#undef EDGELAND_CLI_ADD_COMMAND

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version arrive here as "errors" with status 0; app.exit prints them.
    return app.exit(error) == 0 ? kExitOk : kExitUnreadable;
  }
  try {
    for (const Command& command : commands) {
      if (command.app->parsed()) return command.run();
    }
  } catch (const std::exception& error) {
    std::cerr << "edgeland: internal error: " << error.what() << '\n';
    return kExitInternal;
  }
  return kExitUnreadable;  // unreachable: require_subcommand(1) rejects a missing subcommand
}
