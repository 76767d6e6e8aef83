// Noding (clip/src/noding.hpp): find_contacts against a brute force over every pair of segments,
// classified by the kernel's `intersect` alone (none of classify_pair's shortcuts for shared
// endpoints and axis-parallel pairs), and classify_pair on small hand-made cases.
//
// Contract checked, from noding.hpp: a pair meets "other than at a shared endpoint" (counted in
// `intersections`) unless the kernel finds them disjoint or touching at a point that is an
// endpoint of both; both segments are touched unless they are ring neighbours meeting only at
// their shared endpoint; splits are exactly the integer contact points (touching points, overlap
// ends, integer crossings) strictly inside a segment; hot lists the pixels of the non-integer
// crossings; `overlaps` counts pairs sharing a stretch of positive length, and the budget stops
// noding exactly when they pass it; the screen stops exactly at the contacts that prove an
// operand invalid (a ring meeting itself other than at neighbours' shared endpoint, two rings of
// one operand crossing properly or overlapping in the same direction).
#include "noding.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "generators.hpp"
#include "input_edges.hpp"
#include "stage_inputs.hpp"

namespace edgeland::test {
namespace {

using detail::Contacts;
using detail::EdgeList;
using detail::Meeting;
using detail::NodingOptions;

struct Expected {
  std::set<std::pair<std::uint32_t, Point64>> splits;
  std::set<Point64> hot;
  std::vector<std::uint8_t> touched;
  std::size_t intersections = 0;
  std::size_t overlaps = 0;
  bool invalid = false;  // some contact proves an operand invalid (screening)
};

bool shared_endpoint_only(const SegmentIntersection& r, const Segment& s, const Segment& t) {
  if (r.relation != SegmentRelation::kTouching) return false;
  const Point64 p = round_to_grid(r.point);  // an endpoint: exact
  return (p == s.a || p == s.b) && (p == t.a || p == t.b);
}

void split_if_interior(Expected& x, std::uint32_t i, const Segment& s, Point64 p) {
  if (p != s.a && p != s.b) x.splits.insert({i, p});
}

Expected brute_force(const EdgeList& edges) {
  const auto& segs = edges.segments;
  const auto spans = stages::ring_spans(edges);
  std::vector<std::uint32_t> ring_of(edges.size());
  for (std::uint32_t r = 0; r < spans.size(); ++r)
    for (std::uint32_t s = spans[r].first; s < spans[r].second; ++s) ring_of[s] = r;
  Expected x;
  x.touched.assign(edges.size(), 0);
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    for (std::uint32_t j = i + 1; j < edges.size(); ++j) {
      const Segment &s = segs[i], &t = segs[j];
      const SegmentIntersection r = intersect(s, t);
      if (r.relation == SegmentRelation::kDisjoint) continue;
      const bool endpoint_only = shared_endpoint_only(r, s, t);
      const bool neighbours = edges.next[i] == j || edges.next[j] == i;
      if (!(endpoint_only && neighbours)) x.touched[i] = x.touched[j] = 1;
      if (!endpoint_only) ++x.intersections;
      switch (r.relation) {
        case SegmentRelation::kTouching: {
          const Point64 p = round_to_grid(r.point);
          split_if_interior(x, i, s, p);
          split_if_interior(x, j, t, p);
          break;
        }
        case SegmentRelation::kOverlapping:
          ++x.overlaps;
          for (Point64 p : {r.overlap_from, r.overlap_to}) {
            split_if_interior(x, i, s, p);
            split_if_interior(x, j, t, p);
          }
          break;
        case SegmentRelation::kCrossing:
          if (r.point.is_integer()) {
            split_if_interior(x, i, s, round_to_grid(r.point));
            split_if_interior(x, j, t, round_to_grid(r.point));
          } else {
            x.hot.insert(round_to_grid(r.point));
          }
          break;
        case SegmentRelation::kDisjoint:
          break;
      }
      // Screening's proofs of an invalid operand.
      if (ring_of[i] == ring_of[j]) {
        if (!(endpoint_only && neighbours)) x.invalid = true;
      } else if (edges.channel[i] == edges.channel[j]) {
        const bool same_way =
            Int128(s.b.x - s.a.x) * (t.b.x - t.a.x) + Int128(s.b.y - s.a.y) * (t.b.y - t.a.y) > 0;
        if (r.relation == SegmentRelation::kCrossing ||
            (r.relation == SegmentRelation::kOverlapping && same_way))
          x.invalid = true;
      }
    }
  }
  return x;
}

Contacts noded(const EdgeList& edges, const NodingOptions& options) {
  detail::SegmentSearch search(edges.segments, edges.next);
  return detail::find_contacts(edges.segments, edges.next, search, options);
}

void assert_contacts_match(const Contacts& c, const Expected& x) {
  RC_ASSERT(!c.stopped());
  const std::set<std::pair<std::uint32_t, Point64>> splits(c.splits.begin(), c.splits.end());
  RC_ASSERT(splits == x.splits);
  const std::set<Point64> hot(c.hot.begin(), c.hot.end());
  RC_ASSERT(hot == x.hot);
  RC_ASSERT(c.touched == x.touched);
  RC_ASSERT(c.intersections == x.intersections);
  RC_ASSERT(c.overlaps == x.overlaps);
}

EdgeList edges_of(const std::vector<Ring>& subject, const std::vector<Ring>& clip) {
  EdgeList edges;
  detail::append_ring_edges(subject, detail::kSubjectChannel, true, edges);
  detail::append_ring_edges(clip, detail::kClipChannel, true, edges);
  return edges;
}

// Crowded self-intersecting rings in two operands. With 64 segments or more and short runs
// noding walks a segment grid instead of the run index: both paths are taken.
rc::Gen<EdgeList> crowded_edges() {
  return rc::gen::exec([] {
    const int points = *rc::gen::element(6, 24, 48);
    return edges_of(*stages::crowded_rings(4, points, true),
                    *stages::crowded_rings(3, points, true));
  });
}

RC_GTEST_PROP(Noding, ContactsAreExactlyThoseOfAllPairs, ()) {
  const EdgeList edges = *crowded_edges();
  RC_TAG(edges.size() >= 64 ? "64 segments or more" : "fewer than 64 segments");
  assert_contacts_match(noded(edges, {}), brute_force(edges));
}

// Valid operands (strictly simple rings): skipping the pairs within a ring loses nothing.
RC_GTEST_PROP(Noding, SimpleRingsLoseNoContactOfValidOperands, ()) {
  const OperandPair p = *gen::local_pair({0, 0}, *rc::gen::element<std::int64_t>(4, 8, 16));
  const EdgeList edges = edges_of(p.a, p.b);
  NodingOptions options;
  options.simple_rings = true;
  assert_contacts_match(noded(edges, options), brute_force(edges));
}

// The screen stops exactly when some contact proves an operand invalid; when it does not stop,
// the contacts are complete.
RC_GTEST_PROP(Noding, ScreenStopsExactlyAtProofsOfInvalidOperands, ()) {
  const bool valid = (stages::uniform(0, 1) == 1);
  EdgeList edges;
  if (valid) {
    const OperandPair p = *gen::local_pair({0, 0}, *rc::gen::element<std::int64_t>(4, 8, 16));
    edges = edges_of(p.a, p.b);
  } else {
    edges = *crowded_edges();
  }
  const Expected x = brute_force(edges);
  RC_TAG(x.invalid ? "invalid" : "valid");
  if (valid) RC_ASSERT(!x.invalid);  // the reference agrees the generator's sets are valid
  NodingOptions options;
  options.simple_rings = (stages::uniform(0, 1) == 1);  // ignored when screening
  options.screen_channel = &edges.channel;
  const Contacts c = noded(edges, options);
  RC_ASSERT(c.operand_invalid == x.invalid);
  RC_ASSERT(!c.overlap_heavy);
  if (!x.invalid) assert_contacts_match(c, x);
}

// The overlap budget: noding stops exactly when more pairs overlap than it allows.
RC_GTEST_PROP(Noding, OverlapBudgetStopsExactlyWhenPassed, ()) {
  // Stacks of collinear squares: copies and shifted copies along a common side, with a few
  // crowded rings around them.
  const int copies = stages::uniform_int(1, 5);
  std::vector<Ring> rings;
  for (int k = 0; k < copies; ++k) {
    const std::int64_t dx = stages::uniform(0, 2);
    rings.push_back({{dx, 0}, {dx + 4, 0}, {dx + 4, 4}, {dx, 4}});
  }
  const EdgeList edges = edges_of(rings, *stages::crowded_rings(2, 6));
  const Expected x = brute_force(edges);
  NodingOptions options;
  options.overlap_budget =
      static_cast<std::size_t>(stages::uniform(0, static_cast<std::int64_t>(x.overlaps) + 1));
  const Contacts c = noded(edges, options);
  RC_ASSERT(c.overlap_heavy == (x.overlaps > options.overlap_budget));
  RC_ASSERT(!c.operand_invalid);
  if (!c.overlap_heavy) assert_contacts_match(c, x);
}

TEST(Noding, OverlapBudgetStopsOnAStackOfCopies) {
  // Five copies of a square: C(5, 2) = 10 overlapping pairs on each side, 40 in all.
  const std::vector<Ring> copies(5, Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const EdgeList edges = edges_of(copies, {});
  NodingOptions options;
  options.overlap_budget = 39;
  EXPECT_TRUE(noded(edges, options).overlap_heavy);
  options.overlap_budget = 40;
  const Contacts c = noded(edges, options);
  EXPECT_FALSE(c.overlap_heavy);
  EXPECT_EQ(c.overlaps, 40u);
  EXPECT_EQ(c.intersections, 40u);  // pairs of different sides meet only at shared corners
}

TEST(Noding, ScreenStopsAtARingTouchingItself) {
  // A square with a notch from the top whose tip (2, 0) lies on the ring's own bottom edge.
  const Ring pinched{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}};
  EdgeList edges = edges_of({pinched}, {});
  NodingOptions options;
  options.screen_channel = &edges.channel;
  EXPECT_TRUE(noded(edges, options).operand_invalid);
  // The same ring without the touch (the notch stops short of the bottom) is valid.
  edges = edges_of({{{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}}, {});
  options.screen_channel = &edges.channel;
  EXPECT_FALSE(noded(edges, options).operand_invalid);
  // Two squares of one operand sharing an edge in opposite directions are valid; two of one
  // operand overlapping are not, while the same squares in two operands are.
  const Ring left{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, right{{2, 0}, {4, 0}, {4, 2}, {2, 2}},
      shifted{{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  edges = edges_of({left, right}, {});
  options.screen_channel = &edges.channel;
  EXPECT_FALSE(noded(edges, options).operand_invalid);
  edges = edges_of({left, shifted}, {});
  options.screen_channel = &edges.channel;
  EXPECT_TRUE(noded(edges, options).operand_invalid);
  edges = edges_of({left}, {shifted});
  options.screen_channel = &edges.channel;
  EXPECT_FALSE(noded(edges, options).operand_invalid);
}

// ---- classify_pair on hand-made pairs --------------------------------------------------------

struct Classified {
  Meeting meeting;
  Contacts c;
};

Classified classify(Segment s, Segment t) {
  Classified out{Meeting::kNone, {}};
  out.meeting = detail::classify_pair(s, 0, t, 1, out.c);
  return out;
}

std::vector<std::pair<std::uint32_t, Point64>> splits_of(const Contacts& c) {
  std::vector<std::pair<std::uint32_t, Point64>> v(c.splits.begin(), c.splits.end());
  std::sort(v.begin(), v.end());
  return v;
}

TEST(ClassifyPair, CrossingAtAnIntegerPointSplitsBoth) {
  const Classified r = classify({{0, 0}, {4, 4}}, {{0, 4}, {4, 0}});
  EXPECT_EQ(r.meeting, Meeting::kOther);
  EXPECT_EQ(splits_of(r.c),
            (std::vector<std::pair<std::uint32_t, Point64>>{{0, {2, 2}}, {1, {2, 2}}}));
  EXPECT_TRUE(r.c.hot.empty());
  EXPECT_EQ(r.c.intersections, 1u);
  EXPECT_EQ(r.c.overlaps, 0u);
}

TEST(ClassifyPair, CrossingAtANonIntegerPointIsHot) {
  // (0, 0)-(3, 1) and (0, 1)-(3, 0) cross at (3/2, 1/2): its pixel is (2, 1) (ties round up).
  const Classified r = classify({{0, 0}, {3, 1}}, {{0, 1}, {3, 0}});
  EXPECT_EQ(r.meeting, Meeting::kOther);
  EXPECT_TRUE(r.c.splits.empty());
  EXPECT_EQ(std::vector<Point64>(r.c.hot.begin(), r.c.hot.end()), (std::vector<Point64>{{2, 1}}));
  EXPECT_EQ(r.c.intersections, 1u);
  // (0, 0)-(5, 2) and (0, 2)-(5, 0) cross at (5/2, 1): pixel (3, 1).
  const Classified q = classify({{0, 0}, {5, 2}}, {{0, 2}, {5, 0}});
  EXPECT_EQ(std::vector<Point64>(q.c.hot.begin(), q.c.hot.end()), (std::vector<Point64>{{3, 1}}));
}

TEST(ClassifyPair, TJunctionSplitsOnlyTheSegmentTouchedInside) {
  for (const Segment& stem :
       {Segment{{2, 0}, {2, 3}}, Segment{{2, 3}, {2, 0}}, Segment{{2, 0}, {5, 3}}}) {
    const Classified r = classify({{0, 0}, {4, 0}}, stem);
    EXPECT_EQ(r.meeting, Meeting::kOther);
    EXPECT_EQ(splits_of(r.c), (std::vector<std::pair<std::uint32_t, Point64>>{{0, {2, 0}}}));
    EXPECT_EQ(r.c.intersections, 1u);
    EXPECT_EQ(r.c.overlaps, 0u);
    // The other way round: segment 1 is split.
    const Classified q = classify(stem, {{4, 0}, {0, 0}});
    EXPECT_EQ(q.meeting, Meeting::kOther);
    EXPECT_EQ(splits_of(q.c), (std::vector<std::pair<std::uint32_t, Point64>>{{1, {2, 0}}}));
  }
}

TEST(ClassifyPair, CollinearOverlapSplitsAtTheOtherEnds) {
  // Horizontal, and along a diagonal of slope 1/2.
  Classified r = classify({{0, 0}, {4, 0}}, {{6, 0}, {2, 0}});
  EXPECT_EQ(r.meeting, Meeting::kOther);
  EXPECT_EQ(splits_of(r.c),
            (std::vector<std::pair<std::uint32_t, Point64>>{{0, {2, 0}}, {1, {4, 0}}}));
  EXPECT_EQ(r.c.overlaps, 1u);
  EXPECT_EQ(r.c.intersections, 1u);
  r = classify({{0, 0}, {4, 2}}, {{2, 1}, {6, 3}});
  EXPECT_EQ(splits_of(r.c),
            (std::vector<std::pair<std::uint32_t, Point64>>{{0, {2, 1}}, {1, {4, 2}}}));
  EXPECT_EQ(r.c.overlaps, 1u);
  // One inside the other: the outer one is split at both ends of the inner one.
  r = classify({{0, 0}, {0, 6}}, {{0, 4}, {0, 1}});
  EXPECT_EQ(splits_of(r.c),
            (std::vector<std::pair<std::uint32_t, Point64>>{{0, {0, 1}}, {0, {0, 4}}}));
  // The same segment, either way round: an overlap with nothing to split.
  for (const Segment& t : {Segment{{1, 1}, {4, 3}}, Segment{{4, 3}, {1, 1}}}) {
    r = classify({{1, 1}, {4, 3}}, t);
    EXPECT_EQ(r.meeting, Meeting::kOther);
    EXPECT_TRUE(r.c.splits.empty());
    EXPECT_EQ(r.c.overlaps, 1u);
    EXPECT_EQ(r.c.intersections, 1u);
  }
  // A spike: neighbours sharing an endpoint and folding back along each other.
  r = classify({{0, 0}, {4, 0}}, {{4, 0}, {1, 0}});
  EXPECT_EQ(r.meeting, Meeting::kOther);
  EXPECT_EQ(splits_of(r.c), (std::vector<std::pair<std::uint32_t, Point64>>{{0, {1, 0}}}));
  EXPECT_EQ(r.c.overlaps, 1u);
}

TEST(ClassifyPair, SharedEndpointRecordsNothing) {
  for (const auto& [s, t] : {std::pair<Segment, Segment>{{{0, 0}, {4, 0}}, {{4, 0}, {4, 3}}},
                             {{{0, 0}, {2, 0}}, {{2, 0}, {5, 0}}},  // collinear, end to end
                             {{{0, 0}, {2, 2}}, {{5, 1}, {0, 0}}},
                             {{{3, 3}, {0, 0}}, {{3, 3}, {6, 6}}}}) {  // collinear, back to back
    const Classified r = classify(s, t);
    EXPECT_EQ(r.meeting, Meeting::kSharedEndpoint);
    EXPECT_TRUE(r.c.splits.empty());
    EXPECT_TRUE(r.c.hot.empty());
    EXPECT_EQ(r.c.intersections, 0u);
    EXPECT_EQ(r.c.overlaps, 0u);
  }
}

TEST(ClassifyPair, DisjointPairsRecordNothing) {
  for (const auto& [s, t] : {std::pair<Segment, Segment>{{{0, 0}, {4, 0}}, {{0, 1}, {4, 1}}},
                             {{{0, 0}, {1, 0}}, {{2, 0}, {3, 0}}},  // collinear, apart
                             {{{0, 0}, {0, 4}}, {{1, 2}, {5, 2}}},  // perpendicular, apart
                             {{{0, 0}, {4, 4}}, {{3, 0}, {5, 1}}}}) {
    const Classified r = classify(s, t);
    EXPECT_EQ(r.meeting, Meeting::kNone);
    EXPECT_TRUE(r.c.splits.empty());
    EXPECT_TRUE(r.c.hot.empty());
    EXPECT_EQ(r.c.intersections, 0u);
  }
}

}  // namespace
}  // namespace edgeland::test
