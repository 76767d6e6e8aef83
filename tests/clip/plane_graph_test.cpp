// The plane graph (clip/src/plane_graph.hpp): build_plane_graph on real snapped fragments
// (crowded random rings, stacks of collinear edges merged as normalize merges them, and hand
// cases), checked against its contract by brute force:
//  * vertices are sorted and unique: every end of a touched segment's fragment, and otherwise
//    only ends of chains (fragment ends with an edge);
//  * the edges' polylines, cut into lattice unit steps, carry exactly the net multiplicity per
//    (channel, polygon) that the fragments carry (weights counted, directions signed), and no two
//    pieces of polylines cross, overlap or touch except at graph vertices (or consecutively
//    within one chain);
//  * each edge's multiplicities are nonzero and ordered by (channel, polygon); no chain has an
//    interior point below both its ends, or at a vertex;
//  * around[] lists each vertex's half-edges counter-clockwise from angle 0 (an independent angle
//    comparison), turn_at[h] is the position of the half-edge clockwise from h's twin, and the
//    faces it traces satisfy Euler's formula per component (a planar rotation system);
//  * cancelled_edges counts the groups of coinciding touched fragments whose nets all sum to 0.
#include "plane_graph.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "collinear_merge.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "stage_inputs.hpp"

namespace edgeland::test {
namespace {

using detail::EdgeList;
using detail::PlaneGraph;
using stages::UnitStep;

using Tag = std::pair<std::uint8_t, std::int32_t>;  // (channel, polygon)
using StepNets = std::map<UnitStep, std::map<Tag, std::int64_t>>;

using stages::ccw_before;
using stages::str;

void add_steps(StepNets& nets, Point64 a, Point64 b, Tag tag, std::int64_t net) {
  stages::for_each_unit_step(a, b, [&](Point64 p, Point64 q) {
    nets[stages::undirected(p, q)][tag] += net * stages::step_sign(p, q);
  });
}

void drop_zeros(StepNets& nets) {
  for (auto it = nets.begin(); it != nets.end();) {
    std::erase_if(it->second, [](const auto& kv) { return kv.second == 0; });
    it = it->second.empty() ? nets.erase(it) : std::next(it);
  }
}

// The points of edge e from `from` to `to`.
std::vector<Point64> polyline(const PlaneGraph& g, std::uint32_t e) {
  std::vector<Point64> pts;
  g.append_points(2 * e, pts);
  pts.push_back(g.vertices[g.to(e)]);
  return pts;
}

// The first violation of the contract, or "".
std::string graph_problems(const EdgeList& edges, const std::vector<detail::Fragment>& listed,
                           const std::vector<std::uint8_t>& touched, const PlaneGraph& g) {
  const auto frags = stages::fragments_by_segment(edges, listed);
  const std::size_t nv = g.vertices.size(), ne = g.edge_count();
  // Vertices: sorted, unique.
  for (std::size_t v = 1; v < nv; ++v)
    if (!(g.vertices[v - 1] < g.vertices[v]))
      return "vertices not sorted and unique at " + str(g.vertices[v]);
  auto is_vertex = [&](Point64 p) {
    return std::binary_search(g.vertices.begin(), g.vertices.end(), p);
  };
  if (g.origin_of.size() != 2 * ne || g.mult_begin.size() != ne + 1 || g.chain.size() != ne ||
      g.around_begin.size() != nv + 1 || g.around.size() != 2 * ne || g.turn_at.size() != 2 * ne)
    return "array sizes disagree";
  std::vector<std::uint32_t> degree(nv, 0);
  for (std::uint32_t e = 0; e < ne; ++e) {
    if (!(g.from(e) < g.to(e)) || g.to(e) >= nv)
      return "edge " + std::to_string(e) + " not from < to";
    ++degree[g.from(e)];
    ++degree[g.to(e)];
  }
  // Vertices are fragment ends: all ends of touched segments' fragments, and otherwise only
  // chain ends.
  std::set<Point64> touched_ends, all_ends;
  for (std::uint32_t s = 0; s < edges.size(); ++s)
    for (const Segment& f : frags[s]) {
      all_ends.insert(f.a);
      all_ends.insert(f.b);
      if (touched[s]) {
        touched_ends.insert(f.a);
        touched_ends.insert(f.b);
      }
    }
  for (Point64 p : touched_ends)
    if (!is_vertex(p)) return "fragment end " + str(p) + " of a touched segment is no vertex";
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (!all_ends.count(g.vertices[v]))
      return "vertex " + str(g.vertices[v]) + " is no fragment end";
    if (!touched_ends.count(g.vertices[v]) && degree[v] == 0)
      return "vertex " + str(g.vertices[v]) + " is neither a touched fragment's end nor a chain's";
  }
  // Multiplicities: nonzero, strictly ordered by (channel, polygon) within an edge.
  if (g.mult_begin[0] != 0 || g.mult_begin[ne] != g.mults.size()) return "mult_begin bounds";
  for (std::uint32_t e = 0; e < ne; ++e) {
    if (g.mult_begin[e] >= g.mult_begin[e + 1]) return "edge without multiplicity";
    for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k) {
      if (g.mults[k].net == 0) return "zero multiplicity";
      if (k > g.mult_begin[e] && !(Tag{g.mults[k - 1].channel, g.mults[k - 1].polygon} <
                                   Tag{g.mults[k].channel, g.mults[k].polygon}))
        return "multiplicities not ordered by (channel, polygon)";
    }
  }
  // Chains: interior points are no vertices and not below both ends.
  for (std::uint32_t e = 0; e < ne; ++e) {
    const std::vector<Point64> pts = polyline(g, e);
    if (pts.size() != g.interior_count(e) + 2) return "append_points length";
    for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
      if (is_vertex(pts[i])) return "chain interior point " + str(pts[i]) + " is a vertex";
      if (pts[i] < pts.front() && pts[i] < pts.back())
        return "chain interior point " + str(pts[i]) + " below both ends";
      if (pts[i] != g.interior_point(e, static_cast<std::uint32_t>(i - 1))) return "interior_point";
    }
    // The points of the twin are the same, backwards.
    std::vector<Point64> back;
    g.append_points(2 * e + 1, back);
    back.push_back(g.vertices[g.from(e)]);
    std::reverse(back.begin(), back.end());
    if (back != pts) return "append_points of the twin is not the reverse";
  }
  // Unit steps: the graph carries the fragments' nets.
  StepNets want, got;
  for (std::uint32_t s = 0; s < edges.size(); ++s)
    for (const Segment& f : frags[s])
      add_steps(want, f.a, f.b, {edges.channel[s], edges.polygon[s]}, edges.weight_of(s));
  for (std::uint32_t e = 0; e < ne; ++e) {
    const std::vector<Point64> pts = polyline(g, e);
    for (std::uint32_t k = g.mult_begin[e]; k < g.mult_begin[e + 1]; ++k)
      for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        add_steps(got, pts[i], pts[i + 1], {g.mults[k].channel, g.mults[k].polygon},
                  g.mults[k].net);
  }
  drop_zeros(want);
  drop_zeros(got);
  if (want != got) return "the unit steps of the edges do not carry the fragments' nets";
  // Plane: pieces of polylines meet only at common ends that are vertices, or consecutively.
  struct Piece {
    Segment seg;
    std::uint32_t edge, index;
  };
  std::vector<Piece> pieces;
  for (std::uint32_t e = 0; e < ne; ++e) {
    const std::vector<Point64> pts = polyline(g, e);
    for (std::uint32_t i = 0; i + 1 < pts.size(); ++i)
      pieces.push_back({{pts[i], pts[i + 1]}, e, i});
  }
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = i + 1; j < pieces.size(); ++j) {
      const Segment &s = pieces[i].seg, &t = pieces[j].seg;
      if (std::max(s.a.x, s.b.x) < std::min(t.a.x, t.b.x) ||
          std::max(t.a.x, t.b.x) < std::min(s.a.x, s.b.x) ||
          std::max(s.a.y, s.b.y) < std::min(t.a.y, t.b.y) ||
          std::max(t.a.y, t.b.y) < std::min(s.a.y, s.b.y))
        continue;
      const SegmentIntersection r = intersect(s, t);
      if (r.relation == SegmentRelation::kDisjoint) continue;
      const Point64 p = round_to_grid(r.point);
      const bool common_end = r.relation == SegmentRelation::kTouching && (p == s.a || p == s.b) &&
                              (p == t.a || p == t.b);
      const bool consecutive =
          pieces[i].edge == pieces[j].edge && pieces[i].index + 1 == pieces[j].index;
      if (!common_end || !(is_vertex(p) || consecutive))
        return "polylines of the graph meet away from a vertex near " + str(s.a) + "-" + str(s.b) +
               " and " + str(t.a) + "-" + str(t.b);
    }
  // around: each vertex's half-edges, counter-clockwise from angle 0.
  if (g.around_begin[0] != 0 || g.around_begin[nv] != 2 * ne) return "around_begin bounds";
  std::vector<std::uint32_t> position(2 * ne, 0xffffffffu);
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (g.around_begin[v + 1] - g.around_begin[v] != degree[v]) return "around_begin counts";
    for (std::uint32_t k = g.around_begin[v]; k < g.around_begin[v + 1]; ++k) {
      const std::uint32_t h = g.around[k];
      if (h >= 2 * ne || g.origin(h) != v || position[h] != 0xffffffffu)
        return "around[] is not a listing by origin";
      position[h] = k;
      if (k > g.around_begin[v]) {
        const Point64 o = g.vertices[v], p1 = g.first_step(g.around[k - 1]), p2 = g.first_step(h);
        if (!ccw_before({p1.x - o.x, p1.y - o.y}, {p2.x - o.x, p2.y - o.y}))
          return "half-edges round " + str(o) + " not counter-clockwise from angle 0";
      }
    }
  }
  // turn_at: the position, at h's target, of the half-edge before h's twin.
  for (std::uint32_t h = 0; h < 2 * ne; ++h) {
    const std::uint32_t w = g.target(h), b = g.around_begin[w], e = g.around_begin[w + 1];
    const std::uint32_t twin_at = position[h ^ 1];
    if (g.turn_at[h] != (twin_at == b ? e - 1 : twin_at - 1)) return "turn_at";
  }
  // Euler's formula per component: V - E + F = 2 with F the face cycles h -> around[turn_at[h]].
  std::vector<std::uint32_t> parent(nv);
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::uint32_t e = 0; e < ne; ++e) parent[root(g.from(e))] = root(g.to(e));
  std::size_t used_vertices = 0, components = 0, cycles = 0;
  for (std::uint32_t v = 0; v < nv; ++v)
    if (degree[v] > 0) {
      ++used_vertices;
      if (root(v) == v) ++components;
    }
  std::vector<std::uint8_t> seen(2 * ne, 0);
  for (std::uint32_t h = 0; h < 2 * ne; ++h) {
    if (seen[h]) continue;
    ++cycles;
    for (std::uint32_t x = h; !seen[x]; x = g.around[g.turn_at[x]]) seen[x] = 1;
  }
  if (used_vertices + cycles != ne + 2 * components)
    return "Euler's formula fails: not a planar rotation";
  // cancelled_edges: groups of coinciding touched fragments whose nets all sum to 0.
  std::map<std::pair<Point64, Point64>, std::map<Tag, std::int64_t>> groups;
  for (std::uint32_t s = 0; s < edges.size(); ++s) {
    if (!touched[s]) continue;
    for (const Segment& f : frags[s]) {
      const bool up = f.a < f.b;
      groups[up ? std::pair{f.a, f.b} : std::pair{f.b, f.a}]
            [{edges.channel[s], edges.polygon[s]}] += up ? edges.weight_of(s) : -edges.weight_of(s);
    }
  }
  std::size_t cancelled = 0;
  for (const auto& [ends, nets] : groups)
    if (std::all_of(nets.begin(), nets.end(), [](const auto& kv) { return kv.second == 0; }))
      ++cancelled;
  if (g.cancelled_edges != cancelled)
    return "cancelled_edges " + std::to_string(g.cancelled_edges) + ", expected " +
           std::to_string(cancelled);
  return "";
}

std::string problems(const stages::Arrangement& a) {
  return graph_problems(a.edges, a.fragments, a.touched, a.graph);
}

RC_GTEST_PROP(PlaneGraph, IsThePlaneArrangementOfTheFragments, ()) {
  const stages::Arrangement a(*stages::crowded_rings(4, 20), *stages::crowded_rings(3, 20), false);
  RC_TAG(a.graph.cancelled_edges > 0 ? "cancelled edges" : "nothing cancelled");
  RC_TAG(std::count(a.touched.begin(), a.touched.end(), 0) > 0 ? "chains" : "no chains");
  RC_ASSERT(problems(a) == std::string());
}

// Normalize's path for stacks of collinear edges (pipeline.cpp): merged into weighted intervals
// (weights possibly 0, rings cut into open runs) and noded again; segments next to a merged
// stretch are touched.
RC_GTEST_PROP(PlaneGraph, IsThePlaneArrangementOfMergedStacks, ()) {
  std::vector<Ring> rings;
  const int copies = stages::uniform_int(2, 5);
  for (int k = 0; k < copies; ++k) {
    const std::int64_t x = stages::uniform(0, 2), w = stages::uniform(1, 3);
    Ring r{{x, 0}, {x + w, 0}, {x + w, 3}, {x, 3}};
    if ((stages::uniform(0, 1) == 1)) std::reverse(r.begin(), r.end());
    rings.push_back(r);
  }
  for (const Ring& r : *stages::crowded_rings(2, 8)) rings.push_back(r);
  detail::EdgeList input;
  detail::append_ring_edges(rings, detail::kSubjectChannel, false, input);
  const detail::MergedEdges merged = detail::merge_collinear_overlaps(input);
  detail::SegmentSearch search(merged.edges.segments, merged.edges.next);
  detail::Contacts contacts =
      detail::find_contacts(merged.edges.segments, merged.edges.next, search, {});
  detail::Snapped snapped =
      detail::snap_round(merged.edges.segments, merged.edges.next, contacts, search);
  for (std::size_t s = 0; s < merged.edges.size(); ++s)
    if (merged.unchained[s]) snapped.touched[s] = true;
  PlaneGraph g;
  detail::build_plane_graph(merged.edges, snapped.fragments, snapped.touched, g);
  RC_ASSERT(graph_problems(merged.edges, snapped.fragments, snapped.touched, g) == std::string());
}

// ---- hand cases --------------------------------------------------------------------------

std::vector<Point64> vertices_of(const PlaneGraph& g) { return g.vertices; }

TEST(PlaneGraph, TwoOverlappingSquares) {
  // [0, 4]^2 and [2, 6]^2 cross at (4, 2) and (2, 4). The subject's left and bottom sides meet
  // nothing: chained, and cut at (0, 0), the chain's least point; the clip's right and top
  // sides are one chain from (6, 2) round (6, 6) to (2, 6).
  const stages::Arrangement a({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
                              {{{2, 2}, {6, 2}, {6, 6}, {2, 6}}}, true);
  EXPECT_EQ(problems(a), "");
  EXPECT_EQ(vertices_of(a.graph),
            (std::vector<Point64>{
                {0, 0}, {0, 4}, {2, 2}, {2, 4}, {2, 6}, {4, 0}, {4, 2}, {4, 4}, {6, 2}}));
  // Edges: (0,4)-(0,0), (0,0)-(4,0), (4,0)-(4,2), (4,2)-(4,4), (4,4)-(2,4), (2,4)-(0,4),
  // (2,6)-(2,4), (2,4)-(2,2), (2,2)-(4,2), (4,2)-(6,2), (6,2)-(6,6)-(2,6).
  EXPECT_EQ(a.graph.edge_count(), 11u);
  EXPECT_EQ(a.graph.cancelled_edges, 0u);
  // The vertex (4, 2): east (to (6, 2)), north, west, south.
  const auto v = static_cast<std::uint32_t>(6);
  ASSERT_EQ(a.graph.vertices[v], (Point64{4, 2}));
  std::vector<Point64> round;
  for (std::uint32_t k = a.graph.around_begin[v]; k < a.graph.around_begin[v + 1]; ++k)
    round.push_back(a.graph.first_step(a.graph.around[k]));
  EXPECT_EQ(round, (std::vector<Point64>{{6, 2}, {4, 4}, {2, 2}, {4, 0}}));
}

TEST(PlaneGraph, SpikeFoldedBackCancelsAndLeavesItsTipAlone) {
  // A square with a spike from (4, 4) to (6, 6) and back: the two spike edges cancel, (6, 6)
  // stays a vertex with no edge; the untouched left and bottom sides are one gap of the ring,
  // cut at its least point (0, 0).
  const stages::Arrangement a({{{0, 0}, {4, 0}, {4, 4}, {6, 6}, {4, 4}, {0, 4}}}, {}, false);
  EXPECT_EQ(problems(a), "");
  EXPECT_EQ(vertices_of(a.graph), (std::vector<Point64>{{0, 0}, {0, 4}, {4, 0}, {4, 4}, {6, 6}}));
  EXPECT_EQ(a.graph.cancelled_edges, 1u);
  EXPECT_EQ(a.graph.edge_count(), 4u);
  EXPECT_EQ(a.graph.around_begin[5] - a.graph.around_begin[4], 0u);  // (6, 6): no half-edge
}

TEST(PlaneGraph, RingNothingTouchesIsTwoChains) {
  // Cut at its smallest vertex (0, 0) and halfway round (4, 4): two edges between the same
  // two vertices, one through (4, 0), the other through (0, 4).
  const stages::Arrangement a({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, {}, true);
  EXPECT_EQ(problems(a), "");
  EXPECT_EQ(vertices_of(a.graph), (std::vector<Point64>{{0, 0}, {4, 4}}));
  ASSERT_EQ(a.graph.edge_count(), 2u);
  std::set<Point64> middles;
  for (std::uint32_t e = 0; e < 2; ++e) {
    ASSERT_EQ(a.graph.interior_count(e), 1u);
    middles.insert(a.graph.interior_point(e, 0));
  }
  EXPECT_EQ(middles, (std::set<Point64>{{4, 0}, {0, 4}}));
}

TEST(PlaneGraph, SegmentsAndTheirReversesCancel) {
  // One ring round the square and back: each side once each way, one tag: every edge cancels,
  // the corners stay.
  const stages::Arrangement a({{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {0, 4}, {4, 4}, {4, 0}}},
                              {}, false);
  EXPECT_EQ(problems(a), "");
  EXPECT_EQ(a.graph.edge_count(), 0u);
  EXPECT_EQ(a.graph.cancelled_edges, 4u);
  EXPECT_EQ(vertices_of(a.graph), (std::vector<Point64>{{0, 0}, {0, 4}, {4, 0}, {4, 4}}));
  // The square and its reverse as two polygons, or in two operands, do not cancel: each edge
  // carries +1 of one tag and -1 of the other.
  const Ring square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const Ring reversed(square.rbegin(), square.rend());
  for (const auto& [subject, clip] :
       {std::pair<std::vector<Ring>, std::vector<Ring>>{{square, reversed}, {}},
        {{square}, {reversed}}}) {
    const stages::Arrangement b(subject, clip, false);
    EXPECT_EQ(problems(b), "");
    EXPECT_EQ(b.graph.edge_count(), 4u);
    EXPECT_EQ(b.graph.cancelled_edges, 0u);
    EXPECT_EQ(b.graph.mults.size(), 8u);
  }
}

}  // namespace
}  // namespace edgeland::test
