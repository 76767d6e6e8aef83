// The `edgeland` command: parses the command line and runs the chosen subcommand.
// The subcommands are listed in commands.hpp, one file each.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "commands.hpp"

namespace {

using namespace edgeland::cli;

// The first argument names no subcommand (CLI11 would only say one is required).
bool names_unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->check_name(argv[1])) return false;
  }
  return true;
}

std::string subcommand_names(const CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  return names;
}

// Usage errors take one line (CLI11's own message adds a second, "Run with --help ...").
int usage_error(const std::string& command, const CLI::ParseError& error) {
  std::string message = error.what();
  for (char& c : message) c = c == '\n' ? ' ' : c;
  std::cerr << command << ": " << message << " (`" << command << " --help` lists the options)\n";
  return kExitUnreadable;
}

// Whatever the subcommand printed must reach its reader: a full disk or a closed pipe is a
// failure, not a silent success.
int flushed(int status) {
  std::cout.flush();
  if (std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout)) return status;
  const int error = errno;
  std::cerr << "edgeland: cannot write standard output"
            << (error != 0 ? std::string(": ") + std::strerror(error) : std::string()) << '\n';
  return kExitUnreadable;
}

int run(const std::vector<Command>& commands) {
  try {
    for (const Command& command : commands) {
      if (command.app->parsed()) return command.run();
    }
  } catch (const std::bad_alloc&) {
    std::cerr << "edgeland: out of memory\n";
    return kExitOutOfMemory;
  } catch (const std::exception& error) {
    std::cerr << "edgeland: internal error: " << error.what() << '\n';
    return kExitInternal;
  }
  return kExitUnreadable;  // unreachable: require_subcommand(1) rejects a missing subcommand
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"edgeland: exact integer polygons for games.", "edgeland"};
  app.set_version_flag("--version", "edgeland " EDGELAND_VERSION);
  app.require_subcommand(1);
  app.footer("Run `edgeland SUBCOMMAND --help` for the options of a subcommand.");

  std::vector<Command> commands;
#define EDGELAND_CLI_ADD_COMMAND(name) commands.push_back(add_##name##_command(app));
  EDGELAND_CLI_COMMANDS(EDGELAND_CLI_ADD_COMMAND)
#undef EDGELAND_CLI_ADD_COMMAND

  if (names_unknown_subcommand(app, argc, argv)) {
    std::cerr << "edgeland: unknown subcommand '" << argv[1] << "' (one of "
              << subcommand_names(app) << ")\n";
    return kExitUnreadable;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return flushed(app.exit(help));
  } catch (const CLI::CallForAllHelp& help) {
    return flushed(app.exit(help));
  } catch (const CLI::CallForVersion& version) {
    return flushed(app.exit(version));
  } catch (const CLI::ParseError& error) {
    std::string command = "edgeland";
    for (const Command& c : commands) {
      if (c.app->parsed()) command += " " + c.app->get_name();
    }
    return usage_error(command, error);
  }
  return flushed(run(commands));
}
