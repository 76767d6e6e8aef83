#pragma once
// The subcommands of `edgeland`: what each provides, the exit status convention they share, and
// their list. To add one, write cli/<name>_command.cpp defining
//   Command add_<name>_command(CLI::App& parent);
// (it registers its options on `parent`) and add one X(<name>) line below; CMake picks up
// every *_command.cpp by itself.
#include <CLI/CLI.hpp>
#include <functional>

// One X(...) line per subcommand.
// clang-format off
#define EDGELAND_CLI_COMMANDS(X) \
  X(validate) \
  X(inspect) \
  X(clip) \
  X(replay) \
  X(render) \
  X(demo) \
  X(export) \
  EDGELAND_CLI_NET_COMMANDS(X)
// The shared world's commands, when store/ and net/ are built (cli/CMakeLists.txt).
#ifdef EDGELAND_HAVE_NET
#define EDGELAND_CLI_NET_COMMANDS(X) \
  X(serve) \
  X(client) \
  X(store) \
  X(stream)
#else
#define EDGELAND_CLI_NET_COMMANDS(X)
#endif
// clang-format on

namespace edgeland::cli {

// Exit status of every subcommand.
inline constexpr int kExitOk = 0;           // done; for `validate`: the input is valid
inline constexpr int kExitInvalid = 1;      // the input was read but breaks a rule
inline constexpr int kExitUnreadable = 2;   // unreadable input or bad command line
inline constexpr int kExitInternal = 3;     // a bug: an unexpected exception escaped
inline constexpr int kExitOutOfMemory = 4;  // the input needs more memory than there is

struct Command {
  CLI::App* app = nullptr;   // the registered subcommand (main asks it whether it was chosen)
  std::function<int()> run;  // runs it once the command line is parsed; returns the exit status
};

#define EDGELAND_CLI_DECLARE_COMMAND(name) Command add_##name##_command(CLI::App& parent);
EDGELAND_CLI_COMMANDS(EDGELAND_CLI_DECLARE_COMMAND)
#undef EDGELAND_CLI_DECLARE_COMMAND
}  // namespace edgeland::cli
