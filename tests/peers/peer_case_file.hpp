#pragma once
// The data files of tests/peers/data/*.wkt: operand pairs copied from peers' test suites and
// bug reports, each with its provenance. Format (tests/peers/README.md):
//   # comment                                  (also blank lines)
//   source <repository> <path or issue URL> <license>    applies to the cases below it
//   case <name>                                the peer's own name for the case
//   a <WKT>                                    first operand, decimal coordinates as written
//   b <WKT>                                    second operand
//   peer_scale <n>                             optional: the peer rounds this case to 10^-n
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace edgeland::test {

struct PeerCase {
  std::string file;               // data file name without extension, e.g. "boost_overlay_cases"
  std::string source;             // the "source" line in force: repository, path, license
  std::string name;               // the case's name in its source
  std::string a, b;               // the operands' WKT
  std::size_t line = 0;           // line of the "case" line, for messages
  std::optional<int> peer_scale;  // the peer's own grid: coordinates x 10^peer_scale
};

// Throws std::runtime_error naming file and line for a malformed file (a case without both
// operands, a case before any source, an unknown line).
std::vector<PeerCase> read_peer_cases(const std::filesystem::path& file);

// Every *.wkt file in dir, in file name order.
std::vector<PeerCase> read_peer_case_dir(const std::filesystem::path& dir);

}  // namespace edgeland::test
