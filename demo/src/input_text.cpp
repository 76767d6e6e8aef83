#include "edgeland/demo/input_text.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace edgeland::demo {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

// C stdio rather than iostreams: fread/ferror tell an empty file from a failed read (a
// directory opens fine and only fails when read), which stream state bits do not.
std::string read_all(std::FILE* file, const std::string& name) {
  std::string text;
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, got);
  if (std::ferror(file)) {
    throw InputError("cannot read " + name + ": " + std::strerror(errno));
  }
  return text;
}

}  // namespace

std::string read_input_text(const std::string& path) {
  if (path == "-") return read_all(stdin, "standard input");
  errno = 0;
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw InputError("cannot open '" + path + "': " + std::strerror(errno));
  return read_all(file.get(), "'" + path + "'");
}

}  // namespace edgeland::demo
