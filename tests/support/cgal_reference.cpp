// The only translation unit that includes CGAL (see cgal_reference.hpp for why).
#include "cgal_reference.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <cmath>
#include <sstream>
#include <type_traits>
#include <utility>

namespace edgeland::test {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using CPoint = K::Point_2;
using CSegment = K::Segment_2;
using CPolygon = CGAL::Polygon_2<K>;
using CPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;
using CSet = CGAL::Polygon_set_2<K>;

// CGAL's exact number type: boost's mpq_rational or GMPXX's mpq_class depending on how CGAL
// was configured. Both wrap a GMP mpq_t, through which values are converted exactly.
using Exact = std::decay_t<decltype(CGAL::exact(K::FT(1)))>;

template <class E>
Rational to_rational(const E& e) {
  if constexpr (std::is_same_v<E, Rational>) return e;
  else return Rational(e.get_mpq_t());
}
template <class E = Exact>
E to_exact(const Rational& r) {
  if constexpr (std::is_same_v<E, Rational>) return r;
  else return E(r.backend().data());
}

// Integer coordinates up to 2^31 are exact doubles, and a lazy number built from a double
// carries that exact value.
K::FT ft(std::int64_t v) { return K::FT(static_cast<double>(v)); }
K::FT ft(const Rational& v) { return K::FT(to_exact(v)); }
CPoint cpoint(Point64 p) { return CPoint(ft(p.x), ft(p.y)); }
CPoint cpoint(const QPoint& p) { return CPoint(ft(p.x), ft(p.y)); }

CPolygon cpolygon(const Polygon& polygon) {
  CPolygon out;
  for (const Point64& p : polygon) out.push_back(cpoint(p));
  return out;
}

// ceil(sqrt(v)) for a rational v >= 0, exactly: the smallest k with k^2 >= v.
BigInt ceil_sqrt(const Rational& v) {
  const BigInt num = boost::multiprecision::numerator(v);
  const BigInt den = boost::multiprecision::denominator(v);
  BigInt k = boost::multiprecision::sqrt(BigInt(num / den));
  while (k * k * den < num) ++k;
  return k;
}

std::string text(const Exact& v) { return to_rational(v).str(); }

void write_ring(std::ostringstream& os, const CPolygon& ring) {
  os << '(';
  bool first = true;
  for (auto it = ring.vertices_begin(); it != ring.vertices_end(); ++it) {
    if (!first) os << ", ";
    first = false;
    os << text(CGAL::exact(it->x())) << ' ' << text(CGAL::exact(it->y()));
  }
  if (!ring.is_empty())
    os << ", " << text(CGAL::exact(ring.vertex(0).x())) << ' '
       << text(CGAL::exact(ring.vertex(0).y()));
  os << ')';
}

}  // namespace

struct ExactRegion::Impl {
  CSet set;
  std::vector<CPolygonWithHoles> parts;
  std::vector<CSegment> boundary;
  std::vector<CGAL::Bbox_2> boxes;  // conservative (outward-rounded) boxes of `boundary`
  std::size_t cycles = 0;
  Rational area = 0;

  explicit Impl(CSet s) : set(std::move(s)) {
    set.polygons_with_holes(std::back_inserter(parts));
    auto add_ring = [&](const CPolygon& ring) {
      ++cycles;
      area += to_rational(CGAL::exact(ring.area()));  // holes are clockwise: negative area
      for (auto e = ring.edges_begin(); e != ring.edges_end(); ++e) {
        boundary.push_back(*e);
        boxes.push_back(e->bbox());
      }
    };
    for (const CPolygonWithHoles& p : parts) {
      add_ring(p.outer_boundary());
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) add_ring(*h);
    }
  }
};

ExactRegion::ExactRegion() : impl_(std::make_shared<const Impl>(CSet())) {}
ExactRegion::ExactRegion(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

ExactRegion ExactRegion::of(const PolygonSet& set) {
  std::vector<CPolygon> polygons;
  for (const Polygon& p : set) polygons.push_back(cpolygon(p));
  CSet s;
  if (!polygons.empty()) s.join(polygons.begin(), polygons.end());
  return ExactRegion(std::make_shared<const Impl>(std::move(s)));
}

ExactRegion ExactRegion::of(const Polygon& polygon) { return of(PolygonSet{polygon}); }

ExactRegion ExactRegion::of_rational_polygons(const std::vector<std::vector<QPoint>>& polygons) {
  std::vector<CPolygon> pieces;
  for (const auto& poly : polygons) {
    CPolygon c;
    for (const QPoint& p : poly) {
      const CPoint cp = cpoint(p);
      if (c.is_empty() || c.vertex(c.size() - 1) != cp) c.push_back(cp);
    }
    while (c.size() > 1 && c.vertex(0) == c.vertex(c.size() - 1)) c.erase(c.vertices_end() - 1);
    if (c.size() < 3) continue;
    const CGAL::Sign s = CGAL::sign(c.area());
    if (s == CGAL::ZERO) continue;
    if (s == CGAL::NEGATIVE) c.reverse_orientation();
    pieces.push_back(std::move(c));
  }
  CSet s;
  if (!pieces.empty()) s.join(pieces.begin(), pieces.end());
  return ExactRegion(std::make_shared<const Impl>(std::move(s)));
}

namespace {

void apply_in_place(CSet& r, ClipOp op, const CSet& other) {
  switch (op) {
    case ClipOp::kUnion: r.join(other); break;
    case ClipOp::kIntersection: r.intersection(other); break;
    case ClipOp::kDifference: r.difference(other); break;
    case ClipOp::kXor: r.symmetric_difference(other); break;
  }
}

// The same region in a set built afresh from its polygons with holes (a new arrangement).
CSet rebuilt(const std::vector<CPolygonWithHoles>& parts) {
  CSet s;
  if (!parts.empty()) s.join(parts.begin(), parts.end());
  return s;
}

// A op B computed one part of A (and for xor, of B) at a time, each against the other whole
// set, the results joined: intersection and difference distribute over the disjoint parts, and
// xor = (A - B) + (B - A). A different arrangement for each piece.
CSet part_by_part(ClipOp op, const std::vector<CPolygonWithHoles>& a,
                  const std::vector<CPolygonWithHoles>& b) {
  if (op == ClipOp::kUnion) {
    std::vector<CPolygonWithHoles> all(a);
    all.insert(all.end(), b.begin(), b.end());
    return rebuilt(all);
  }
  const CSet whole_b = rebuilt(b);
  auto each = [](const std::vector<CPolygonWithHoles>& parts, ClipOp part_op, const CSet& other,
                 std::vector<CPolygonWithHoles>& out) {
    for (const CPolygonWithHoles& p : parts) {
      CSet piece;
      piece.insert(p);
      apply_in_place(piece, part_op, other);
      piece.polygons_with_holes(std::back_inserter(out));
    }
  };
  std::vector<CPolygonWithHoles> out;
  if (op == ClipOp::kXor) {
    each(a, ClipOp::kDifference, whole_b, out);
    each(b, ClipOp::kDifference, rebuilt(a), out);
  } else {
    each(a, op, whole_b, out);
  }
  return rebuilt(out);
}

}  // namespace

ExactRegion ExactRegion::apply(ClipOp op, const ExactRegion& other) const {
  CSet r = impl_->set;
  try {
    apply_in_place(r, op, other.impl_->set);
  } catch (const CGAL::Precondition_exception&) {
    // CGAL 5.5's Boolean operations on a set carried through many operations can fail the
    // arrangement precondition "number_of_outer_ccbs() == 1" (cf. CGAL issue #644) although
    // the region is valid; seen after a few hundred steps of the closure chain, with this
    // session's and earlier edgeland alike. The same operation on sets rebuilt from their
    // polygons with holes succeeds; should it not, the exception propagates.
    try {
      r = rebuilt(impl_->parts);
      apply_in_place(r, op, rebuilt(other.impl_->parts));
    } catch (const CGAL::Precondition_exception&) {
      r = part_by_part(op, impl_->parts, other.impl_->parts);
    }
  }
  return ExactRegion(std::make_shared<const Impl>(std::move(r)));
}

bool ExactRegion::empty() const { return impl_->parts.empty(); }
Rational ExactRegion::area() const { return impl_->area; }
std::size_t ExactRegion::boundary_cycles() const { return impl_->cycles; }
std::size_t ExactRegion::boundary_edges() const { return impl_->boundary.size(); }

BigInt ExactRegion::perimeter_ceil() const {
  BigInt sum = 0;
  for (const CSegment& s : impl_->boundary) sum += ceil_sqrt(to_rational(CGAL::exact(s.squared_length())));
  return sum;
}

// By the parity of boundary crossings of the ray from p towards +x (half-open in y), with
// exact orientation tests, rather than by Polygon_set_2::oriented_side: for a result whose
// island lies in a hole of another part (A minus B where the members of A enclose a hole
// holding another member), CGAL 5.5's point location answered "outside" for points of the
// island, while the boundary curves (and so areas and distances) were right.
ExactRegion::Location ExactRegion::locate(const QPoint& p) const {
  if (boundary_within(p, 0)) return Location::kOnBoundary;
  const CPoint cp = cpoint(p);
  const double px = p.x.convert_to<double>(), py = p.y.convert_to<double>();
  bool inside = false;
  for (std::size_t i = 0; i < impl_->boundary.size(); ++i) {
    // Prefilter on the conservative boxes (one unit of margin for p's rounding to double):
    // a segment entirely above, below or left of p cannot cross the ray.
    const CGAL::Bbox_2& box = impl_->boxes[i];
    if (box.ymin() > py + 1 || box.ymax() < py - 1 || box.xmax() < px - 1) continue;
    const CSegment& s = impl_->boundary[i];
    const CPoint &a = s.source(), &b = s.target();
    const bool a_below = a.y() <= cp.y(), b_below = b.y() <= cp.y();
    if (a_below == b_below) continue;
    const CGAL::Orientation o = CGAL::orientation(a, b, cp);
    if ((a_below && o == CGAL::LEFT_TURN) || (!a_below && o == CGAL::RIGHT_TURN)) inside = !inside;
  }
  return inside ? Location::kInside : Location::kOutside;
}

ExactRegion::Location ExactRegion::locate_by_cgal(const QPoint& p) const {
  switch (impl_->set.oriented_side(cpoint(p))) {
    case CGAL::ON_POSITIVE_SIDE: return Location::kInside;
    case CGAL::ON_NEGATIVE_SIDE: return Location::kOutside;
    default: return Location::kOnBoundary;
  }
}

bool ExactRegion::boundary_within(const QPoint& p, const Rational& squared_radius) const {
  // A cheap prefilter on the conservative boxes (margin of one unit for the rounding of p to
  // double); the decision itself is the exact comparison.
  const double px = p.x.convert_to<double>(), py = p.y.convert_to<double>();
  const double r = std::sqrt(squared_radius.convert_to<double>()) + 1.0;
  const CPoint cp = cpoint(p);
  const K::FT limit = ft(squared_radius);
  for (std::size_t i = 0; i < impl_->boundary.size(); ++i) {
    const CGAL::Bbox_2& b = impl_->boxes[i];
    if (px < b.xmin() - r || px > b.xmax() + r || py < b.ymin() - r || py > b.ymax() + r)
      continue;
    if (CGAL::squared_distance(cp, impl_->boundary[i]) <= limit) return true;
  }
  return false;
}

std::string ExactRegion::to_text() const {
  if (impl_->parts.empty()) return "MULTIPOLYGON EMPTY";
  std::ostringstream os;
  os << "MULTIPOLYGON (";
  for (std::size_t i = 0; i < impl_->parts.size(); ++i) {
    if (i) os << ", ";
    os << '(';
    write_ring(os, impl_->parts[i].outer_boundary());
    for (auto h = impl_->parts[i].holes_begin(); h != impl_->parts[i].holes_end(); ++h) {
      os << ", ";
      write_ring(os, *h);
    }
    os << ')';
  }
  os << ')';
  return os.str();
}

bool segments_farther_than(const Segment& s, const Segment& t, const Rational& squared_radius) {
  const K::FT limit = ft(squared_radius);
  // Degenerate segments are points (CGAL's Segment_2 requires distinct endpoints).
  if (s.a == s.b && t.a == t.b) return CGAL::squared_distance(cpoint(s.a), cpoint(t.a)) > limit;
  if (s.a == s.b) return CGAL::squared_distance(cpoint(s.a), CSegment(cpoint(t.a), cpoint(t.b))) > limit;
  if (t.a == t.b) return CGAL::squared_distance(cpoint(t.a), CSegment(cpoint(s.a), cpoint(s.b))) > limit;
  const CSegment a(cpoint(s.a), cpoint(s.b)), b(cpoint(t.a), cpoint(t.b));
  return CGAL::squared_distance(a, b) > limit;
}

}  // namespace edgeland::test
