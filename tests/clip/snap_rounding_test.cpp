// Snap rounding's output contract (clip/src/snap_rounding.hpp), checked by brute force over every
// pair of output fragments: fragments meet only at common endpoints or coincide, each segment's
// fragments run from its start to its end, and every fragment stays within the pixels its
// segment passes (half a unit in x and y of it).
//
// The re-check after rounding tests only pairs with a fragment off its classic route, relying on
// the snap-rounding theorem for the rest (clip/README.md); these brute-force checks are what
// would catch a pair it wrongly skips. The inputs are crowded on purpose: many rings of random
// points in a small square, so that crossings round next to vertices and long segments pass
// through the pixels of vertices that are not hot.
#include "snap_rounding.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

struct Input {
  std::vector<Segment> segments;
  std::vector<std::uint32_t> next;  // ring successor of each segment
};

// Appends the ring through `pts` (a repeated closing point dropped; fewer than two points: none)
// as segments linked along it.
void add_ring(std::vector<Point64> pts, Input& in) {
  while (pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
  if (pts.size() < 2) return;
  const auto first = static_cast<std::uint32_t>(in.segments.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    in.segments.push_back({pts[i], pts[(i + 1) % pts.size()]});
    in.next.push_back(i + 1 < pts.size() ? static_cast<std::uint32_t>(in.segments.size()) : first);
  }
}

// Rings of random points (self-intersecting, overlapping each other) in [0, side]^2.
rc::Gen<Input> crowded_rings() {
  return rc::gen::exec([] {
    const std::int64_t side = *rc::gen::element<std::int64_t>(6, 12, 40, 1000, 3'000'000'000);
    const int rings = *rc::gen::inRange(1, 6);
    Input in;
    for (int r = 0; r < rings; ++r) {
      const int n = *rc::gen::inRange(3, 40);
      std::vector<Point64> pts;
      for (int i = 0; i < n; ++i) {
        const Point64 p{*rc::gen::inRange<std::int64_t>(0, side + 1) - side / 2,
                        *rc::gen::inRange<std::int64_t>(0, side + 1) - side / 2};
        if (pts.empty() || p != pts.back()) pts.push_back(p);
      }
      add_ring(std::move(pts), in);
    }
    return in;
  });
}

// Many rings (over 256 segments, so no flat search), each of random points in its own window,
// the windows scattered over a larger square, and a few crowded ones (windows of 6 to 40 units)
// among them: many crossings, yet few segments pass through the pixel of a vertex that is not
// hot, nearly all of them in the crowded rings, so the re-check walks every fragment through a
// grid of the few fragments off their classic routes (snap_recheck.cpp,
// check_against_off_fragments), and those pairs are the ones that need it.
rc::Gen<Input> scattered_rings() {
  return rc::gen::exec([] {
    const std::int64_t wide = *rc::gen::element<std::int64_t>(5'000, 20'000);
    const std::int64_t square = *rc::gen::element<std::int64_t>(30'000, 60'000);
    const int rings = *rc::gen::inRange(10, 15), crowded = *rc::gen::inRange(1, 4);
    Input in;
    for (int r = 0; r < rings + crowded; ++r) {
      const Point64 c{*rc::gen::inRange<std::int64_t>(0, square),
                      *rc::gen::inRange<std::int64_t>(0, square)};
      const std::int64_t window = r < rings ? wide : *rc::gen::element<std::int64_t>(6, 12, 40);
      const int n = r < rings ? *rc::gen::inRange(20, 37) : *rc::gen::inRange(8, 30);
      std::vector<Point64> pts;
      for (int i = 0; i < n; ++i) {
        const Point64 p{c.x + *rc::gen::inRange<std::int64_t>(0, window + 1) - window / 2,
                        c.y + *rc::gen::inRange<std::int64_t>(0, window + 1) - window / 2};
        if (pts.empty() || p != pts.back()) pts.push_back(p);
      }
      add_ring(std::move(pts), in);
    }
    return in;
  });
}

// Every fragment, listed or not (a segment without listed fragments is its own fragment).
std::vector<Fragment> all_fragments(const Input& in, const std::vector<Fragment>& listed) {
  std::vector<bool> has(in.segments.size(), false);
  for (const Fragment& f : listed) has[f.parent] = true;
  std::vector<Fragment> all = listed;
  for (std::uint32_t s = 0; s < in.segments.size(); ++s)
    if (!has[s]) all.push_back({in.segments[s], s});
  return all;
}

// Whether p lies within half a unit (in x and y) of s: in the closed pixel of a point of s.
bool within_half_unit(const Segment& s, Point64 p) {
  const Int128 dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  if (2 * (p.x - std::max(s.a.x, s.b.x)) > 1 || 2 * (std::min(s.a.x, s.b.x) - p.x) > 1 ||
      2 * (p.y - std::max(s.a.y, s.b.y)) > 1 || 2 * (std::min(s.a.y, s.b.y) - p.y) > 1)
    return false;
  const Int128 det = dx * (p.y - s.a.y) - dy * (p.x - s.a.x);
  return 2 * (det < 0 ? -det : det) <= (dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy);
}

// Fragments meet only at common endpoints or coincide: every pair whose boxes overlap, tested
// exactly (pairs from a sort by min x, independent of the library's searches).
void require_fragments_meet_only_at_endpoints(std::vector<Fragment> all) {
  std::sort(all.begin(), all.end(), [](const Fragment& x, const Fragment& y) {
    return std::min(x.seg.a.x, x.seg.b.x) < std::min(y.seg.a.x, y.seg.b.x);
  });
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Segment& f = all[i].seg;
    RC_ASSERT(f.a != f.b);
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const Segment& g = all[j].seg;
      if (std::min(g.a.x, g.b.x) > std::max(f.a.x, f.b.x)) break;
      const SegmentIntersection r = intersect(f, g);
      switch (r.relation) {
        case SegmentRelation::kDisjoint:
          break;
        case SegmentRelation::kTouching: {
          const Point64 p = round_to_grid(r.point);
          RC_ASSERT((p == f.a || p == f.b) && (p == g.a || p == g.b));
          break;
        }
        case SegmentRelation::kOverlapping:
          RC_ASSERT(((f.a == g.a && f.b == g.b) || (f.a == g.b && f.b == g.a)));
          break;
        case SegmentRelation::kCrossing:
          RC_FAIL("two fragments cross");
      }
    }
  }
}

RC_GTEST_PROP(SnapRounding, FragmentsMeetOnlyAtCommonEndpoints, ()) {
  const Input in = *crowded_rings();
  RC_PRE(!in.segments.empty());
  const std::vector<Fragment> listed = node_and_snap_round(in.segments, in.next, false).fragments;
  const std::vector<Fragment> all = all_fragments(in, listed);
  // At twice as many fragments as segments the re-check takes its filtered grid path.
  RC_TAG(all.size() >= 2 * in.segments.size() ? "many fragments" : "few fragments");
  require_fragments_meet_only_at_endpoints(all);
}

RC_GTEST_PROP(SnapRounding, FragmentsOfManyScatteredRingsMeetOnlyAtCommonEndpoints, ()) {
  const Input in = *scattered_rings();
  const std::vector<Fragment> listed = node_and_snap_round(in.segments, in.next, false).fragments;
  require_fragments_meet_only_at_endpoints(all_fragments(in, listed));
}

RC_GTEST_PROP(SnapRounding, EachSegmentIsAChainOfNearbyFragments, ()) {
  const Input in = *crowded_rings();
  RC_PRE(!in.segments.empty());
  const std::vector<Fragment> listed = node_and_snap_round(in.segments, in.next, false).fragments;
  std::vector<std::vector<Segment>> of(in.segments.size());
  for (const Fragment& f : listed) of[f.parent].push_back(f.seg);
  for (std::uint32_t s = 0; s < in.segments.size(); ++s) {
    const Segment& seg = in.segments[s];
    if (of[s].empty()) continue;  // its own fragment
    RC_ASSERT(of[s].front().a == seg.a);
    RC_ASSERT(of[s].back().b == seg.b);
    for (std::size_t k = 0; k < of[s].size(); ++k) {
      if (k > 0) RC_ASSERT(of[s][k].a == of[s][k - 1].b);
      RC_ASSERT(within_half_unit(seg, of[s][k].a));
      RC_ASSERT(within_half_unit(seg, of[s][k].b));
    }
  }
}

}  // namespace
}  // namespace edgeland::detail
