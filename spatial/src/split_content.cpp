#include "split_content.hpp"

#include <algorithm>
#include <optional>

#include "edgeland/clip/errors.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::detail {
namespace {

// The one box of `boxes` whose closed box contains every polygon of `content`, if any. Polygons
// have area, so no two boxes with disjoint interiors both contain them.
std::optional<std::size_t> only_child_holding(const LabeledSet& content,
                                              const std::vector<Box64>& boxes) {
  const std::optional<Box64> all = bounding_box(content.set.polygons());
  if (!all) return std::nullopt;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (boxes[i].contains(all->min) && boxes[i].contains(all->max)) return i;
  return std::nullopt;
}

bool same_parts(const std::vector<LabeledSet>& a, const std::vector<LabeledSet>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), same_content);
}

}  // namespace

std::vector<LabeledSet> cut_to_children(LabeledSet content, const std::vector<Box64>& boxes,
                                        const ClipOptions& options) {
  const std::optional<std::size_t> only = only_child_holding(content, boxes);
  if (!only) return cut_to_windows(content.set, content.labels, boxes, options);
  std::vector<LabeledSet> whole = options.checked
                                      ? cut_to_windows(content.set, content.labels, boxes, options)
                                      : std::vector<LabeledSet>{};
  std::vector<LabeledSet> parts(boxes.size());
  parts[*only] = std::move(content);
  // Not reached by tests: the two answers agree (an internal error otherwise).
  if (options.checked && !same_parts(parts, whole))
    throw InternalError("split: the content in one child is not cut_to_windows' answer",
                        to_wkt(parts[*only].set.polygons()), "");
  return parts;
}

}  // namespace edgeland::detail
