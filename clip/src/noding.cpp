#include "noding.hpp"

#include <algorithm>

#include "box_sweep.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

Box64 box_of(const Segment& s) {
  Box64 b{s.a, s.a};
  b.expand(s.b);
  return b;
}

void split_if_interior(Contacts& c, std::uint32_t seg, const Segment& s, Point64 p) {
  if (p != s.a && p != s.b) c.splits.emplace_back(seg, p);
}

}  // namespace

Contacts find_contacts(const std::vector<Segment>& segments, const std::vector<bool>& involved) {
  std::vector<Box64> boxes(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) boxes[i] = box_of(segments[i]);
  Contacts c;
  for_each_overlapping_pair(boxes, [&](std::uint32_t i, std::uint32_t j) {
    if (!involved.empty() && !involved[i] && !involved[j]) return;
    const Segment& s = segments[i];
    const Segment& t = segments[j];
    const SegmentIntersection r = intersect(s, t);
    switch (r.relation) {
      case SegmentRelation::kDisjoint:
        return;
      case SegmentRelation::kTouching: {
        const Point64 p = round_to_grid(r.point);  // exact: touching points are endpoints
        if ((p == s.a || p == s.b) && (p == t.a || p == t.b)) return;  // shared vertex
        ++c.intersections;
        split_if_interior(c, i, s, p);
        split_if_interior(c, j, t, p);
        return;
      }
      case SegmentRelation::kOverlapping:
        ++c.intersections;
        for (Point64 p : {r.overlap_from, r.overlap_to}) {
          split_if_interior(c, i, s, p);
          split_if_interior(c, j, t, p);
        }
        return;
      case SegmentRelation::kCrossing:
        ++c.intersections;
        if (r.point.is_integer()) {
          const Point64 p = round_to_grid(r.point);
          c.splits.emplace_back(i, p);
          c.splits.emplace_back(j, p);
        } else {
          c.hot.push_back(round_to_grid(r.point));
        }
        return;
    }
  });
  return c;
}

}  // namespace edgeland::detail
