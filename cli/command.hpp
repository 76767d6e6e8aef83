#pragma once
// What every `edgeland` subcommand provides, and the exit status convention they share.
#include <CLI/CLI.hpp>
#include <functional>

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

}  // namespace edgeland::cli
