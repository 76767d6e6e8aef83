// The Landscape's construction, edits (edit.cpp does the work), state and log.
#include "edgeland/spatial/landscape.hpp"

#include "cell_split.hpp"
#include "check.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edgeland/spatial/log_format.hpp"
#include "edit.hpp"
#include "edit_log.hpp"
#include "regions.hpp"
#include "state_hash.hpp"

namespace edgeland {
namespace {

// The grid of thesis 4.4 (and the tree down to the region depth): the world cut to `depth`
// levels at once (one arrangement per level). `cells` counts the cells made, against the limit.
class GridBuilder {
 public:
  GridBuilder(const LandscapeConfig& config, const LandscapeLimits& limits, PolygonId& next_id)
      : config_(config), limits_(limits), next_id_(next_id) {}

  detail::NodePtr build(const Box64& box, LabeledSet content) {
    const int depth = std::max({config_.grid_depth, config_.region_depth, 0});
    return node(box, 0, depth, std::move(content), 0);
  }

 private:
  // `index`: the node's path as base-4 digits (the region's index at the region depth).
  detail::NodePtr node(const Box64& box, std::uint32_t depth, int grid_depth, LabeledSet content,
                       std::uint64_t index) {
    if (config_.region_ids && detail::is_region(config_, depth)) {
      PolygonId counter = detail::region_first_id(index);
      std::swap(counter, next_id_);
      detail::NodePtr region = node_within(box, depth, grid_depth, std::move(content), index);
      std::swap(counter, next_id_);
      return region;
    }
    return node_within(box, depth, grid_depth, std::move(content), index);
  }

  detail::NodePtr node_within(const Box64& box, std::uint32_t depth, int grid_depth,
                              LabeledSet content, std::uint64_t index) {
    if (static_cast<int>(depth) >= grid_depth || !detail::can_split(box, config_)) {
      if (++cells_ > limits_.max_cells)
        throw LimitExceeded(LimitExceeded::Limit::kCells, limits_.max_cells, cells_);
      std::vector<PolygonId> ids(content.labels.size());
      for (PolygonId& id : ids) id = next_id_++;
      return detail::make_cell(box, depth, std::move(content), std::move(ids), counter_at(depth));
    }
    const std::vector<Box64> boxes = detail::split_boxes(box, config_);
    std::vector<LabeledSet> parts = cut_to_windows(content.set, content.labels, boxes);
    std::vector<detail::NodePtr> children;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      children.push_back(node(boxes[i], depth + 1, grid_depth, std::move(parts[i]), index * 4 + i));
    return detail::make_inner(box, depth, children, counter_at(depth));
  }

  PolygonId counter_at(std::uint32_t depth) const {
    return config_.region_ids && detail::is_region(config_, depth) ? next_id_ : 0;
  }

  const LandscapeConfig& config_;
  const LandscapeLimits& limits_;
  PolygonId& next_id_;
  std::size_t cells_ = 0;
};

}  // namespace

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
  s_.root = GridBuilder(config, limits, s_.next_id).build(world, std::move(content));
}

ChangeSet Landscape::carve(const ValidSet& shape) {
  return apply(shape, detail::EditTable::carve(),
               [&] { return log::edit_line(log::LandscapeEditKind::kCarve, shape.polygons()); });
}
ChangeSet Landscape::fill(const ValidSet& shape, Material m) {
  return apply(shape, detail::EditTable::fill(m),
               [&] { return log::edit_line(log::LandscapeEditKind::kFill, shape.polygons(), m); });
}
ChangeSet Landscape::fill_empty(const ValidSet& shape, Material m) {
  return apply(shape, detail::EditTable::fill_empty(m), [&] {
    return log::edit_line(log::LandscapeEditKind::kFillEmpty, shape.polygons(), m);
  });
}
ChangeSet Landscape::replace(const ValidSet& shape, Material from, Material to) {
  return apply(shape, detail::EditTable::replace(from, to), [&] {
    return log::edit_line(log::LandscapeEditKind::kReplace, shape.polygons(), to, from);
  });
}
ChangeSet Landscape::relabel(const ValidSet& shape, const MaterialMap& map) {
  return apply(shape, detail::EditTable::relabel(map),
               [&] { return log::relabel_line(shape.polygons(), map); });
}

// A batch of one is that edit (apply_edit: the same state and log line); more are one edit of
// several steps, each a relabel by its edit's map (what the kinds' tables are).
ChangeSet Landscape::apply_batch(std::span<const Edit> edits) {
  if (edits.empty()) return {};
  if (edits.size() == 1) return apply_edit(*this, edits.front());
  std::vector<detail::EditTable> tables;
  tables.reserve(edits.size());
  for (const Edit& e : edits) tables.push_back(detail::EditTable::relabel(e.map));
  std::vector<RelabelStep> steps;
  for (std::size_t k = 0; k < edits.size(); ++k)
    steps.push_back({&edits[k].shape, tables[k].table});
  return apply([&] { return detail::EditBuilder(s_, steps).build(); },
               [&] { return log::batch_line(edits); });
}

// Every edit: the next state built (edit.cpp; s_ untouched, so a throw leaves the landscape as
// it was), the edit's line recorded, and the commit, one assignment.
ChangeSet Landscape::apply(const ValidSet& shape, const detail::EditTable& table,
                           const std::function<std::string()>& log_line) {
  const RelabelStep step{&shape, table.table};
  return apply([&] { return detail::EditBuilder(s_, std::span(&step, 1)).build(); }, log_line);
}

ChangeSet Landscape::apply(const std::function<detail::EditResult()>& build,
                           const std::function<std::string()>& log_line) {
  detail::EditResult edit = [&] {
    try {
      return build();
    } catch (const detail::EditFailure& failure) {
      throw detail::internal_error(s_, failure.what, log_line());
    }
  }();
  if (edit.next.logging) detail::append_log(edit.next, log_line());
  s_ = std::move(edit.next);
  return std::move(edit.changes);
}
ChangeSet Landscape::carve(const PolygonSet& shape) { return carve(edit_shape(shape)); }
ChangeSet Landscape::fill(const PolygonSet& shape, Material m) {
  return fill(edit_shape(shape), m);
}
ChangeSet Landscape::fill_empty(const PolygonSet& shape, Material m) {
  return fill_empty(edit_shape(shape), m);
}
ChangeSet Landscape::replace(const PolygonSet& shape, Material from, Material to) {
  return replace(edit_shape(shape), from, to);
}
ChangeSet Landscape::relabel(const PolygonSet& shape, const MaterialMap& map) {
  return relabel(edit_shape(shape), map);
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
  detail::add_world(h, s_.world, s_.config);
  h.add(static_cast<std::uint64_t>(s_.next_id)).add(s_.root->hash);
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
