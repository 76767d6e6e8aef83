// Reader of the peer case data files (see peer_case_file.hpp).
#include "peer_case_file.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace edgeland::test {
namespace {

// Splits "keyword rest of line" at the first space.
std::pair<std::string, std::string> keyword_and_rest(const std::string& line) {
  const std::size_t space = line.find(' ');
  if (space == std::string::npos) return {line, ""};
  return {line.substr(0, space), line.substr(space + 1)};
}

}  // namespace

std::vector<PeerCase> read_peer_cases(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::vector<PeerCase> cases;
  std::string source;
  std::string line;
  std::size_t number = 0;
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(file.string() + ":" + std::to_string(number) + ": " + why);
  };
  auto check_complete = [&] {
    if (!cases.empty() && (cases.back().a.empty() || cases.back().b.empty()))
      fail("case " + cases.back().name + " lacks an operand");
  };
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const auto [keyword, rest] = keyword_and_rest(line);
    if (keyword == "source") {
      check_complete();
      source = rest;
    } else if (keyword == "case") {
      check_complete();
      if (source.empty()) fail("case before any source line");
      cases.push_back({file.stem().string(), source, rest, "", "", number, std::nullopt});
    } else if (keyword == "a" || keyword == "b") {
      if (cases.empty()) fail("operand before any case line");
      std::string& operand = keyword == "a" ? cases.back().a : cases.back().b;
      if (!operand.empty()) fail("operand " + keyword + " given twice");
      operand = rest;
    } else if (keyword == "peer_scale") {
      if (cases.empty()) fail("peer_scale before any case line");
      cases.back().peer_scale = std::stoi(rest);
    } else {
      fail("unknown line: " + keyword);
    }
  }
  check_complete();
  return cases;
}

std::vector<PeerCase> read_peer_case_dir(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".wkt") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<PeerCase> all;
  for (const auto& f : files) {
    auto cases = read_peer_cases(f);
    all.insert(all.end(), cases.begin(), cases.end());
  }
  return all;
}

}  // namespace edgeland::test
