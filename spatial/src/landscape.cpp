// The Landscape's construction, edits (edit.cpp does the work), state and log.
#include "edgeland/spatial/landscape.hpp"

#include "cell_split.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edgeland/spatial/tree_boxes.hpp"
#include "edit.hpp"
#include "edit_log.hpp"
#include "state_hash.hpp"

namespace edgeland {
namespace {

// A coordinate beyond the bound is its own error (CoordinateOutOfRange); anything else that
// validate() rejects is InvalidInput naming the shape as the clip operand.
ValidSet shape_of(const PolygonSet& shape) {
  for (std::size_t i = 0; i < shape.size(); ++i)
    for (std::size_t j = 0; j < shape[i].size(); ++j)
      if (!in_range(shape[i][j])) throw CoordinateOutOfRange(Operand::kClip, i, 0, j, shape[i][j]);
  return ValidSet(shape, Operand::kClip);
}

// The grid of thesis 4.4: the world cut to `depth` levels at once (one arrangement per level).
// `cells` counts the cells made, against the limit.
detail::NodePtr grid(const Box64& box, std::uint32_t depth, int grid_depth, LabeledSet content,
                     const LandscapeConfig& config, const LandscapeLimits& limits,
                     PolygonId& next_id, std::size_t& cells) {
  if (static_cast<int>(depth) >= grid_depth || !detail::can_split(box, config)) {
    if (++cells > limits.max_cells)
      throw LimitExceeded(LimitExceeded::Limit::kCells, limits.max_cells, cells);
    std::vector<PolygonId> ids(content.labels.size());
    for (PolygonId& id : ids) id = next_id++;
    return detail::make_cell(box, depth, std::move(content), std::move(ids));
  }
  const std::vector<Box64> boxes = detail::split_boxes(box, config);
  std::vector<LabeledSet> parts = cut_to_windows(content.set, content.labels, boxes);
  std::vector<detail::NodePtr> children;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    children.push_back(
        grid(boxes[i], depth + 1, grid_depth, std::move(parts[i]), config, limits, next_id, cells));
  return detail::make_inner(box, depth, children);
}

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
  }
  return "unusable configuration";
}

}  // namespace

InvalidConfig::InvalidConfig(Setting s, const Box64& w, const LandscapeConfig& c)
    : LandscapeError(config_problem(s, w, c)), setting(s), world(w), config(c) {}

namespace {

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

}  // namespace

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

Landscape::Landscape(const Box64& world, Material fill, const LandscapeConfig& config,
                     const LandscapeLimits& limits) {
  detail::require_config(world, config);
  LabeledSet content;
  auto areas = std::make_shared<detail::AreaTable>();
  if (fill != kEmpty) {
    content.set = ValidSet(
        PolygonSet{{world.min, {world.max.x, world.min.y}, world.max, {world.min.x, world.max.y}}});
    content.labels = {fill.value()};
    (*areas)[fill.value()] = twice_signed_area(content.set.polygons().front());
  }
  s_.world = world;
  s_.config = config;
  s_.limits = limits;
  s_.initial_fill = fill;
  s_.areas = std::move(areas);
  std::size_t cells = 0;
  s_.root = grid(world, 0, std::max(config.grid_depth, 0), std::move(content), config, limits,
                 s_.next_id, cells);
}

namespace {

// One edit as the steps of an edit (edit.hpp): the shape and the table.
detail::EditStep step_of(const ValidSet& shape, detail::EditTable table) {
  return {&shape, std::move(table)};
}

}  // namespace

ChangeSet Landscape::carve(const ValidSet& shape) {
  const detail::EditStep step = step_of(shape, detail::EditTable::carve());
  return apply(std::span(&step, 1), [&] { return detail::carve_line(shape.polygons()); });
}
ChangeSet Landscape::fill(const ValidSet& shape, Material m) {
  const detail::EditStep step = step_of(shape, detail::EditTable::fill(m));
  return apply(std::span(&step, 1), [&] { return detail::fill_line(shape.polygons(), m); });
}
ChangeSet Landscape::fill_empty(const ValidSet& shape, Material m) {
  const detail::EditStep step = step_of(shape, detail::EditTable::fill_empty(m));
  return apply(std::span(&step, 1), [&] { return detail::fill_empty_line(shape.polygons(), m); });
}
ChangeSet Landscape::replace(const ValidSet& shape, Material from, Material to) {
  const detail::EditStep step = step_of(shape, detail::EditTable::replace(from, to));
  return apply(std::span(&step, 1),
               [&] { return detail::replace_line(shape.polygons(), from, to); });
}
ChangeSet Landscape::relabel(const ValidSet& shape, const MaterialMap& map) {
  const detail::EditStep step = step_of(shape, detail::EditTable::relabel(map));
  return apply(std::span(&step, 1), [&] { return detail::relabel_line(shape.polygons(), map); });
}

// A batch of one is that edit (apply_edit: the same result, and its own log line); more are one
// edit of several steps, each a relabel by its map (what the kind's table does).
ChangeSet Landscape::apply_batch(std::span<const Edit> edits) {
  if (edits.empty()) return {};
  if (edits.size() == 1) return apply_edit(*this, edits.front());
  std::vector<detail::EditStep> steps;
  steps.reserve(edits.size());
  for (const Edit& e : edits) steps.push_back(step_of(e.shape, detail::EditTable::relabel(e.map)));
  return apply(steps, [&] { return detail::batch_line(edits); });
}

// Every edit: the next state built (edit.cpp; s_ untouched, so a throw leaves the landscape as
// it was), the edit's line recorded, and the commit, one assignment.
ChangeSet Landscape::apply(std::span<const detail::EditStep> steps,
                           const std::function<std::string()>& log_line) {
  detail::EditResult edit = [&] {
    try {
      return detail::EditBuilder(s_, steps).build();
    } catch (const detail::EditFailure& failure) {
      throw detail::internal_error(s_, failure.what, log_line());
    }
  }();
  if (edit.next.logging) detail::append_log(edit.next, log_line());
  s_ = std::move(edit.next);
  return std::move(edit.changes);
}
ChangeSet Landscape::carve(const PolygonSet& shape) { return carve(shape_of(shape)); }
ChangeSet Landscape::fill(const PolygonSet& shape, Material m) { return fill(shape_of(shape), m); }
ChangeSet Landscape::fill_empty(const PolygonSet& shape, Material m) {
  return fill_empty(shape_of(shape), m);
}
ChangeSet Landscape::replace(const PolygonSet& shape, Material from, Material to) {
  return replace(shape_of(shape), from, to);
}
ChangeSet Landscape::relabel(const PolygonSet& shape, const MaterialMap& map) {
  return relabel(shape_of(shape), map);
}

Int128 Landscape::twice_area(Material m) const {
  if (m != kEmpty) return (*s_.areas)[m.value()];
  Int128 solid = 0;
  for (std::size_t i = 1; i < kMaterialCount; ++i) solid += (*s_.areas)[i];
  const Box64& w = s_.world;
  const Ring world{w.min, {w.max.x, w.min.y}, w.max, {w.min.x, w.max.y}};
  return twice_signed_area(world) - solid;
}

std::uint64_t Landscape::state_hash() const noexcept {
  detail::StateHash h;
  const LandscapeConfig& c = s_.config;
  h.add(s_.world)
      .add(static_cast<std::uint64_t>(c.tree))
      .add(static_cast<std::uint64_t>(c.edge_cap))
      .add(static_cast<std::uint64_t>(c.merge_below))
      .add(static_cast<std::uint64_t>(c.min_cell_size))
      .add(static_cast<std::uint64_t>(static_cast<std::int64_t>(c.grid_depth)))
      .add(static_cast<std::uint64_t>(s_.next_id))
      .add(s_.root->hash);
  return h.value();
}

LandscapeReport Landscape::check() const { return detail::check_all(s_); }

void Landscape::start_log() {
  if (s_.logging) return;
  const std::string first = detail::state_log(s_);
  s_.logging = true;
  s_.log.reset();
  detail::append_log(s_, first);
}

std::string Landscape::log() const { return detail::log_text(s_); }

}  // namespace edgeland
