// Assembly (clip/src/assembly.hpp): assemble, trace_boundaries and split_at_repeated_vertices on
// real labels of real plane graphs (valid operand pairs under every operation, crowded rings
// under every fill rule), checked by brute force:
//  * every ring written is strictly simple; rings of regions without holes are counter-clockwise
//    and canonical (smallest point first, no collinear vertices); a region with a hole goes to
//    `holed` with its outer rings counter-clockwise and its holes clockwise;
//  * the rings, cut into lattice unit steps, are exactly the boundary of the labelled regions:
//    each unit step of the arrangement whose two sides have different labels (from the snapped
//    rings' winding numbers at points just beside it, stage_inputs.hpp) appears once in a ring of
//    the label on its left, in that direction, for each side that is in the result; nothing else;
//  * trace_boundaries walks every emitted half-edge exactly once, along closed walks taking the
//    sharpest left turn among half-edges of the walk's label (independent angle comparison), and
//    flags exactly the walks that leave a vertex twice; split_at_repeated_vertices cuts a walk
//    into closed loops that leave each vertex once and together use the walk's half-edges.
#include "assembly.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "canonical.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "generators.hpp"
#include "stage_inputs.hpp"

namespace edgeland::test {
namespace {

using detail::Assembled;
using detail::FaceLabel;
using detail::LabelMode;
using detail::LabelOf;
using detail::SideState;

// One assembly input: operands, how they are labelled, and what the result keeps.
struct Case {
  std::vector<Ring> subject, clip;
  LabelMode mode = LabelMode::kOwner;
  LabelOf label_of = LabelOf::operation(ClipOp::kUnion);
  bool collinear_free = false;  // the operands have no collinear consecutive vertices
  bool simple_rings = true;
};

rc::Gen<Case> cases() {
  return rc::gen::exec([] {
    Case c;
    const std::int64_t kind = stages::uniform(0, 2);
    if (kind < 2) {  // valid operands under an operation
      const std::int64_t r = *rc::gen::element<std::int64_t>(4, 8, 16, 30);
      const Point64 at{*gen::coord(-2, 2), *gen::coord(-2, 2)};
      // Random pairs, or a shape with smaller shapes in and around it (holes, holes touching
      // the outer ring or each other).
      const OperandPair p = kind == 0 ? *gen::local_pair(at, r)
                                      : gen::pair_of("shapes-inside", {*gen::shape(at, r)},
                                                     *gen::polygon_set(at, r / 2));
      c.subject = p.a;
      c.clip = p.b;
      c.label_of =
          LabelOf::operation(kind == 0 ? *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection,
                                                           ClipOp::kDifference, ClipOp::kXor)
                                       : *rc::gen::element(ClipOp::kDifference, ClipOp::kXor));
      c.collinear_free = detail::collinear_free(p.a) && detail::collinear_free(p.b);
    } else {  // any rings under a fill rule
      c.subject = *stages::crowded_rings(4, 16);
      c.clip = *stages::crowded_rings(2, 16);
      c.mode = LabelMode::kWinding;
      c.label_of = LabelOf::fill(*rc::gen::element(FillRule::kEvenOdd, FillRule::kNonZero,
                                                   FillRule::kPositive, FillRule::kNegative));
      c.simple_rings = false;
    }
    return c;
  });
}

// Label of the face around the (scaled) point q, from the snapped rings.
FaceLabel brute_label(const stages::BruteStates& brute, const Case& c, Point64 q) {
  if (c.mode == LabelMode::kWinding) return c.label_of(brute.winding_state(q));
  const std::optional<SideState> s = brute.owner_state(q);
  RC_ASSERT(s.has_value());
  return c.label_of(*s);
}

using LabelledStep =
    std::tuple<Point64, Point64, FaceLabel>;  // directed unit step, label on its left

void add_ring_steps(const Ring& ring, FaceLabel label, std::map<LabelledStep, int>& steps) {
  for (std::size_t i = 0; i < ring.size(); ++i)
    stages::for_each_unit_step(ring[i], ring[(i + 1) % ring.size()], [&](Point64 p, Point64 q) {
      ++steps[{p, q, label}];
    });
}

// The first labelled step counted differently in `got` (the rings) and `want`, or "".
std::string first_difference(const std::map<LabelledStep, int>& got,
                             const std::map<LabelledStep, int>& want) {
  std::map<LabelledStep, std::pair<int, int>> both;
  for (const auto& [step, n] : got) both[step].first = n;
  for (const auto& [step, n] : want) both[step].second = n;
  for (const auto& [step, n] : both) {
    if (n.first == n.second) continue;
    const auto& [p, q, label] = step;
    return "unit step " + stages::str(p) + " -> " + stages::str(q) + " with label " +
           std::to_string(label) + " on its left: in the rings " + std::to_string(n.first) +
           " times, on the boundary " + std::to_string(n.second) + " times";
  }
  return "";
}

bool canonical(const Ring& ring) {
  if (*std::min_element(ring.begin(), ring.end()) != ring.front()) return false;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
    if (orientation(ring[i], ring[(i + 1) % n], ring[(i + 2) % n]) == Orientation::kCollinear)
      return false;
  return true;
}

Ring reversed(const Ring& r) { return Ring(r.rbegin(), r.rend()); }

RC_GTEST_PROP(Assembly, RingsAreExactlyTheBoundariesOfTheLabelledRegions, ()) {
  const Case c = *cases();
  const stages::Arrangement a(c.subject, c.clip, c.simple_rings);
  std::vector<SideState> left;
  RC_ASSERT(detail::label_sides(a.graph, c.mode, left));
  const Assembled out = detail::assemble(a.graph, left, c.label_of, c.collinear_free);
  RC_TAG(out.holed.empty() ? "no holes" : "holes");
  // The rings.
  RC_ASSERT(out.labels.size() == out.rings.size());
  std::map<LabelledStep, int> got;
  for (std::size_t i = 0; i < out.rings.size(); ++i) {
    RC_ASSERT(validate(out.rings[i], 1).ok());  // strictly simple, counter-clockwise
    RC_ASSERT(canonical(out.rings[i]));
    RC_ASSERT(out.labels[i] >= 0);
    add_ring_steps(out.rings[i], out.labels[i], got);
  }
  for (std::size_t k = 0; k < out.holed.size(); ++k) {
    const detail::RegionRings& region = out.holed[k];
    if (k > 0) RC_ASSERT(out.holed[k - 1].label < region.label);
    RC_ASSERT(std::find(out.labels.begin(), out.labels.end(), region.label) == out.labels.end());
    RC_ASSERT(!region.holes.empty());
    RC_ASSERT(!region.outers.empty());
    for (const Ring& r : region.outers) {
      RC_ASSERT(validate(r, 1).ok());
      add_ring_steps(r, region.label, got);
    }
    for (const Ring& r : region.holes) {
      RC_ASSERT(validate(reversed(r), 1).ok());  // clockwise
      add_ring_steps(r, region.label, got);
    }
  }
  // The boundary of the labelled regions, unit step by unit step.
  const stages::BruteStates brute(a);
  std::set<stages::UnitStep> steps;
  for (const auto& fragments : stages::fragments_by_segment(a.edges, a.fragments))
    for (const Segment& f : fragments)
      stages::for_each_unit_step(
          f.a, f.b, [&](Point64 p, Point64 q) { steps.insert(stages::undirected(p, q)); });
  std::map<LabelledStep, int> want;
  for (const stages::UnitStep& s : steps) {
    const FaceLabel l = brute_label(brute, c, brute.probe().left_of(s.lo, s.hi));
    const FaceLabel r = brute_label(brute, c, brute.probe().right_of(s.lo, s.hi));
    if (l == r) continue;
    if (l >= 0) ++want[{s.lo, s.hi, l}];
    if (r >= 0) ++want[{s.hi, s.lo, r}];
  }
  RC_ASSERT(first_difference(got, want) == std::string());
}

// What assemble emits (assembly.hpp): on every edge whose sides have different labels, each
// half-edge carries the label on its left.
std::vector<FaceLabel> emitted_of(const detail::PlaneGraph& g, const std::vector<SideState>& left,
                                  const LabelOf& label_of) {
  std::vector<FaceLabel> emitted(left.size(), -1);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const FaceLabel l = label_of(left[2 * e]), r = label_of(left[2 * e + 1]);
    if (l == r) continue;
    emitted[2 * e] = l;
    emitted[2 * e + 1] = r;
  }
  return emitted;
}

Point64 direction(const detail::PlaneGraph& g, std::uint32_t h) {
  const Point64 o = g.vertices[g.origin(h)], t = g.first_step(h);
  return {t.x - o.x, t.y - o.y};
}

// The half-edge after `cur` on the boundary of `label`: at cur's target, the first half-edge
// of that label clockwise from cur's twin.
std::uint32_t sharpest_left(const detail::PlaneGraph& g, const std::vector<FaceLabel>& emitted,
                            std::uint32_t cur, FaceLabel label) {
  const std::uint32_t w = g.target(cur);
  const Point64 back = direction(g, cur ^ 1);
  std::optional<std::uint32_t> before, last;  // the last candidate before `back`, the last of all
  for (std::uint32_t k = g.around_begin[w]; k < g.around_begin[w + 1]; ++k) {
    const std::uint32_t h = g.around[k];
    if (emitted[h] != label) continue;
    const Point64 d = direction(g, h);
    if (!last || stages::ccw_before(direction(g, *last), d)) last = h;
    if (stages::ccw_before(d, back) && (!before || stages::ccw_before(direction(g, *before), d)))
      before = h;
  }
  RC_ASSERT(last.has_value());
  return before ? *before : *last;
}

bool closed_chain(const detail::PlaneGraph& g, const std::uint32_t* first,
                  const std::uint32_t* last) {
  for (const std::uint32_t* h = first; h != last; ++h) {
    const std::uint32_t next = h + 1 == last ? *first : *(h + 1);
    if (g.target(*h) != g.origin(next)) return false;
  }
  return first != last;
}

RC_GTEST_PROP(Assembly, WalksFollowTheSharpestLeftTurnOverEveryEmittedHalfEdgeOnce, ()) {
  const Case c = *cases();
  const stages::Arrangement a(c.subject, c.clip, c.simple_rings);
  const detail::PlaneGraph& g = a.graph;
  std::vector<SideState> left;
  RC_ASSERT(detail::label_sides(g, c.mode, left));
  const std::vector<FaceLabel> emitted = emitted_of(g, left, c.label_of);
  const detail::BoundaryWalks walks = detail::trace_boundaries(g, emitted);
  RC_ASSERT(walks.begin.size() == walks.size() + 1);
  RC_ASSERT(walks.revisits.size() == walks.size());
  RC_ASSERT(walks.begin.front() == 0u);
  RC_ASSERT(walks.begin.back() == walks.half_edges.size());
  // Every emitted half-edge once, nothing else.
  std::vector<int> uses(emitted.size(), 0);
  for (std::uint32_t h : walks.half_edges) ++uses[h];
  for (std::uint32_t h = 0; h < emitted.size(); ++h)
    RC_ASSERT(uses[h] == (emitted[h] >= 0 ? 1 : 0));
  std::vector<std::int32_t> position(g.vertices.size(), -1);
  bool any_revisit = false;
  for (std::size_t i = 0; i < walks.size(); ++i) {
    const std::uint32_t *first = walks.first(i), *last = walks.last(i);
    RC_ASSERT(closed_chain(g, first, last));
    std::set<std::uint32_t> origins;
    bool revisits = false;
    for (const std::uint32_t* h = first; h != last; ++h) {
      RC_ASSERT(emitted[*h] == walks.label[i]);
      RC_ASSERT(*(h + 1 == last ? first : h + 1) == sharpest_left(g, emitted, *h, walks.label[i]));
      revisits = revisits || !origins.insert(g.origin(*h)).second;
    }
    RC_ASSERT(static_cast<bool>(walks.revisits[i]) == revisits);
    any_revisit = any_revisit || revisits;
    // Split into loops leaving each vertex once, together the walk's half-edges.
    const auto loops = detail::split_at_repeated_vertices(g, first, last, position);
    RC_ASSERT(
        std::all_of(position.begin(), position.end(), [](std::int32_t p) { return p == -1; }));
    std::vector<std::uint32_t> together;
    for (const auto& loop : loops) {
      RC_ASSERT(closed_chain(g, loop.data(), loop.data() + loop.size()));
      std::set<std::uint32_t> loop_origins;
      for (std::uint32_t h : loop) RC_ASSERT(loop_origins.insert(g.origin(h)).second);
      together.insert(together.end(), loop.begin(), loop.end());
    }
    std::vector<std::uint32_t> walk(first, last);
    if (!revisits) RC_ASSERT(loops.size() == 1u && loops.front() == walk);
    if (revisits) RC_ASSERT(loops.size() >= 2u);
    std::sort(together.begin(), together.end());
    std::sort(walk.begin(), walk.end());
    RC_ASSERT(together == walk);
  }
  RC_TAG(any_revisit ? "a walk revisits a vertex" : "no walk revisits a vertex");
}

// ---- hand cases --------------------------------------------------------------------------

const Ring kBig{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
const Ring kSmall{{3, 3}, {7, 3}, {7, 7}, {3, 7}};

Assembled assembled(const stages::Arrangement& a, ClipOp op) {
  std::vector<SideState> left;
  EXPECT_TRUE(detail::label_sides(a.graph, LabelMode::kOwner, left));
  return detail::assemble(a.graph, left, LabelOf::operation(op), true);
}

std::set<Point64> points_of(const Ring& r) { return {r.begin(), r.end()}; }

TEST(Assembly, SquareWithASquareCutOutIsARegionWithAHole) {
  // [3, 7]^2 inside [0, 10]^2, nothing touching: subject minus clip has one outer ring and one
  // hole, in `holed`; nothing else is in the result.
  const stages::Arrangement a({kBig}, {kSmall}, true);
  const Assembled diff = assembled(a, ClipOp::kDifference);
  EXPECT_TRUE(diff.rings.empty());
  ASSERT_EQ(diff.holed.size(), 1u);
  EXPECT_EQ(diff.holed[0].label, detail::family(0, 0));
  ASSERT_EQ(diff.holed[0].outers.size(), 1u);
  ASSERT_EQ(diff.holed[0].holes.size(), 1u);
  EXPECT_EQ(twice_signed_area(diff.holed[0].outers[0]), Int128(200));
  EXPECT_EQ(twice_signed_area(diff.holed[0].holes[0]), Int128(-32));
  EXPECT_EQ(points_of(diff.holed[0].outers[0]), points_of(kBig));
  EXPECT_EQ(points_of(diff.holed[0].holes[0]), points_of(kSmall));
  // Xor: the clip square lies inside both operands, so the same holed region and nothing else.
  const Assembled x = assembled(a, ClipOp::kXor);
  ASSERT_EQ(x.holed.size(), 1u);
  EXPECT_EQ(x.holed[0].label, detail::family(0, 0));
  EXPECT_TRUE(x.rings.empty());
  // With the operands swapped, xor keeps the big square's polygon (now clip polygon 0) round
  // the hole.
  const stages::Arrangement swapped({kSmall}, {kBig}, true);
  const Assembled y = assembled(swapped, ClipOp::kXor);
  ASSERT_EQ(y.holed.size(), 1u);
  EXPECT_EQ(y.holed[0].label, detail::family(1, 0));
  EXPECT_TRUE(y.rings.empty());
  // Intersection: the small square; union: the big one (a subject polygon keeps its face).
  const Assembled both = assembled(a, ClipOp::kIntersection);
  EXPECT_TRUE(both.holed.empty());
  EXPECT_EQ(both.rings, std::vector<Ring>{kSmall});
  const Assembled either = assembled(a, ClipOp::kUnion);
  EXPECT_TRUE(either.holed.empty());
  EXPECT_EQ(either.rings, std::vector<Ring>{kBig});
  EXPECT_EQ(either.labels, std::vector<FaceLabel>{detail::family(0, 0)});
}

TEST(Assembly, HoleTouchingTheOuterRingIsSplitOffItsWalk) {
  // [0, 4]^2 minus the triangle (0, 2), (2, 1), (2, 3) whose corner lies on the left side: the
  // boundary is one walk through (0, 2) twice (down the left side, round the triangle
  // clockwise, on down), split there into the square (twice area 32) and the hole (-4).
  const stages::Arrangement a({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, {{{0, 2}, {2, 1}, {2, 3}}}, true);
  std::vector<SideState> left;
  ASSERT_TRUE(detail::label_sides(a.graph, LabelMode::kOwner, left));
  const LabelOf difference = LabelOf::operation(ClipOp::kDifference);
  const std::vector<FaceLabel> emitted = emitted_of(a.graph, left, difference);
  const detail::BoundaryWalks walks = detail::trace_boundaries(a.graph, emitted);
  ASSERT_EQ(walks.size(), 1u);
  EXPECT_TRUE(walks.revisits[0]);
  std::vector<std::int32_t> position(a.graph.vertices.size(), -1);
  const auto loops =
      detail::split_at_repeated_vertices(a.graph, walks.first(0), walks.last(0), position);
  ASSERT_EQ(loops.size(), 2u);
  std::multiset<Int128> areas;
  for (const auto& loop : loops)
    areas.insert(
        twice_signed_area(detail::ring_along(a.graph, loop.data(), loop.data() + loop.size())));
  EXPECT_EQ(areas, (std::multiset<Int128>{-4, 32}));
  const Assembled out = detail::assemble(a.graph, left, difference, true);
  EXPECT_TRUE(out.rings.empty());
  ASSERT_EQ(out.holed.size(), 1u);
  ASSERT_EQ(out.holed[0].outers.size(), 1u);
  ASSERT_EQ(out.holed[0].holes.size(), 1u);
  EXPECT_EQ(twice_signed_area(out.holed[0].outers[0]), Int128(32));
  EXPECT_EQ(twice_signed_area(out.holed[0].holes[0]), Int128(-4));
}

TEST(Assembly, RegionsTouchingAtAVertexAreSeparateWalks) {
  // [0, 4]^2 minus two triangles meeting at its centre leaves two triangles of the one subject
  // polygon that touch at (2, 2): the sharpest left turn keeps them apart.
  const stages::Arrangement a({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
                              {{{0, 0}, {4, 0}, {2, 2}}, {{2, 2}, {4, 4}, {0, 4}}}, true);
  const Assembled out = assembled(a, ClipOp::kDifference);
  EXPECT_TRUE(out.holed.empty());
  std::vector<Ring> rings = out.rings;
  std::sort(rings.begin(), rings.end());
  EXPECT_EQ(rings, (std::vector<Ring>{{{0, 0}, {2, 2}, {0, 4}}, {{2, 2}, {4, 0}, {4, 4}}}));
}

}  // namespace
}  // namespace edgeland::test
