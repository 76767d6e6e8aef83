// Replays saved fuzz inputs through the same decoding and checks as the fuzz targets
// (decoders.hpp), without libFuzzer: this is how ctest runs tests/regress/<target>/ and the
// seed corpora in the normal build.
//   regress_replay TARGET PATH...        run every file (directories: every file in them)
//   regress_replay TARGET --log FILE     print the continuous-clip log the input decodes to
//   regress_replay TARGET --write-seeds DIR  write the seeds of delta or net_message
//                                            (fuzz/corpus/TARGET)
// Exit status: 0 all passed, 1 a finding (printed with its log), 2 bad usage or unreadable.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "decoders.hpp"

namespace {

bool read_file(const std::filesystem::path& path, std::vector<std::uint8_t>& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

// Files to run: regular files as given; directories expanded (sorted, notes skipped).
std::vector<std::filesystem::path> inputs(int argc, char** argv) {
  std::vector<std::filesystem::path> files;
  for (int i = 2; i < argc; ++i) {
    const std::filesystem::path path(argv[i]);
    if (!std::filesystem::is_directory(path)) {
      files.push_back(path);
      continue;
    }
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::directory_iterator(path)) {
      if (entry.is_regular_file() && entry.path().extension() != ".note") found.push_back(entry);
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: regress_replay TARGET PATH... | regress_replay TARGET --log FILE\n";
    return 2;
  }
  const std::string target = argv[1];
  const edgeland::fuzz::Runner run = edgeland::fuzz::runner_for(target);
  if (run == nullptr) {
    std::cerr << "regress_replay: unknown target '" << target << "'\n";
    return 2;
  }
  std::vector<std::uint8_t> bytes;
  if (std::string(argv[2]) == "--write-seeds" && argc == 4) {
    const std::vector<std::string> seeds = edgeland::fuzz::seeds_for(target);
    if (seeds.empty()) {
      std::cerr << "regress_replay: " << target << " writes no seeds\n";
      return 2;
    }
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      std::ofstream out(std::filesystem::path(argv[3]) / ("seed-" + std::to_string(i)),
                        std::ios::binary);
      out << seeds[i];
      if (!out) return 2;
    }
    return 0;
  }
  if (std::string(argv[2]) == "--log") {
    if (argc != 4 || !read_file(argv[3], bytes)) {
      std::cerr << "regress_replay: cannot read the input for --log\n";
      return 2;
    }
    std::cout << edgeland::fuzz::input_as_log(target, bytes.data(), bytes.size());
    return 0;
  }
  std::size_t passed = 0;
  for (const std::filesystem::path& file : inputs(argc, argv)) {
    if (!read_file(file, bytes)) {
      std::cerr << "regress_replay: cannot read " << file << '\n';
      return 2;
    }
    if (auto finding = run(bytes.data(), bytes.size())) {
      std::cout << file.string() << ": FINDING\n" << finding->what << '\n';
      if (!finding->log.empty()) std::cout << "replay log:\n" << finding->log;
      return 1;
    }
    ++passed;
  }
  std::cout << target << ": " << passed << " input(s) passed\n";
  return 0;
}
