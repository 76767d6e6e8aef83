// The errors of deltas and paths (errors.hpp).
#include <string>

#include "edgeland/spatial/errors.hpp"

namespace edgeland {
namespace {

const char* field_name(DeltaMismatch::Field field) {
  switch (field) {
    case DeltaMismatch::Field::kWorld:
      return "world hash";
    case DeltaMismatch::Field::kAlgorithm:
      return "algorithm version";
    case DeltaMismatch::Field::kBase:
      return "base hash";
    case DeltaMismatch::Field::kResult:
      return "result hash";
    case DeltaMismatch::Field::kNodeHash:
      return "patched node hash";
  }
  return "field";  // not reached: every field is named above
}

std::string hex(std::uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = digits[v & 15];
  return s;
}

std::string path_text(const TreePath& path) {
  std::string s = "{";
  for (std::size_t i = 0; i < path.size(); ++i) s += (i ? " " : "") + std::to_string(path[i]);
  return s + "}";
}

}  // namespace

DeltaError::DeltaError(const std::string& what, std::size_t at)
    : LandscapeError("cannot read delta at byte " + std::to_string(at) + ": " + what), offset(at) {}

DeltaMismatch::DeltaMismatch(Field f, std::uint64_t e, std::uint64_t a)
    : LandscapeError(std::string("delta does not fit: ") + field_name(f) + " " + hex(e) +
                     ", the landscape's " + hex(a)),
      field(f),
      expected(e),
      actual(a) {}

InvalidPath::InvalidPath(TreePath p)
    : LandscapeError("tree path " + path_text(p) + " names no node"), path(std::move(p)) {}

}  // namespace edgeland
