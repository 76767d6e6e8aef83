#pragma once
// The locality promise of clip.hpp as a test oracle: an input edge farther than 2 units from
// the other operand's boundary appears in the output unchanged, vertex for vertex, or not at
// all. Two readings:
//
//   * kLiteral, the promise as written: a far edge is either covered by one output edge or
//     not overlapped by any output edge at all (never cut short, never partly present);
//   * kOperation, stronger: which of the two is decided by the operation (clip/README.md's
//     table). The edge e (of the subject or the clip set) has, on each side, an owner in its
//     own set (its polygon on the left; on the right the member whose boundary runs back along
//     e, if any) and an owner in the other set (the member containing e's midpoint strictly -
//     e is far from the other boundary, so the whole edge is inside or outside it); the table
//     maps (subject owner, clip owner) to an output label, and e must be in the output iff the
//     labels of its two sides differ. Snap rounding cannot always honour this: a polygon
//     thinner than a pixel whose long edges are routed through one hot pixel may become
//     degenerate far from the crossing (e.g. A = (61 20, 62 21, 40 0) union B = (0 0, 1 0,
//     60 6): all four crossings round to (45 4), and (45 4), (61 20), (62 21) are collinear),
//     so the tests use this reading on inputs without sub-pixel features.
//
// "In the output unchanged" is checked on the canonical output, which removes collinear
// vertices, piece by piece: e is cut at the vertices of its own set that lie on it (where
// another member starts or stops sharing it, or touches it), since the owners of its sides -
// and so whether it bounds the output - can change there; each piece must lie entirely on ONE
// output edge (collinear, the piece within it) or be overlapped by none. Its endpoints are
// not required to stay output vertices one by one: where the exact boundary turns at an
// endpoint, it turns into the ring's next edge, which is then either far too (and checked
// the same way: a missing turn leaves it uncovered) or near (and may be rerouted by snap
// rounding into a straight continuation of e, so that the canonical form removes the corner);
// and an endpoint where e meets a collinear edge of another member may vanish as well.
// "Not at all" means that no output edge overlaps e in a piece of positive length.
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/bbox.hpp"
#include "polygon_set_helpers.hpp"
#include "shape_builders.hpp"

namespace edgeland::test {

namespace locality_detail {

inline bool on_closed_segment(Point64 p, Point64 a, Point64 b) {
  return cross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Collinear with a common piece of positive length.
inline bool overlaps(const Segment& e, const Segment& f) {
  if (cross(e.a, e.b, f.a) != 0 || cross(e.a, e.b, f.b) != 0) return false;
  auto t = [&](Point64 p) {
    return Int128(p.x - e.a.x) * (e.b.x - e.a.x) + Int128(p.y - e.a.y) * (e.b.y - e.a.y);
  };
  const Int128 len = t(e.b), f0 = std::min(t(f.a), t(f.b)), f1 = std::max(t(f.a), t(f.b));
  return std::max<Int128>(0, f0) < std::min(len, f1);
}

// The output label of a point owned by subject member a and clip member b (-1: none), as a
// pair (channel, member) flattened to one integer; -1 for "not in the output".
inline long long label(ClipOp op, long long a, long long b) {
  const long long subject = a, clip = b >= 0 ? (1LL << 40) + b : -1;
  switch (op) {
    case ClipOp::kUnion:
      return a >= 0 ? subject : clip;
    case ClipOp::kIntersection:
      return a >= 0 && b >= 0 ? subject : -1;
    case ClipOp::kDifference:
      return a >= 0 && b < 0 ? subject : -1;
    case ClipOp::kXor:
      return a >= 0 && b < 0 ? subject : a < 0 && b >= 0 ? clip : -1;
  }
  return -1;
}

}  // namespace locality_detail

// Whether every point of e is farther than 2 units from the boundary of `other` (exact).
inline bool far_from(const Segment& e, const PolygonSet& other) {
  const Box64 eb{{std::min(e.a.x, e.b.x) - 2, std::min(e.a.y, e.b.y) - 2},
                 {std::max(e.a.x, e.b.x) + 2, std::max(e.a.y, e.b.y) + 2}};
  for (const Polygon& p : other)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Segment f = ring_edge(p, i);
      const Box64 fb{{std::min(f.a.x, f.b.x), std::min(f.a.y, f.b.y)},
                     {std::max(f.a.x, f.b.x), std::max(f.a.y, f.b.y)}};
      if (!eb.overlaps(fb)) continue;
      if (!segments_farther_than(e, f, 4)) return false;
    }
  return true;
}

// Empty when every far edge of `input` (the subject when input_is_subject, else the clip set)
// is kept whole or removed whole as the operation demands; otherwise the first violation.
enum class Locality { kLiteral, kOperation };

// One piece of a far input edge of member `pi` of `input`, with constant owners along it.
inline std::string check_piece(ClipOp op, const Segment& e, std::size_t pi, const PolygonSet& input,
                               const PolygonSet& other, bool input_is_subject,
                               const std::vector<Segment>& out_edges, Locality reading) {
  using namespace locality_detail;
  const SamplePoint mid{e.a.x + e.b.x, e.a.y + e.b.y, 2};
  long long right = -1, owner_other = -1;
  for (std::size_t j = 0; j < input.size(); ++j)
    if (j != pi && locate(PolygonSet{input[j]}, mid) == Where::kOnBoundary)
      right = static_cast<long long>(j);
  for (std::size_t j = 0; j < other.size(); ++j)
    if (locate(PolygonSet{other[j]}, mid) == Where::kInside)
      owner_other = static_cast<long long>(j);
  const long long me = static_cast<long long>(pi);
  const long long left_label =
      input_is_subject ? label(op, me, owner_other) : label(op, owner_other, me);
  const long long right_label =
      input_is_subject ? label(op, right, owner_other) : label(op, owner_other, right);
  const bool expected = left_label != right_label;
  bool touched = false, kept = false;
  for (const Segment& f : out_edges) {
    if (!overlaps(e, f)) continue;
    touched = true;
    if (on_closed_segment(e.a, f.a, f.b) && on_closed_segment(e.b, f.a, f.b)) kept = true;
  }
  const std::string where = "(" + std::to_string(e.a.x) + ' ' + std::to_string(e.a.y) + ", " +
                            std::to_string(e.b.x) + ' ' + std::to_string(e.b.y) + ")";
  if (touched && !kept) return "far edge " + where + " is only partly in the output";
  if (reading == Locality::kLiteral) return {};
  if (!expected && touched) return "far edge " + where + " should be gone but is in the output";
  if (expected && !touched) return "far edge " + where + " should be kept but is missing";
  return {};
}

inline std::string check_locality(ClipOp op, const PolygonSet& input, const PolygonSet& other,
                                  bool input_is_subject, const PolygonSet& out,
                                  Locality reading = Locality::kOperation) {
  using namespace locality_detail;
  std::vector<Segment> out_edges;
  for (const Polygon& p : out)
    for (std::size_t i = 0; i < p.size(); ++i) out_edges.push_back(ring_edge(p, i));
  std::vector<Point64> input_vertices;
  for (const Polygon& p : input) input_vertices.insert(input_vertices.end(), p.begin(), p.end());
  for (std::size_t pi = 0; pi < input.size(); ++pi) {
    const Polygon& p = input[pi];
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Segment e = ring_edge(p, i);
      if (!far_from(e, other)) continue;
      // Pieces of e between the vertices of its own set that lie on it: along each piece the
      // owners on both sides are constant (another member may share only part of e, or touch
      // it at a vertex), so each piece is kept or removed as a whole.
      std::vector<Point64> cuts{e.a, e.b};
      for (const Point64& v : input_vertices)
        if (on_closed_segment(v, e.a, e.b)) cuts.push_back(v);
      auto along = [&](Point64 v) {
        return Int128(v.x - e.a.x) * (e.b.x - e.a.x) + Int128(v.y - e.a.y) * (e.b.y - e.a.y);
      };
      std::sort(cuts.begin(), cuts.end(),
                [&](Point64 u, Point64 v) { return along(u) < along(v); });
      cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const Segment piece{cuts[k], cuts[k + 1]};
        if (std::string f =
                check_piece(op, piece, pi, input, other, input_is_subject, out_edges, reading);
            !f.empty())
          return f + " (a piece of the input edge (" + std::to_string(e.a.x) + ' ' +
                 std::to_string(e.a.y) + ", " + std::to_string(e.b.x) + ' ' +
                 std::to_string(e.b.y) + "))";
      }
    }
  }
  return {};
}

}  // namespace edgeland::test
