// The stage checkers (clip/src/stage_checks.hpp) reject each broken rule: every test corrupts
// one field of a valid stage output (or builds a minimal broken one) and expects the checker to
// throw a std::logic_error whose text starts "<stage>: <rule>:". The valid outputs come from
// the real stages (tests/support/stage_outputs.hpp); stage_checks_real_outputs_test.cpp shows the
// checkers accept them.
#include "stage_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgeland/kernel/assert.hpp"
#include "pipeline.hpp"
#include "stage_outputs.hpp"

namespace edgeland::detail {
namespace {

Polygon box(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// `call` must throw std::logic_error with text starting with `prefix` ("<stage>: <rule>:").
template <class F>
void expect_failure(F&& call, const std::string& prefix) {
  try {
    call();
  } catch (const std::logic_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u)
        << "expected \"" << prefix << "...\", got: " << e.what();
    return;
  }
  ADD_FAILURE() << "no failure; expected \"" << prefix << "...\"";
}

// Two overlapping squares (cut at integer points: listed fragments) and a square far away that
// nothing touches (its segments are chained).
std::unique_ptr<StageOutputs> squares(ClipOp op = ClipOp::kUnion) {
  auto s = clip_stages({box(0, 0, 10, 10), box(100, 100, 110, 110)}, {box(5, 5, 15, 15)}, op);
  EXPECT_EQ(s->fragments.size(), 8u);  // four edges cut once each
  return s;
}

// ---- how a failure reaches the caller ----------------------------------------------------

TEST(StageCheckAssert, GuardedTurnsAStageFailureIntoAnInternalError) {
  // What run() does with a checker's (or an assert's) std::logic_error: InternalError, with
  // the operation, the stage and the rule in its text and the inputs as WKT.
  auto failing = [] {
    fail_stage("plane graph", "angle order: vertex 3");
    return ClipResult{};
  };
  try {
    guarded(
        failing, ClipOptions{}, "union", [] { return std::string("A"); },
        [] { return std::string("B"); });
    ADD_FAILURE() << "no InternalError";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find(": union: plane graph: angle order: vertex 3 ("),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.subject_wkt, "A");
    EXPECT_EQ(e.clip_wkt, "B");
  }
}

// ---- snap rounding ----------------------------------------------------------------------

void check_fragments_of(const StageOutputs& s) { check_fragments(s.edges, s.fragments, s.touched); }

// Segments as one-segment rings of their own (next[s] == s), every one touched: only the rules
// between fragments apply.
EdgeList lone_segments(const std::vector<Segment>& segments) {
  EdgeList e;
  for (std::uint32_t i = 0; i < segments.size(); ++i) {
    e.segments.push_back(segments[i]);
    e.channel.push_back(0);
    e.polygon.push_back(0);
    e.next.push_back(i);
  }
  return e;
}

void expect_lone_segments_fail(const std::vector<Segment>& segments, const std::string& prefix) {
  const EdgeList e = lone_segments(segments);
  const std::vector<std::uint8_t> touched(segments.size(), 1);
  expect_failure([&] { check_fragments(e, {}, touched); }, prefix);
}

TEST(StageCheckFragments, ZeroLengthFragment) {
  auto s = squares();
  s->fragments[0].seg.b = s->fragments[0].seg.a;
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: zero-length fragment:");
}

TEST(StageCheckFragments, SizesOfTouchedFlags) {
  auto s = squares();
  s->touched.pop_back();
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: sizes:");
}

TEST(StageCheckFragments, ParentOutOfRange) {
  auto s = squares();
  s->fragments.back().parent = 1000;
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: parent out of range:");
}

TEST(StageCheckFragments, FragmentStrayingFromItsSegment) {
  auto s = squares();
  // The cut point moves a unit away from the segment, both fragments still meeting there.
  s->fragments[0].seg.b.x += 1;
  s->fragments[1].seg.a.x += 1;
  ASSERT_EQ(s->fragments[0].seg.a.x, s->fragments[1].seg.b.x);  // a vertical segment
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: strays from its segment:");
}

TEST(StageCheckFragments, ParentOrder) {
  auto s = squares();
  std::swap(s->fragments[0], s->fragments[2]);  // two fragments per cut segment
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: parent order:");
}

TEST(StageCheckFragments, FragmentNotStartingWhereThePreviousEnds) {
  auto s = squares();
  s->fragments[1].seg.a.y += 1;  // along its vertical segment (10 0)-(10 10)
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: end to end:");
}

TEST(StageCheckFragments, LastFragmentNotEndingAtItsSegmentsEnd) {
  auto s = squares();
  s->fragments[1].seg.b.y -= 1;  // along its vertical segment (10 0)-(10 10)
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: end to end:");
}

TEST(StageCheckFragments, ListedButUntouched) {
  auto s = squares();
  s->touched[s->fragments[0].parent] = 0;
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: listed but untouched:");
}

TEST(StageCheckFragments, UntouchedSegmentNotEndingWhereItsSuccessorStarts) {
  auto s = squares();
  const std::size_t far = 5;  // the far square is subject ring 1: segments 4 to 7
  ASSERT_EQ(s->edges.segments[far].a, (Point64{110, 100}));
  ASSERT_FALSE(s->touched[far]);
  s->edges.next[far] = 0;
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: untouched end:");
}

TEST(StageCheckFragments, UncutSegmentsCrossing) {
  auto s = squares();
  s->fragments.clear();  // the squares' edges now cross at (10 5) and (5 10)
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: crossing:");
}

TEST(StageCheckFragments, FragmentEndInsideAnother) {
  auto s = squares();
  // Join the first cut segment's two fragments again: the other square's fragments end on it.
  s->fragments[0].seg.b = s->fragments[1].seg.b;
  s->fragments.erase(s->fragments.begin() + 1);
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: endpoint inside:");
}

TEST(StageCheckFragments, CrossingOfLoneSegments) {
  expect_lone_segments_fail({{{0, 0}, {4, 3}}, {{0, 3}, {4, 0}}}, "snap rounding: crossing:");
}

TEST(StageCheckFragments, EndpointInsideOfLoneSegments) {
  expect_lone_segments_fail({{{0, 0}, {4, 0}}, {{2, 0}, {2, 5}}},
                            "snap rounding: endpoint inside:");
}

TEST(StageCheckFragments, PartialOverlapWithoutCommonEnd) {
  expect_lone_segments_fail({{{0, 0}, {10, 0}}, {{15, 0}, {5, 0}}},
                            "snap rounding: partial overlap:");
}

TEST(StageCheckFragments, PartialOverlapFromACommonEnd) {
  expect_lone_segments_fail({{{0, 0}, {10, 10}}, {{5, 5}, {0, 0}}},
                            "snap rounding: partial overlap:");
}

TEST(StageCheckFragments, SameSegmentTwiceAndCommonEndsPass) {
  const EdgeList e =
      lone_segments({{{0, 0}, {10, 0}}, {{10, 0}, {0, 0}}, {{10, 0}, {10, 5}}, {{0, 0}, {10, 0}}});
  EXPECT_NO_THROW(check_fragments(e, {}, std::vector<std::uint8_t>(4, 1)));
}

TEST(StageCheckFragments, UntouchedSegmentMeetingAnotherRing) {
  // Two triangles sharing the vertex (10 0): noding touches the four segments that end there.
  auto s = std::make_unique<StageOutputs>();
  append_ring_edges({{{0, 0}, {10, 0}, {0, 10}}, {{10, 0}, {20, 0}, {15, 5}}}, 0, true, s->edges);
  snap_stage(*s, true, std::numeric_limits<std::size_t>::max());
  EXPECT_NO_THROW(check_fragments_of(*s));
  std::fill(s->touched.begin(), s->touched.end(), 0);
  expect_failure([&] { check_fragments_of(*s); }, "snap rounding: untouched contact:");
}

TEST(StageCheckFragments, UntouchedSegmentCoincidingWithAnother) {
  EdgeList e = lone_segments({{{0, 0}, {10, 0}}, {{10, 0}, {0, 0}}});
  e.next = {1, 0};  // one ring: a spike folded back onto itself
  EXPECT_NO_THROW(check_fragments(e, {}, {1, 1}));
  expect_failure([&] { check_fragments(e, {}, {1, 0}); }, "snap rounding: untouched contact:");
}

// ---- plane graph ------------------------------------------------------------------------

// The first edge with at least `count` multiplicities (or with a chain when count is 0).
std::uint32_t edge_with(const PlaneGraph& g, std::uint32_t mults, bool chain) {
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    if (g.mult_begin[e + 1] - g.mult_begin[e] >= mults && (!chain || g.chain[e].count > 0))
      return e;
  ADD_FAILURE() << "no such edge";
  return 0;
}

void expect_graph_failure(const StageOutputs& s, const std::string& rule) {
  expect_failure([&] { check_plane_graph(s.graph); }, "plane graph: " + rule + ":");
}

TEST(StageCheckPlaneGraph, OddOriginSize) {
  auto s = squares();
  s->graph.origin_of.push_back(0);
  expect_graph_failure(*s, "sizes");
}

TEST(StageCheckPlaneGraph, TurnAtSize) {
  auto s = squares();
  s->graph.turn_at.pop_back();
  expect_graph_failure(*s, "sizes");
}

TEST(StageCheckPlaneGraph, VerticesNotSorted) {
  auto s = squares();
  std::swap(s->graph.vertices[0], s->graph.vertices[1]);
  expect_graph_failure(*s, "vertex order");
}

TEST(StageCheckPlaneGraph, VertexTwice) {
  auto s = squares();
  s->graph.vertices[1] = s->graph.vertices[0];
  expect_graph_failure(*s, "vertex order");
}

TEST(StageCheckPlaneGraph, EdgeRunningDownwards) {
  auto s = squares();
  std::swap(s->graph.origin_of[0], s->graph.origin_of[1]);
  expect_graph_failure(*s, "edge ends");
}

TEST(StageCheckPlaneGraph, EdgeEndOutOfRange) {
  auto s = squares();
  s->graph.origin_of[1] = static_cast<std::uint32_t>(s->graph.vertices.size());
  expect_graph_failure(*s, "edge ends");
}

TEST(StageCheckPlaneGraph, MultiplicityCsrEnd) {
  auto s = squares();
  s->graph.mult_begin.back() += 1;
  expect_graph_failure(*s, "multiplicity CSR");
}

TEST(StageCheckPlaneGraph, MultiplicityCsrDecreasing) {
  auto s = squares();
  s->graph.mult_begin[1] = s->graph.mult_begin[2] + 1;
  expect_graph_failure(*s, "multiplicity CSR");
}

TEST(StageCheckPlaneGraph, NetZero) {
  auto s = squares();
  s->graph.mults[0].net = 0;
  expect_graph_failure(*s, "multiplicity");
}

TEST(StageCheckPlaneGraph, ChannelOutOfRange) {
  auto s = squares();
  s->graph.mults[0].channel = 2;
  expect_graph_failure(*s, "multiplicity");
}

TEST(StageCheckPlaneGraph, NegativePolygon) {
  auto s = squares();
  s->graph.mults[0].polygon = -1;
  expect_graph_failure(*s, "multiplicity");
}

TEST(StageCheckPlaneGraph, MultiplicitiesOutOfOrder) {
  // A shared edge carries one multiplicity per operand.
  auto s = clip_stages({box(0, 0, 10, 10)}, {box(10, 0, 20, 10)}, ClipOp::kUnion);
  const std::uint32_t e = edge_with(s->graph, 2, false);
  std::swap(s->graph.mults[s->graph.mult_begin[e]], s->graph.mults[s->graph.mult_begin[e] + 1]);
  expect_graph_failure(*s, "multiplicity");
}

TEST(StageCheckPlaneGraph, ChainOutsideItsRing) {
  auto s = squares();
  PlaneGraph::Chain& c = s->graph.chain[edge_with(s->graph, 1, true)];
  c.first = c.ring_begin + c.ring_len;
  expect_graph_failure(*s, "chain record");
}

TEST(StageCheckPlaneGraph, ChainRunningTheWrongWay) {
  auto s = squares();
  PlaneGraph::Chain& c = s->graph.chain[edge_with(s->graph, 1, true)];
  c.reversed = !c.reversed;
  expect_graph_failure(*s, "chain record");
}

TEST(StageCheckPlaneGraph, AroundCsrEnd) {
  auto s = squares();
  s->graph.around_begin.back() -= 1;
  expect_graph_failure(*s, "around CSR");
}

TEST(StageCheckPlaneGraph, HalfEdgeListedTwice) {
  auto s = squares();
  s->graph.around[1] = s->graph.around[0];
  expect_graph_failure(*s, "around");
}

TEST(StageCheckPlaneGraph, HalfEdgeAroundTheWrongVertex) {
  auto s = squares();
  PlaneGraph& g = s->graph;
  std::swap(g.around[g.around_begin[0]], g.around[g.around_begin[1]]);
  expect_graph_failure(*s, "around");
}

TEST(StageCheckPlaneGraph, ZeroFirstStep) {
  auto s = squares();
  PlaneGraph& g = s->graph;
  const PlaneGraph::Chain c = g.chain[edge_with(g, 1, true)];
  // The chain's first interior point moved onto its first point (its segments are read from
  // the edge list).
  s->edges.segments[c.ring_begin + (c.first - c.ring_begin + 1) % c.ring_len].a =
      s->edges.segments[c.first].a;
  expect_graph_failure(*s, "zero first step");
}

TEST(StageCheckPlaneGraph, TwoHalfEdgesLeavingInOneDirection) {
  auto s = squares();
  // The far square (100 100)-(110 110) is two chains cut at (100 100) and (110 110); moving
  // the interior point (100 110) to (105 100) sends both chains east from (100 100).
  for (Segment& seg : s->edges.segments)
    if (seg.a == Point64{100, 110}) seg.a = {105, 100};
  expect_graph_failure(*s, "same direction");
}

TEST(StageCheckPlaneGraph, AngleOrder) {
  auto s = squares();
  PlaneGraph& g = s->graph;
  std::swap(g.around[g.around_begin[0]], g.around[g.around_begin[0] + 1]);
  expect_graph_failure(*s, "angle order");
}

TEST(StageCheckPlaneGraph, TurnAt) {
  auto s = squares();
  PlaneGraph& g = s->graph;
  g.turn_at[0] = g.turn_at[0] == 0 ? 1 : 0;
  expect_graph_failure(*s, "turn_at");
}

// ---- labeling ---------------------------------------------------------------------------

void expect_labels_failure(const StageOutputs& s, const std::string& rule) {
  expect_failure([&] { check_labels(s.graph, s.mode, s.left); }, "labeling: " + rule + ":");
}

// Every half-edge of the face on h's left gets state `to`: faces stay consistent, crossings
// into the face do not.
void relabel_face(StageOutputs& s, std::uint32_t h, SideState to) {
  std::uint32_t cur = h;
  do {
    s.left[cur] = to;
    cur = s.graph.around[s.graph.turn_at[cur]];
  } while (cur != h);
}

// A half-edge with something on its left (inside a polygon, or a nonzero winding).
std::uint32_t inner_half_edge(const StageOutputs& s) {
  for (std::uint32_t h = 0; h < s.left.size(); ++h)
    if (s.left[h] != empty_state(s.mode)) return h;
  ADD_FAILURE() << "no inner face";
  return 0;
}

TEST(StageCheckLabels, Size) {
  auto s = squares();
  s->left.pop_back();
  expect_labels_failure(*s, "size");
}

TEST(StageCheckLabels, OwnerOutOfRange) {
  auto s = squares();
  s->left[0].by_channel[0] = -2;
  expect_labels_failure(*s, "state range");
}

TEST(StageCheckLabels, WindingModeUsingChannelOne) {
  auto s = normalize_stages({box(0, 0, 10, 10)}, FillRule::kNonZero);
  for (SideState& st : s->left) st.by_channel[1] = 1;
  expect_labels_failure(*s, "state range");
}

TEST(StageCheckLabels, FaceWithTwoStates) {
  auto s = squares();
  s->left[inner_half_edge(*s)].by_channel[1] = 7;
  expect_labels_failure(*s, "face");
}

TEST(StageCheckLabels, OwnerNotChangedByItsEdges) {
  auto s = squares();
  relabel_face(*s, inner_half_edge(*s), SideState{{3, -1}});
  expect_labels_failure(*s, "crossing");
}

TEST(StageCheckLabels, WindingNotChangedByItsEdges) {
  auto s = normalize_stages({box(0, 0, 10, 10), box(5, 5, 15, 15)}, FillRule::kNonZero);
  const std::uint32_t h = inner_half_edge(*s);
  SideState wrong = s->left[h];
  wrong.by_channel[0] += 2;
  relabel_face(*s, h, wrong);
  expect_labels_failure(*s, "crossing");
}

TEST(StageCheckLabels, CountNotChangedByItsEdges) {
  auto s = std::make_unique<StageOutputs>();
  append_ring_edges({box(0, 0, 10, 10)}, 0, true, s->edges);
  append_ring_edges({box(5, 5, 15, 15)}, 1, true, s->edges);
  later_stages(*s, LabelMode::kOwnerAndCount, LabelOf::operation(ClipOp::kIntersection), true);
  EXPECT_NO_THROW(check_labels(s->graph, s->mode, s->left));
  std::uint32_t h = 0;
  while (s->left[h].by_channel[1] != 1) ++h;  // inside the channel 1 square
  SideState wrong = s->left[h];
  wrong.by_channel[1] = 2;
  relabel_face(*s, h, wrong);
  expect_labels_failure(*s, "crossing");
}

TEST(StageCheckLabels, OuterFaceNotEmpty) {
  // Every winding number one more: faces and crossings agree, the unbounded face does not.
  auto s = normalize_stages({box(0, 0, 10, 10), box(5, 5, 15, 15)}, FillRule::kNonZero);
  for (SideState& st : s->left) st.by_channel[0] += 1;
  expect_labels_failure(*s, "outer face");
}

// ---- assembly ---------------------------------------------------------------------------

// Two squares with a hole each (two holed regions) and one without (an output ring).
std::unique_ptr<StageOutputs> holes() {
  auto s = clip_stages({box(0, 0, 10, 10), box(20, 0, 30, 10), box(40, 0, 50, 10)},
                       {box(3, 3, 6, 6), box(23, 3, 26, 6)}, ClipOp::kDifference);
  EXPECT_EQ(s->assembled.rings.size(), 1u);
  EXPECT_EQ(s->assembled.holed.size(), 2u);
  return s;
}

void expect_assembly_failure(const StageOutputs& s, const std::string& rule) {
  expect_failure([&] { check_assembled(s.assembled); }, "assembly: " + rule + ":");
}

TEST(StageCheckAssembly, LabelCount) {
  auto s = holes();
  s->assembled.labels.push_back(0);
  expect_assembly_failure(*s, "labels");
}

TEST(StageCheckAssembly, NegativeLabel) {
  auto s = holes();
  s->assembled.labels[0] = -1;
  expect_assembly_failure(*s, "labels");
}

TEST(StageCheckAssembly, RingOfTwoPoints) {
  auto s = holes();
  s->assembled.rings[0].resize(2);
  expect_assembly_failure(*s, "ring size");
}

TEST(StageCheckAssembly, ClosingPointRepeated) {
  auto s = holes();
  Ring& r = s->assembled.rings[0];
  r.push_back(r.front());
  expect_assembly_failure(*s, "closing point repeated");
}

TEST(StageCheckAssembly, RepeatedConsecutivePoint) {
  auto s = holes();
  Ring& r = s->assembled.rings[0];
  r.insert(r.begin() + 1, r[1]);
  expect_assembly_failure(*s, "repeated consecutive point");
}

TEST(StageCheckAssembly, ClockwiseOutputRing) {
  auto s = holes();
  Ring& r = s->assembled.rings[0];
  std::reverse(r.begin() + 1, r.end());  // still starting at its smallest point
  expect_assembly_failure(*s, "orientation");
}

TEST(StageCheckAssembly, ClockwiseOuterOfAHoledRegion) {
  auto s = holes();
  Ring& r = s->assembled.holed[0].outers[0];
  std::reverse(r.begin(), r.end());
  expect_assembly_failure(*s, "orientation");
}

TEST(StageCheckAssembly, CounterClockwiseHole) {
  auto s = holes();
  Ring& r = s->assembled.holed[1].holes[0];
  std::reverse(r.begin(), r.end());
  expect_assembly_failure(*s, "orientation");
}

TEST(StageCheckAssembly, RingVisitingAPointTwice) {
  auto s = holes();
  // Two triangles touching at (45 5): counter-clockwise, canonical start, no collinear vertex.
  s->assembled.rings[0] = {{40, 0}, {50, 0}, {45, 5}, {50, 10}, {40, 10}, {45, 5}};
  expect_assembly_failure(*s, "repeated point");
}

TEST(StageCheckAssembly, NotStartingAtTheSmallestPoint) {
  auto s = holes();
  Ring& r = s->assembled.rings[0];
  std::rotate(r.begin(), r.begin() + 1, r.end());
  expect_assembly_failure(*s, "canonical");
}

TEST(StageCheckAssembly, CollinearVertex) {
  auto s = holes();
  Ring& r = s->assembled.rings[0];
  r.insert(r.begin() + 1, Point64{(r[0].x + r[1].x) / 2, (r[0].y + r[1].y) / 2});
  ASSERT_EQ(r[0], (Point64{40, 0}));
  expect_assembly_failure(*s, "canonical");
}

TEST(StageCheckAssembly, HoledRegionWithoutHoles) {
  auto s = holes();
  s->assembled.holed[0].holes.clear();
  expect_assembly_failure(*s, "holed region");
}

TEST(StageCheckAssembly, HoledRegionWithNegativeLabel) {
  auto s = holes();
  s->assembled.holed[0].label = -1;
  expect_assembly_failure(*s, "holed region");
}

TEST(StageCheckAssembly, HoledRegionsOutOfOrder) {
  auto s = holes();
  std::swap(s->assembled.holed[0], s->assembled.holed[1]);
  expect_assembly_failure(*s, "holed order");
}

}  // namespace
}  // namespace edgeland::detail
