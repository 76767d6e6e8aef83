// The clipper's candidate searches (clip/src: segment_index, segment_grid, box_grid) against
// brute force. They only propose pairs and points for the exact tests, so what matters is that
// they never miss one (a missed pair is a missed intersection) and that pairs come once.
// Generated inputs mix tiny, long and huge boxes, zero-width ones, shared coordinates and both
// ends of the coordinate range.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "box_grid.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "point_set.hpp"
#include "segment_grid.hpp"
#include "segment_index.hpp"

namespace edgeland::detail {
namespace {

rc::Gen<std::int64_t> coordinate() {
  return rc::gen::oneOf(rc::gen::inRange<std::int64_t>(-20, 21),
                        rc::gen::inRange<std::int64_t>(-kCoordBound, kCoordBound + 1),
                        rc::gen::element(-kCoordBound, kCoordBound, std::int64_t{0}));
}

rc::Gen<Point64> point() {
  return rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      coordinate(), coordinate());
}

rc::Gen<Box64> box() {
  return rc::gen::apply(
      [](Point64 a, Point64 b) {
        return Box64{{std::min(a.x, b.x), std::min(a.y, b.y)},
                     {std::max(a.x, b.x), std::max(a.y, b.y)}};
      },
      point(), point());
}

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

RC_GTEST_PROP(BoxGrid, ReportsEveryOverlappingPairExactlyOnce, ()) {
  const auto boxes = *rc::gen::container<std::vector<Box64>>(box());
  Pairs expected, got;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
  for_each_overlapping_pair_in_grid(boxes, [&](std::uint32_t i, std::uint32_t j) {
    RC_ASSERT(i < j);
    got.emplace_back(i, j);
  });
  std::sort(got.begin(), got.end());
  RC_ASSERT(got == expected);  // sorted, so a duplicate would show as an extra element
}

// Many small boxes in a patch (the grid's own case, not its fallback to the sweep).
RC_GTEST_PROP(BoxGrid, ReportsEveryPairAmongManySmallBoxes, ()) {
  const auto corners = *rc::gen::container<std::vector<Point64>>(rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      rc::gen::inRange<std::int64_t>(-500, 500), rc::gen::inRange<std::int64_t>(-500, 500)));
  std::vector<Box64> boxes;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const std::int64_t w = static_cast<std::int64_t>(i * 7 % 31),
                       h = static_cast<std::int64_t>(i * 13 % 23);
    boxes.push_back({corners[i], {corners[i].x + w, corners[i].y + h}});
  }
  Pairs expected, got;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
  for_each_overlapping_pair_in_grid(
      boxes, [&](std::uint32_t i, std::uint32_t j) { got.emplace_back(i, j); });
  std::sort(got.begin(), got.end());
  RC_ASSERT(got == expected);
}

// Twenty boxes covering a 10,000-unit square among 980 unit boxes: the cells follow the
// typical box (about 200 units), so each big box fills every one of some 2,600 cells, far
// past 32 cells per box; the grid hands over to the sweep, which must still report each
// overlapping pair once.
TEST(BoxGrid, FallsBackToTheSweepWhenBigBoxesFillEveryCell) {
  std::vector<Box64> boxes;
  for (std::int64_t k = 0; k < 20; ++k) boxes.push_back({{k, 0}, {10000, 10000 - k}});
  std::uint64_t state = 12345;  // a fixed linear congruential sequence places the small ones
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::int64_t>((state >> 33) % 10000);
  };
  while (boxes.size() < 1000) {
    const Point64 corner{next(), next()};
    boxes.push_back({corner, {corner.x + 1, corner.y + 1}});
  }
  Pairs expected, got;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) expected.emplace_back(i, j);
  for_each_overlapping_pair_in_grid(boxes, [&](std::uint32_t i, std::uint32_t j) {
    EXPECT_LT(i, j);
    got.emplace_back(i, j);
  });
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got.size(), expected.size());
  EXPECT_TRUE(got == expected);  // sorted, so a duplicate would show as an extra element
}

// Rings of random points (some on a small patch, so that boxes overlap often), as segments and
// ring successors.
struct RandomRings {
  std::vector<Segment> segs;
  std::vector<std::uint32_t> next;
};

RandomRings random_rings() {
  const auto ring_sizes = *rc::gen::container<std::vector<int>>(rc::gen::inRange(2, 40));
  RandomRings r;
  std::vector<Segment>& segs = r.segs;
  std::vector<std::uint32_t>& next = r.next;
  for (int size : ring_sizes) {
    std::vector<Point64> pts = *rc::gen::container<std::vector<Point64>>(
        static_cast<std::size_t>(size),
        rc::gen::oneOf(point(), rc::gen::apply(
                                    [](std::int64_t x, std::int64_t y) {
                                      return Point64{x, y};
                                    },
                                    rc::gen::inRange<std::int64_t>(0, 8),
                                    rc::gen::inRange<std::int64_t>(0, 8))));
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    while (pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
    if (pts.size() < 2) continue;
    const std::uint32_t first = static_cast<std::uint32_t>(segs.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      segs.push_back({pts[i], pts[(i + 1) % pts.size()]});
      next.push_back(static_cast<std::uint32_t>(segs.size()));
    }
    next.back() = first;
  }
  return r;
}

// The index's pairs and query hits against a check of every pair and every (query, segment).
void check_pairs_and_queries(const std::vector<Segment>& segs,
                             const std::vector<std::uint32_t>& next, std::size_t flat_up_to) {
  const SegmentIndex index(segs, next, flat_up_to);
  std::set<std::pair<std::uint32_t, std::uint32_t>> got;
  index.for_each_overlapping_pair([&](std::uint32_t i, std::uint32_t j) {
    RC_ASSERT(i != j);
    RC_ASSERT(got.insert({std::min(i, j), std::max(i, j)}).second);  // once
  });
  for (std::uint32_t i = 0; i < segs.size(); ++i)
    for (std::uint32_t j = i + 1; j < segs.size(); ++j) {
      if (!index.box(i).overlaps(index.box(j)) || got.count({i, j})) continue;
      // Left out: only consecutive segments of one run, which meet at one shared endpoint.
      RC_ASSERT(next[i] == j || next[j] == i);
      const Segment& s = segs[i];
      const Segment& t = segs[j];
      const Point64 shared = next[i] == j ? s.b : t.b;
      RC_ASSERT((shared == s.a || shared == s.b) && (shared == t.a || shared == t.b));
      // Same direction in x and y (a monotone run): nothing else in common.
      auto sign = [](std::int64_t v) { return (v > 0) - (v < 0); };
      const Segment& u = next[i] == j ? s : t;
      const Segment& w = next[i] == j ? t : s;
      RC_ASSERT(sign(u.b.x - u.a.x) * sign(w.b.x - w.a.x) >= 0);
      RC_ASSERT(sign(u.b.y - u.a.y) * sign(w.b.y - w.a.y) >= 0);
    }
  // Box queries: every segment whose box overlaps a query box.
  const auto queries = *rc::gen::container<std::vector<Box64>>(box());
  std::set<std::pair<std::uint32_t, std::uint32_t>> hits;
  index.query(queries, [&](std::uint32_t k, std::uint32_t s) { hits.insert({k, s}); });
  for (std::uint32_t k = 0; k < queries.size(); ++k)
    for (std::uint32_t s = 0; s < segs.size(); ++s)
      RC_ASSERT(hits.count({k, s}) == (queries[k].overlaps(index.box(s)) ? 1u : 0u));
}

// The flat search (few segments) and the run search, both asked: kFlatUpTo decides which one an
// index of these segments takes.
constexpr std::size_t kBothSearches[] = {0, std::numeric_limits<std::size_t>::max()};

RC_GTEST_PROP(SegmentIndex, ProposesEveryBoxOverlappingPairButRunNeighbours, ()) {
  const RandomRings rings = random_rings();  // (clang 14 cannot capture structured bindings)
  const std::vector<Segment>& segs = rings.segs;
  const std::vector<std::uint32_t>& next = rings.next;
  for (std::size_t flat_up_to : kBothSearches) check_pairs_and_queries(segs, next, flat_up_to);
}

// Both searches give the same pairs (with and without the pairs of one ring) and the same
// query hits.
RC_GTEST_PROP(SegmentIndex, FlatAndRunSearchesAgree, ()) {
  const RandomRings rings = random_rings();  // (clang 14 cannot capture structured bindings)
  const std::vector<Segment>& segs = rings.segs;
  const std::vector<std::uint32_t>& next = rings.next;
  const auto queries = *rc::gen::container<std::vector<Box64>>(box());
  auto answers = [&](std::size_t flat_up_to) {
    const SegmentIndex index(segs, next, flat_up_to);
    RC_ASSERT(index.flat() == (flat_up_to != 0 || segs.empty()));
    std::set<std::tuple<int, std::uint32_t, std::uint32_t>> got;
    for (const bool across : {false, true})
      index.for_each_overlapping_pair(
          [&](std::uint32_t i, std::uint32_t j) {
            got.insert({across, std::min(i, j), std::max(i, j)});
          },
          across);
    index.query(queries, [&](std::uint32_t k, std::uint32_t s) { got.insert({2, k, s}); });
    return got;
  };
  RC_ASSERT(answers(kBothSearches[0]) == answers(kBothSearches[1]));
}

// Long segments in every direction on a small patch (cells of a unit or two, where a meeting on
// a cell line or corner decides) or over the whole range: every pair that shares a point is
// proposed, and no pair twice.
// A point of the small patch [-12, 12]^2.
rc::Gen<Point64> patch_point() {
  return rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      rc::gen::inRange<std::int64_t>(-12, 13), rc::gen::inRange<std::int64_t>(-12, 13));
}

// `small`: `crowded` segments on the patch; otherwise up to 60 with ends on the patch or
// anywhere in the range.
std::vector<Segment> grid_segments(bool small, std::size_t crowded) {
  const auto end = small ? patch_point() : rc::gen::oneOf(point(), patch_point());
  return *rc::gen::container<std::vector<Segment>>(
      small ? crowded : *rc::gen::inRange<std::size_t>(0, 60), rc::gen::apply(
                                                                   [](Point64 a, Point64 b) {
                                                                     return Segment{a, b};
                                                                   },
                                                                   end, end));
}

RC_GTEST_PROP(SegmentGrid, ProposesEveryMeetingPairOnce, ()) {
  const bool small = *rc::gen::arbitrary<bool>();
  const std::vector<Segment> segs = grid_segments(small, 200);
  SegmentGrid grid(segs);
  if (*rc::gen::arbitrary<bool>()) grid.order_crowded_cells(segs);
  std::set<std::pair<std::uint32_t, std::uint32_t>> got;
  grid.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    RC_ASSERT(i < j);
    RC_ASSERT(got.insert({i, j}).second);
  });
  for (std::uint32_t i = 0; i < segs.size(); ++i)
    for (std::uint32_t j = i + 1; j < segs.size(); ++j)
      if (intersect(segs[i], segs[j]).relation != SegmentRelation::kDisjoint)
        RC_ASSERT(got.count({i, j}) == 1u);
  // Long diagonal segments do not fill the grid the way their boxes would.
  if (small) RC_ASSERT(grid.entries() <= 60 * segs.size());
}

// Whether segment s has a point in the closed box b (exact, by its corners and sides).
bool meets_box(const Segment& s, const Box64& b) {
  if (b.contains(s.a) || b.contains(s.b)) return true;
  const Point64 c[4] = {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
  for (int k = 0; k < 4; ++k)
    if (intersect(s, Segment{c[k], c[(k + 1) % 4]}).relation != SegmentRelation::kDisjoint)
      return true;
  return false;
}

// Snap rounding asks the grid for the segments near a point (a box of side 2 around it): every
// segment with a point in the box is visited, also for boxes reaching past the grid's extent.
RC_GTEST_PROP(SegmentGrid, BoxQueryVisitsEverySegmentMeetingTheBox, ()) {
  const std::vector<Segment> segs = grid_segments(*rc::gen::arbitrary<bool>(), 100);
  SegmentGrid grid(segs);
  if (*rc::gen::arbitrary<bool>()) grid.order_crowded_cells(segs);
  // Noding drops the pair walk also of a grid it did not walk (the run index won): its cells'
  // lists are then filled on the first query, from the slots it kept for that.
  if (*rc::gen::arbitrary<bool>()) grid.drop_pair_walk();
  const auto queries = *rc::gen::container<std::vector<Box64>>(
      20, rc::gen::oneOf(rc::gen::apply(
                             [](Point64 p) {
                               return Box64{{p.x - 1, p.y - 1}, {p.x + 1, p.y + 1}};
                             },
                             rc::gen::oneOf(patch_point(), point())),
                         box()));
  for (const Box64& q : queries) {
    std::set<std::uint32_t> visited;
    grid.for_each_in_box(q, [&](std::uint32_t s) {
      RC_ASSERT(s < segs.size());
      visited.insert(s);
    });
    for (std::uint32_t s = 0; s < segs.size(); ++s)
      if (meets_box(segs[s], q)) RC_ASSERT(visited.count(s) == 1u);
  }
}

// Two zigzags of long, nearly parallel segments a few units apart, the second shifted across
// the first (issue 28's zigzag stars in miniature, in any direction): vertex i of a zigzag lies
// i steps along `across` and, for odd i, `length` times `along` further, each vertex moved by up
// by jitter() in x and in y. Every grid cell they pass is crowded with them; their segments meet
// their neighbours, the other zigzag's segments, or nothing by a few units.
template <class Jitter>
std::vector<Segment> zigzag_pair(Point64 along, std::int64_t length, std::int64_t step,
                                 std::int64_t shift, Jitter jitter, std::size_t n) {
  const Point64 across{-along.y, along.x};
  std::vector<Segment> segs;
  for (std::int64_t z = 0; z < 2; ++z) {
    auto vertex = [&](std::int64_t i) {
      const std::int64_t out = i % 2 == 1 ? length : 0, side = i * step + z * shift;
      const std::int64_t jx = jitter(), jy = jitter();
      return Point64{across.x * side + along.x * out + jx, across.y * side + along.y * out + jy};
    };
    Point64 from = vertex(0);
    for (std::size_t i = 1; i <= n; ++i) {
      const Point64 to = vertex(static_cast<std::int64_t>(i));
      segs.push_back({from, to});
      from = to;
    }
  }
  return segs;
}

rc::Gen<std::vector<Segment>> crowded_zigzags() {
  return rc::gen::exec([] {
    const auto component = rc::gen::inRange<std::int64_t>(-300, 301);
    Point64 along{*component, *component};
    if (along == Point64{0, 0}) along = {1, 0};
    const std::int64_t length = *rc::gen::inRange<std::int64_t>(200, 20000);
    const std::int64_t step = *rc::gen::inRange<std::int64_t>(1, 4);
    const std::int64_t shift = *rc::gen::inRange<std::int64_t>(0, 6);
    const std::int64_t jitter = *rc::gen::element<std::int64_t>(0, 2, 40);
    return zigzag_pair(
        along, length, step, shift,
        [jitter] { return *rc::gen::inRange<std::int64_t>(-jitter, jitter + 1); },
        *rc::gen::inRange<std::size_t>(40, 160));
  });
}

// Crowded cells propose only pairs whose offsets across the cell overlap: still every pair that
// shares a point, once, and every segment with a point in a queried box.
RC_GTEST_PROP(SegmentGrid, CrowdedCellsMissNoMeetingPair, ()) {
  const std::vector<Segment> segs = *crowded_zigzags();
  SegmentGrid grid(segs);
  grid.order_crowded_cells(segs);
  std::set<std::pair<std::uint32_t, std::uint32_t>> got;
  grid.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) {
    RC_ASSERT(i < j);
    RC_ASSERT(got.insert({i, j}).second);
  });
  std::size_t meeting = 0;
  for (std::uint32_t i = 0; i < segs.size(); ++i)
    for (std::uint32_t j = i + 1; j < segs.size(); ++j)
      if (intersect(segs[i], segs[j]).relation != SegmentRelation::kDisjoint) {
        RC_ASSERT(got.count({i, j}) == 1u);
        ++meeting;
      }
  RC_CLASSIFY(grid.crowded_cells() > 0, "crowded");
  RC_ASSERT(grid.offsets_violation(segs).empty());
  RC_ASSERT(grid.cell_pairs() >= got.size());  // each proposed pair is counted in some cell
  std::vector<std::pair<Box64, std::set<std::uint32_t>>> queries;
  for (int k = 0; k < 20; ++k) {
    // Pixels around segment ends and points near segments' middles, and boxes over the fan.
    const Segment& s = *rc::gen::elementOf(segs);
    const Point64 mid{(s.a.x + s.b.x) / 2 + *rc::gen::inRange(-2, 3),
                      (s.a.y + s.b.y) / 2 + *rc::gen::inRange(-2, 3)};
    const Point64 p = *rc::gen::element(s.a, s.b, mid);
    const std::int64_t r = *rc::gen::element<std::int64_t>(1, 1, 30, 5000);
    const Box64 q{{p.x - r, p.y - r}, {p.x + r, p.y + r}};
    std::set<std::uint32_t> visited;
    grid.for_each_in_box(q, [&](std::uint32_t t) { visited.insert(t); });
    for (std::uint32_t t = 0; t < segs.size(); ++t)
      if (meets_box(segs[t], q)) RC_ASSERT(visited.count(t) == 1u);
    queries.push_back({q, visited});
  }
  // Noding frees the per-segment slots before snap rounding's box queries: they answer the same.
  grid.drop_pair_walk();
  for (const auto& [q, visited] : queries) {
    std::set<std::uint32_t> again;
    grid.for_each_in_box(q, [&](std::uint32_t t) { again.insert(t); });
    RC_ASSERT(again == visited);
  }
}

// A fixed case of the above that must take the crowded path, and must gain by it: the pairs
// the cells propose stay within a few per segment, not the hundreds sharing each cell.
TEST(SegmentGrid, CrowdedCellsProposeFewPairsAndAllMeetingOnes) {
  std::int64_t wobble = 0;  // a fixed jitter: -1, 0, 1, -1, ...
  const std::vector<Segment> segs = zigzag_pair(
      {7, 200}, 5000, 3, 2, [&] { return ++wobble % 3 - 1; }, 400);
  SegmentGrid grid(segs);
  const std::size_t unordered_pairs = grid.cell_pairs();
  grid.order_crowded_cells(segs);
  ASSERT_GT(grid.crowded_cells(), 0u);
  EXPECT_EQ(grid.offsets_violation(segs), "");
  std::set<std::pair<std::uint32_t, std::uint32_t>> got;
  grid.for_each_candidate_pair([&](std::uint32_t i, std::uint32_t j) { got.insert({i, j}); });
  std::size_t meeting = 0;
  for (std::uint32_t i = 0; i < segs.size(); ++i)
    for (std::uint32_t j = i + 1; j < segs.size(); ++j)
      if (intersect(segs[i], segs[j]).relation != SegmentRelation::kDisjoint) {
        EXPECT_EQ(got.count({i, j}), 1u) << i << " " << j;
        ++meeting;
      }
  EXPECT_GE(meeting, segs.size() - 2);            // ring neighbours at least
  EXPECT_GT(unordered_pairs, 100 * segs.size());  // every pair of each cell
  EXPECT_LE(grid.cell_pairs(), 16 * segs.size());
  EXPECT_LE(got.size(), 8 * segs.size());
}

// The hot-pixel set against std::set: inserts report novelty, membership survives growth and
// clear() empties it. Points are few distinct ones (many repeats) or spread over the range.
RC_GTEST_PROP(PointSet, AgreesWithStdSet, ()) {
  const auto small_point = rc::gen::apply(
      [](std::int64_t x, std::int64_t y) {
        return Point64{x, y};
      },
      rc::gen::inRange<std::int64_t>(-5, 6), rc::gen::inRange<std::int64_t>(-5, 6));
  const auto pts = *rc::gen::container<std::vector<Point64>>(rc::gen::oneOf(small_point, point()));
  PointSet set;
  std::set<Point64> reference;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (k == pts.size() / 2 && *rc::gen::arbitrary<bool>()) {
      set.clear();
      reference.clear();
    }
    RC_ASSERT(set.insert(pts[k]) == reference.insert(pts[k]).second);
    RC_ASSERT(set.size() == reference.size());
  }
  for (const Point64 p : pts) RC_ASSERT(set.contains(p) == (reference.count(p) == 1));
  RC_ASSERT(!set.contains(Point64{kCoordBound, -kCoordBound}) ||
            reference.count(Point64{kCoordBound, -kCoordBound}) == 1);
}

// Validated operands' rings are simple: the index can leave out every pair within one ring.
// Pairs of one ring are exactly the pairs for_each_overlapping_pair leaves out across rings.
void check_across_rings_only(const std::vector<Segment>& segs,
                             const std::vector<std::uint32_t>& next,
                             const std::vector<std::uint32_t>& ring_of, std::size_t flat_up_to) {
  const SegmentIndex index(segs, next, flat_up_to);
  std::set<std::pair<std::uint32_t, std::uint32_t>> all, across;
  index.for_each_overlapping_pair([&](std::uint32_t i, std::uint32_t j) {
    all.insert({std::min(i, j), std::max(i, j)});
  });
  index.for_each_overlapping_pair(
      [&](std::uint32_t i, std::uint32_t j) {
        across.insert({std::min(i, j), std::max(i, j)});
      },
      true);
  std::size_t same_ring = 0;
  for (const auto& pair : all) {
    const bool same = ring_of[pair.first] == ring_of[pair.second];
    same_ring += same;
    EXPECT_EQ(across.count(pair), same ? 0u : 1u);
  }
  EXPECT_EQ(across.size() + same_ring, all.size());
  EXPECT_GT(same_ring, 0u);
  EXPECT_GT(across.size(), 0u);
}

TEST(SegmentIndex, AcrossRingsOnlyLeavesOutExactlyThePairsOfOneRing) {
  // Two overlapping zigzag rings (many short runs) and a square crossing both.
  std::vector<Segment> segs;
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> ring_of;
  auto add_ring = [&](const std::vector<Point64>& pts) {
    const std::uint32_t first = static_cast<std::uint32_t>(segs.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      segs.push_back({pts[i], pts[(i + 1) % pts.size()]});
      next.push_back(static_cast<std::uint32_t>(segs.size()));
      ring_of.push_back(first);
    }
    next.back() = first;
  };
  std::vector<Point64> zig, zag;
  for (std::int64_t x = 0; x <= 40; x += 2) zig.push_back({x, x % 4 == 0 ? 0 : 6});
  zig.push_back({40, -10});
  zig.push_back({0, -10});
  for (std::int64_t x = 1; x <= 41; x += 2) zag.push_back({x, x % 4 == 1 ? 1 : 7});
  zag.push_back({41, 20});
  zag.push_back({1, 20});
  add_ring(zig);
  add_ring(zag);
  add_ring({{-5, -5}, {50, -5}, {50, 3}, {-5, 3}});
  for (std::size_t flat_up_to : kBothSearches) {
    SCOPED_TRACE(flat_up_to == 0 ? "run search" : "flat search");
    check_across_rings_only(segs, next, ring_of, flat_up_to);
  }
}

}  // namespace
}  // namespace edgeland::detail
