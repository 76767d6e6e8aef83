// CGAL peers of triangulate() and convex_pieces() (cgal_pieces.hpp).
#include "cgal_pieces.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/partition_2.h>

#include <iterator>
#include <list>
#include <vector>

namespace edgeland::bench {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;  // nesting level, -1 unknown
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Marks the faces reachable from `start` without crossing a constraint with `level`, queueing
// the faces across constraints for level + 1.
void mark_domain(Cdt& cdt, Cdt::Face_handle start, int level, std::list<Cdt::Edge>& border) {
  std::list<Cdt::Face_handle> queue{start};
  while (!queue.empty()) {
    const Cdt::Face_handle f = queue.front();
    queue.pop_front();
    if (f->info() != -1) continue;
    f->info() = level;
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle n = f->neighbor(i);
      if (n->info() != -1) continue;
      if (cdt.is_constrained({f, i}))
        border.push_back({f, i});
      else
        queue.push_back(n);
    }
  }
}

std::size_t count_odd_levels(Cdt& cdt) {
  for (Cdt::Face_handle f : cdt.all_face_handles()) f->info() = -1;
  std::list<Cdt::Edge> border;
  mark_domain(cdt, cdt.infinite_face(), 0, border);
  while (!border.empty()) {
    const Cdt::Edge e = border.front();
    border.pop_front();
    const Cdt::Face_handle n = e.first->neighbor(e.second);
    if (n->info() == -1) mark_domain(cdt, n, e.first->info() + 1, border);
  }
  std::size_t inside = 0;
  for (Cdt::Face_handle f : cdt.finite_face_handles()) inside += f->info() % 2 == 1;
  return inside;
}

K::Point_2 point(Point64 p) { return {static_cast<double>(p.x), static_cast<double>(p.y)}; }

}  // namespace

std::size_t cgal_cdt_inside_faces(const Polygon& polygon) {
  std::vector<K::Point_2> points;
  points.reserve(polygon.size());
  for (const Point64& p : polygon) points.push_back(point(p));
  Cdt cdt;
  cdt.insert_constraint(points.begin(), points.end(), /*close=*/true);
  return count_odd_levels(cdt);
}

std::size_t cgal_convex_partition(const Polygon& polygon, CgalPartition kind) {
  using Traits = CGAL::Partition_traits_2<K>;
  std::vector<Traits::Point_2> points;
  for (const Point64& p : polygon) points.push_back(point(p));
  std::vector<Traits::Polygon_2> pieces;
  switch (kind) {
    case CgalPartition::kApprox:
      CGAL::approx_convex_partition_2(points.begin(), points.end(), std::back_inserter(pieces));
      break;
    case CgalPartition::kGreene:
      CGAL::greene_approx_convex_partition_2(points.begin(), points.end(),
                                             std::back_inserter(pieces));
      break;
    case CgalPartition::kOptimal:
      CGAL::optimal_convex_partition_2(points.begin(), points.end(), std::back_inserter(pieces));
      break;
  }
  return pieces.size();
}

}  // namespace edgeland::bench
