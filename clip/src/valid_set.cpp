// ValidSet (valid_set.hpp): made by validating, recording whether it is free of collinear
// consecutive vertices (the pipeline then tests only the vertices an operation creates).
#include "edgeland/clip/valid_set.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <queue>
#include <vector>

#include "canonical.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "pipeline.hpp"

namespace edgeland {

ValidSet::ValidSet(PolygonSet set, Operand which) : set_(std::move(set)) {
  detail::require_valid(set_, which);
  collinear_free_ = detail::collinear_free(set_);
}

ValidSet subset(const ValidSet& set, std::span<const std::size_t> members) {
  PolygonSet out;
  out.reserve(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (members[k] >= set.set_.size() || (k > 0 && members[k] <= members[k - 1]))
      throw ArgumentOutOfRange("members", static_cast<std::int64_t>(members[k]),
                               k > 0 ? static_cast<std::int64_t>(members[k - 1]) + 1 : 0,
                               static_cast<std::int64_t>(set.set_.size()) - 1);
    out.push_back(set.set_[members[k]]);
  }
  ValidSet part(std::move(out), ValidSet::Trusted{});
  part.canonical_ = set.canonical_;
  part.collinear_free_ = set.collinear_free_;
  return part;
}

namespace {

bool members_in_boxes(std::span<const BoxedSet> parts) {
  for (const BoxedSet& part : parts) {
    if (part.set == nullptr) continue;
    for (const Polygon& p : part.set->polygons()) {
      const std::optional<Box64> b = bounding_box(p);
      if (!b || !part.box.contains(b->min) || !part.box.contains(b->max)) return false;
    }
  }
  return true;
}

// Whether no two boxes' interiors meet: a sweep over x keeping the boxes it is inside, whose
// open y-ranges are then pairwise disjoint (keyed by their bottom), so a new box need only be
// compared with the one just below its top. O(k log k).
bool interiors_apart(std::span<const BoxedSet> parts) {
  std::vector<Box64> boxes;
  for (const BoxedSet& part : parts)
    if (part.set != nullptr && !part.set->polygons().empty()) boxes.push_back(part.box);
  std::sort(boxes.begin(), boxes.end(),
            [](const Box64& l, const Box64& r) { return l.min.x < r.min.x; });
  const auto ends_later = [](const Box64& l, const Box64& r) { return l.max.x > r.max.x; };
  std::priority_queue<Box64, std::vector<Box64>, decltype(ends_later)> open(ends_later);
  std::map<std::int64_t, std::int64_t> ranges;  // bottom -> top of the open boxes
  for (const Box64& b : boxes) {
    if (b.min.x >= b.max.x || b.min.y >= b.max.y) continue;  // no interior
    while (!open.empty() && open.top().max.x <= b.min.x) {
      ranges.erase(open.top().min.y);
      open.pop();
    }
    const auto above = ranges.lower_bound(b.max.y);  // the first range from b's top up
    if (above != ranges.begin() && std::prev(above)->second > b.min.y) return false;
    ranges.emplace(b.min.y, b.max.y);
    open.push(b);
  }
  return true;
}

}  // namespace

ValidSet join(std::span<const BoxedSet> parts) {
  PolygonSet all;
  bool collinear_free = true;
  for (const BoxedSet& part : parts) {
    if (part.set == nullptr) continue;
    all.insert(all.end(), part.set->polygons().begin(), part.set->polygons().end());
    collinear_free = collinear_free && part.set->collinear_free_;
  }
  if (!members_in_boxes(parts) || !interiors_apart(parts)) return ValidSet(std::move(all));
  // Not marked canonical: the order across parts is the caller's.
  ValidSet joined(std::move(all), ValidSet::Trusted{});
  joined.collinear_free_ = collinear_free;  // a property of each ring alone
  return joined;
}

}  // namespace edgeland
