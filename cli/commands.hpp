#pragma once
// The list of subcommands. To add one, write cli/<name>_command.cpp defining
//   Command add_<name>_command(CLI::App& parent);
// (it registers its options on `parent`) and add one X(<name>) line below; CMake picks up
// every *_command.cpp by itself.
#include "command.hpp"

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
#define EDGELAND_CLI_DECLARE_COMMAND(name) Command add_##name##_command(CLI::App& parent);
EDGELAND_CLI_COMMANDS(EDGELAND_CLI_DECLARE_COMMAND)
#undef EDGELAND_CLI_DECLARE_COMMAND
}  // namespace edgeland::cli
