#include "canonical_cell.hpp"

#include <vector>

#include "edgeland/kernel/canonical_form.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::detail {
namespace {

// Above this many edge pairs between two polygons the pairwise test gives way to the overlay,
// whose cost grows as n log n (a cell over the edge cap at min_cell_size can be large).
constexpr std::size_t kMaxEdgePairs = 4096;

// Whether two rings share a boundary segment of positive length (exact: the kernel's segment
// classification). nullopt: too many edge pairs to look.
std::optional<bool> share_a_segment(const Polygon& a, const Box64& a_box, const Polygon& b,
                                    const Box64& b_box) {
  if (!a_box.overlaps(b_box)) return false;
  if (a.size() * b.size() > kMaxEdgePairs) return std::nullopt;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Segment s = ring_edge(a, i);
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Segment t = ring_edge(b, j);
      if (std::max(s.a.x, s.b.x) < std::min(t.a.x, t.b.x) ||
          std::max(t.a.x, t.b.x) < std::min(s.a.x, s.b.x))
        continue;
      if (intersect(s, t).relation == SegmentRelation::kOverlapping) return true;
    }
  }
  return false;
}

// Whether every two of these polygons (indices into the cell) of one material meet at vertices
// at most. nullopt: too large to tell this way.
std::optional<bool> materials_meet_at_vertices_only(const Node& cell,
                                                    std::span<const std::size_t> members) {
  const PolygonSet& polys = cell.polygon_set();
  for (std::size_t a = 0; a < members.size(); ++a) {
    const std::size_t i = members[a];
    for (std::size_t b = a + 1; b < members.size(); ++b) {
      const std::size_t j = members[b];
      if (cell.content.labels[i] != cell.content.labels[j]) continue;
      const std::optional<bool> shared =
          share_a_segment(polys[i], cell.boxes[i], polys[j], cell.boxes[j]);
      if (!shared) return std::nullopt;
      if (*shared) return false;
    }
  }
  return true;
}

std::vector<std::size_t> all_members(const Node& cell) {
  std::vector<std::size_t> out(cell.polygon_set().size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = i;
  return out;
}

}  // namespace

bool cell_is_canonical_by_overlay(const Node& cell) {
  const LabeledClipResult again =
      relabel(cell.content.set, cell.content.labels, ValidSet(), cell.box, {});
  return again.regions.labels == cell.content.labels &&
         again.regions.set.polygons() == cell.polygon_set();
}

// The overlay merges faces of one material that share an edge, splits faces with holes, and
// writes every ring in canonical form and order (relabel.hpp). In a valid set whose polygons of
// one material share no boundary segment, every polygon is a face of its own (faces meeting at
// a vertex stay apart) without a hole, so the overlay writes each polygon back as it is, in
// canonical form: the content is canonical exactly when it is in canonical form. Pieces of one
// material sharing a segment (the bridges of a split hole, or pieces that should be one) are
// left to the overlay.
bool cell_is_canonical(const Node& cell) {
  if (!is_canonical(cell.polygon_set())) return false;
  const std::optional<bool> apart = materials_meet_at_vertices_only(cell, all_members(cell));
  if (apart == true) return true;
  return cell_is_canonical_by_overlay(cell);
}

// A part of a canonical set is in canonical form (same rings, same order), so the argument above
// applies to the members alone.
bool members_stay_apart(const Node& cell, std::span<const std::size_t> members) {
  return materials_meet_at_vertices_only(cell, members) == true;
}

}  // namespace edgeland::detail
