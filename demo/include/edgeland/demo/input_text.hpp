#pragma once
// Reading a whole input file, or standard input for "-", for any subcommand.
#include <stdexcept>
#include <string>

namespace edgeland::demo {

// The file could not be opened or read (missing, a directory, an I/O error).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Returns the bytes of `path` ("-" = standard input) unchanged. Throws InputError with a
// one-line message naming the path and the system's reason.
std::string read_input_text(const std::string& path);

}  // namespace edgeland::demo
