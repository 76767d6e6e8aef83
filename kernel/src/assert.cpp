#include "edgeland/kernel/assert.hpp"

#include <stdexcept>
#include <string_view>

namespace edgeland::detail {

void fail_stage(const char* stage, const std::string& what, const char* file_path, int line) {
  std::string_view file = file_path;
  if (const auto slash = file.find_last_of("/\\"); slash != std::string_view::npos)
    file.remove_prefix(slash + 1);
  throw std::logic_error(std::string(stage) + ": " + what + " (" + std::string(file) + ":" +
                         std::to_string(line) + ")");
}

}  // namespace edgeland::detail
