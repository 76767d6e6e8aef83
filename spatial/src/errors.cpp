// The constructors of the landscape's errors (errors.hpp): each builds its one-line message from
// the data it keeps.
#include "edgeland/spatial/errors.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "cell_split.hpp"
#include "edgeland/spatial/material.hpp"
#include "edgeland/spatial/tree_boxes.hpp"

namespace edgeland {
namespace {

std::string config_problem(InvalidConfig::Setting setting, const Box64& w,
                           const LandscapeConfig& c) {
  using Setting = InvalidConfig::Setting;
  const auto n = [](auto v) { return std::to_string(v); };
  const std::string box =
      "world box (" + n(w.min.x) + " " + n(w.min.y) + ", " + n(w.max.x) + " " + n(w.max.y) + ")";
  switch (setting) {
    case Setting::kWorldOutOfRange:
      return box + " beyond the coordinate bound";
    case Setting::kWorldEmpty:
      return box + " without positive width and height";
    case Setting::kEdgeCap:
      return "edge_cap " + n(c.edge_cap) + " below " + n(detail::kMinEdgeCap);
    case Setting::kMergeBelow:
      return "merge_below " + n(c.merge_below) + " not below edge_cap " + n(c.edge_cap);
    case Setting::kMinCellSize:
      return "min_cell_size " + n(c.min_cell_size) + " below 1";
    case Setting::kGridDepth:
      return "grid_depth " + n(c.grid_depth) + " outside -1.." + n(detail::kMaxGridDepth);
    case Setting::kGridDepthBeyondCells:
      return "grid_depth " + n(c.grid_depth) + " deeper than min_cell_size " + n(c.min_cell_size) +
             " lets the " + box + " split (at most " + n(max_grid_depth(w, c)) + ")";
    case Setting::kTree:
      return "unknown tree kind " + n(static_cast<int>(c.tree));
    case Setting::kRegionDepth:
      return "region_depth " + n(c.region_depth) + " outside -1.." +
             n(std::min({detail::kMaxGridDepth, max_grid_depth(w, c),
                         c.grid_depth >= 0 ? c.grid_depth : detail::kMaxGridDepth})) +
             " for the " + box;
    case Setting::kRegionIds:
      return "region_ids without a region_depth";
  }
  return "unusable configuration";
}

const char* limit_name(LimitExceeded::Limit limit) {
  switch (limit) {
    case LimitExceeded::Limit::kVertices:
      return "landscape vertex";
    case LimitExceeded::Limit::kShapeVertices:
      return "shape vertex";
    case LimitExceeded::Limit::kCells:
      return "cell";
    case LimitExceeded::Limit::kPolygonIds:
      return "polygon id";
  }
  return "unknown";  // not reached: every limit is named above
}

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

InvalidConfig::InvalidConfig(Setting s, const Box64& w, const LandscapeConfig& c)
    : LandscapeError(config_problem(s, w, c)), setting(s), world(w), config(c) {}

LimitExceeded::LimitExceeded(Limit l, std::size_t max, std::size_t req)
    : LandscapeError(std::string(limit_name(l)) + " limit exceeded: " + std::to_string(req) +
                     " > " + std::to_string(max)),
      limit(l),
      maximum(max),
      requested(req) {}

LandscapeInternalError::LandscapeInternalError(const std::string& what, std::string s,
                                               std::string lg)
    : LandscapeError("edgeland landscape internal error (please report with the log): " + what),
      state(std::move(s)),
      log(std::move(lg)) {}

LoadError::LoadError(const std::string& what, std::size_t at)
    : LandscapeError("cannot load landscape at byte " + std::to_string(at) + ": " + what),
      offset(at) {}

InvalidMaterial::InvalidMaterial(std::int64_t n)
    : LandscapeError("material " + std::to_string(n) + " outside 0..255"), number(n) {}

void detail::throw_invalid_material(std::int64_t number) { throw InvalidMaterial(number); }

DeltaError::DeltaError(const std::string& what, std::size_t at)
    : LandscapeError("cannot read delta at byte " + std::to_string(at) + ": " + what), offset(at) {}

DeltaMismatch::DeltaMismatch(Field f, std::uint64_t e, std::uint64_t a)
    : LandscapeError(std::string("delta does not fit: ") + field_name(f) + " " + hex(e) +
                     ", the landscape's " + hex(a)),
      field(f),
      expected(e),
      actual(a) {}

RegionNotLoaded::RegionNotLoaded(TreePath p, const Box64& b)
    : LandscapeError("region " + path_text(p) + " (" + std::to_string(b.min.x) + " " +
                     std::to_string(b.min.y) + ", " + std::to_string(b.max.x) + " " +
                     std::to_string(b.max.y) + ") is not loaded"),
      path(std::move(p)),
      box(b) {}

InvalidPath::InvalidPath(TreePath p)
    : LandscapeError("tree path " + path_text(p) + " names no node"), path(std::move(p)) {}

UnknownPolygon::UnknownPolygon(PolygonId i, const Box64& c)
    : LandscapeError("polygon " + std::to_string(i) + " is not in the cell (" +
                     std::to_string(c.min.x) + " " + std::to_string(c.min.y) + " " +
                     std::to_string(c.max.x) + " " + std::to_string(c.max.y) + ")"),
      id(i),
      cell(c) {}

}  // namespace edgeland
