// import_polygons() (ogc_import.hpp): each ring stands for the region it winds around
// (non-zero rule). A strictly simple ring is that region's boundary once it turns the right way:
// exteriors counter-clockwise, holes clockwise; then the sum of +1 over exteriors and -1 over
// holes is filled where positive. A ring that is not simple (a bow tie, a spike, a figure eight:
// invalid OGC, common in foreign data) is replaced by the boundaries of its own non-zero region,
// so every lobe of a self-crossing exterior counts, whichever way it turns (orienting it by its
// total signed area would keep only the lobes turning with the larger ones; GEOS and PostGIS
// MakeValid keep them all too).
#include "ogc_import.hpp"

#include <algorithm>

#include "canonical.hpp"
#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "input_edges.hpp"
#include "snap_rounding.hpp"

namespace edgeland::detail {
namespace {

// The rings of all polygons, exteriors counter-clockwise and holes clockwise, with which are
// exteriors and which are strictly simple.
struct OrientedRings {
  std::vector<Ring> rings;
  std::vector<bool> exterior, simple;
};

OrientedRings oriented_rings(const std::vector<std::vector<Ring>>& polygons) {
  OrientedRings out;
  for (const auto& polygon : polygons)
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      Ring ring = polygon[k];
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (!in_range(ring[i])) {
          const auto index = static_cast<std::size_t>(&polygon - polygons.data());
          throw CoordinateOutOfRange(Operand::kRings, index, k, i, ring[i]);
        }
      // Repeated points (a closing point copied from WKT or GeoJSON among them) change no
      // winding number; without them a valid ring passes the simplicity test below.
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
      if (twice_signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
      out.simple.push_back(validate(ring, 1).ok());  // strictly simple (and now CCW)
      out.exterior.push_back(k == 0);
      if (k > 0) std::reverse(ring.begin(), ring.end());
      out.rings.push_back(std::move(ring));
    }
  return out;
}

// Every ring routed through the hot pixels of all of them snapped together (snap_rounding.hpp),
// as closed integer polylines in their own direction: the routes meet one another and
// themselves only at shared vertices or along shared stretches, never crossing.
std::vector<Ring> snapped_rings(const std::vector<Ring>& rings, ClipStats& stats) {
  EdgeList edges;
  append_ring_edges(rings, kSubjectChannel, true, edges);
  const Snapped snapped =
      node_and_snap_round(edges.segments, edges.next, false, &stats.intersections);
  const auto& fragments = snapped.fragments;
  stats.vertices_snapped = snapped.hot_pixels;
  // Listed fragments come in segment order, each segment's from its start to its end; a
  // segment with none listed is its own fragment.
  std::vector<Ring> out(rings.size());
  std::size_t f = 0;
  for (std::uint32_t s = 0; s < edges.size(); ++s) {
    Ring& route = out[static_cast<std::size_t>(edges.polygon[s])];
    if (f == fragments.size() || fragments[f].parent != s) {
      route.push_back(edges.segments[s].a);
      continue;
    }
    for (; f < fragments.size() && fragments[f].parent == s; ++f)
      route.push_back(fragments[f].seg.a);
  }
  return out;
}

// One rounding for everything: all rings are snapped together first, after which filling
// a ring alone, or all of them, meets only integer contacts and rounds nothing more.
// (Snapping each odd ring alone and then all together would round twice; a vertex could
// then lie farther than a unit from the exact boundary, and a property test found one.)
ClipResult fill_snapped(const OrientedRings& in, const ClipOptions& options) {
  ClipStats snapped_stats;
  const std::vector<Ring> snapped = snapped_rings(in.rings, snapped_stats);
  std::vector<Ring> filled;
  for (std::size_t r = 0; r < snapped.size(); ++r) {
    if (in.simple[r]) {
      filled.push_back(snapped[r]);
      continue;
    }
    for (Polygon& piece : normalize({snapped[r]}, FillRule::kNonZero, options).polygons) {
      if (!in.exterior[r]) std::reverse(piece.begin(), piece.end());
      filled.push_back(std::move(piece));
    }
  }
  ClipResult out = normalize(filled, FillRule::kPositive, options);
  out.stats.intersections = snapped_stats.intersections;
  out.stats.vertices_snapped = snapped_stats.vertices_snapped;
  return out;
}

}  // namespace

ClipResult import_ogc(const std::vector<std::vector<Ring>>& polygons, const ClipOptions& options) {
  OrientedRings in = oriented_rings(polygons);
  // One strictly simple ring without holes is a valid set already: its canonical form is what
  // normalize would return, at the cost of the check above (a 4 * 10^5-vertex polygon minus the
  // empty set spent 80% of its time re-noding it).
  if (in.rings.size() == 1 && in.simple[0]) {
    ClipResult out;
    out.polygons.push_back(canonical_ring(std::move(in.rings[0])));
    return out;
  }
  if (std::find(in.simple.begin(), in.simple.end(), false) == in.simple.end())
    return normalize(in.rings, FillRule::kPositive, options);  // valid OGC input: one pass
  return fill_snapped(in, options);
}

}  // namespace edgeland::detail
