// The only translation unit that includes CGAL (see cgal_reference.hpp for why).
#include "cgal_reference.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
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
  if constexpr (std::is_same_v<E, Rational>)
    return e;
  else
    return Rational(e.get_mpq_t());
}
template <class E = Exact>
E to_exact(const Rational& r) {
  if constexpr (std::is_same_v<E, Rational>)
    return r;
  else
    return E(r.backend().data());
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

// ---------------------------------------------------------------------------------------------
// Working around CGAL 5.5. Its Boolean operations on valid regions can fail their own
// arrangement precondition "number_of_outer_ccbs() == 1" (cf. CGAL issue #644): seen on sets
// carried through a few hundred operations of the closure chain (the same operation on rebuilt
// sets then succeeded), and reported in longer chains from computations that retry did not cover.
// Whether an operation fails depends on the exact shapes and on the arrangement it runs in, so
// every construction and operation of the oracle computes the SAME region another way when CGAL
// fails: each fallback below is an exact identity of regularised Boolean operations, evaluated
// by CGAL in other, smaller arrangements; none approximates or skips anything, and a failure of
// the last one propagates.
// ---------------------------------------------------------------------------------------------
namespace {

using Parts = std::vector<CPolygonWithHoles>;

// A set and its polygons with holes, read from it.
struct Computed {
  CSet set;
  Parts parts;
};

Computed read(CSet s) {
  Computed c{std::move(s), {}};
  c.set.polygons_with_holes(std::back_inserter(c.parts));
  return c;
}

// Reading the polygons with holes walks the arrangement's faces (where the precondition lives),
// so it belongs to the attempt: a failed attempt gives nothing, never part of a region.
template <class Compute>
std::optional<Computed> attempt(Compute compute) {
  try {
    return read(compute());
  } catch (const CGAL::Failure_exception&) {
    return std::nullopt;
  }
}

// Uses of each fallback (oracle_fallbacks()); atomic as a test may use the oracle on threads.
std::atomic<std::size_t> rebuilt_uses{0}, split_uses{0}, part_by_part_uses{0}, halves_uses{0};

// ForcedOracleFallback's setting on this thread: 0, or how many ways apply() skips.
thread_local int forced_skip = 0;

// How deep split() may nest: at most 2^6 strips for one operation.
constexpr int kMaxSplits = 6;

void apply_in_place(CSet& r, ClipOp op, const CSet& other) {
  switch (op) {
    case ClipOp::kUnion:
      r.join(other);
      break;
    case ClipOp::kIntersection:
      r.intersection(other);
      break;
    case ClipOp::kDifference:
      r.difference(other);
      break;
    case ClipOp::kXor:
      r.symmetric_difference(other);
      break;
  }
}

// The same region in a set built afresh from its polygons with holes (a new arrangement).
CSet rebuilt(const Parts& parts) {
  CSet s;
  if (!parts.empty()) s.join(parts.begin(), parts.end());
  return s;
}

Computed apply_parts(ClipOp op, const Parts& a, const Parts& b, int splits_left);

// A op B computed one part of A (and for xor, of B) at a time, each against the other whole
// set, the results joined: intersection and difference distribute over the disjoint parts, and
// xor = (A - B) + (B - A). A different arrangement for each piece. The last resort: a failure
// here propagates.
CSet part_by_part(ClipOp op, const Parts& a, const Parts& b) {
  if (op == ClipOp::kUnion) {
    Parts all(a);
    all.insert(all.end(), b.begin(), b.end());
    return rebuilt(all);
  }
  const CSet whole_b = rebuilt(b);
  auto each = [](const Parts& parts, ClipOp part_op, const CSet& other, Parts& out) {
    for (const CPolygonWithHoles& p : parts) {
      CSet piece;
      piece.insert(p);
      apply_in_place(piece, part_op, other);
      piece.polygons_with_holes(std::back_inserter(out));
    }
  };
  Parts out;
  if (op == ClipOp::kXor) {
    each(a, ClipOp::kDifference, whole_b, out);
    each(b, ClipOp::kDifference, rebuilt(a), out);
  } else {
    each(a, op, whole_b, out);
  }
  return rebuilt(out);
}

CGAL::Bbox_2 bbox(const Parts& a, const Parts& b) {
  CGAL::Bbox_2 box;
  for (const Parts* parts : {&a, &b})
    for (const CPolygonWithHoles& p : *parts) box += p.outer_boundary().bbox();
  return box;
}

CPolygonWithHoles rectangle(const K::FT& x0, const K::FT& y0, const K::FT& x1, const K::FT& y1) {
  CPolygon r;
  r.push_back(CPoint(x0, y0));
  r.push_back(CPoint(x1, y0));
  r.push_back(CPoint(x1, y1));
  r.push_back(CPoint(x0, y1));
  return CPolygonWithHoles(r);
}

// A op B as the union of (A * H) op (B * H) over the two closed half-boxes H either side of a
// vertical line through the middle of the operands' box: regularised operations commute with
// restriction to a closed cell, and the two results meet only along the line. Every piece is
// computed in its own, smaller arrangement (through apply_parts, so a piece that fails again is
// split again). The line x = m + 1/2 misses every integer vertex of the inputs.
Computed split(ClipOp op, const Parts& a, const Parts& b, int splits_left) {
  const CGAL::Bbox_2 box = bbox(a, b);  // CGAL's boxes of exact points are outward-rounded
  const double x0 = std::floor(box.xmin()) - 1, x1 = std::ceil(box.xmax()) + 1;
  const double y0 = std::floor(box.ymin()) - 1, y1 = std::ceil(box.ymax()) + 1;
  const K::FT cut = K::FT(std::floor((x0 + x1) / 2)) + K::FT(1) / K::FT(2);
  const Parts halves[] = {{rectangle(K::FT(x0), K::FT(y0), cut, K::FT(y1))},
                          {rectangle(cut, K::FT(y0), K::FT(x1), K::FT(y1))}};
  Parts pieces[2];
  for (int i = 0; i < 2; ++i) {
    const Computed ah = apply_parts(ClipOp::kIntersection, a, halves[i], splits_left - 1);
    const Computed bh = apply_parts(ClipOp::kIntersection, b, halves[i], splits_left - 1);
    pieces[i] = apply_parts(op, ah.parts, bh.parts, splits_left - 1).parts;
  }
  return apply_parts(ClipOp::kUnion, pieces[0], pieces[1], splits_left - 1);
}

// A op B once it failed in sets built from A's and B's polygons with holes: split along a
// vertical line (while the nesting allows), else part by part.
Computed fallbacks(ClipOp op, const Parts& a, const Parts& b, int splits_left) {
  if (splits_left > 0) {
    if (auto r = attempt([&] { return split(op, a, b, splits_left).set; })) {
      ++split_uses;
      return std::move(*r);
    }
  }
  ++part_by_part_uses;
  return read(part_by_part(op, a, b));
}

std::optional<Computed> in_rebuilt_sets(ClipOp op, const Parts& a, const Parts& b) {
  return attempt([&] {
    CSet s = rebuilt(a);
    apply_in_place(s, op, rebuilt(b));
    return s;
  });
}

// A op B for regions given by their polygons with holes.
Computed apply_parts(ClipOp op, const Parts& a, const Parts& b, int splits_left) {
  if (auto r = in_rebuilt_sets(op, a, b)) return std::move(*r);
  return fallbacks(op, a, b, splits_left);
}

// The union of simple counterclockwise polygons: joined at once, else (the union being
// associative) the polygons sorted by their left ends, each half joined, then the two halves
// united. Halving terminates: a single polygon is inserted as it is.
Computed joined(std::vector<CPolygon> polygons) {
  if (polygons.size() <= 1) {
    CSet s;
    if (!polygons.empty()) s.insert(polygons.front());
    return read(std::move(s));
  }
  if (forced_skip == 0) {
    if (auto r = attempt([&] {
          CSet s;
          s.join(polygons.begin(), polygons.end());
          return s;
        }))
      return std::move(*r);
  }
  ++halves_uses;
  std::sort(polygons.begin(), polygons.end(),
            [](const CPolygon& p, const CPolygon& q) { return p.bbox().xmin() < q.bbox().xmin(); });
  const auto mid = polygons.begin() + static_cast<std::ptrdiff_t>(polygons.size() / 2);
  const Computed left = joined(std::vector<CPolygon>(polygons.begin(), mid));
  const Computed right = joined(std::vector<CPolygon>(mid, polygons.end()));
  return apply_parts(ClipOp::kUnion, left.parts, right.parts, kMaxSplits);
}

}  // namespace

OracleFallbacks oracle_fallbacks() {
  return {rebuilt_uses.load(), split_uses.load(), part_by_part_uses.load(), halves_uses.load()};
}

ForcedOracleFallback::ForcedOracleFallback(Skip skip) : previous_(forced_skip) {
  forced_skip = static_cast<int>(skip);
}
ForcedOracleFallback::~ForcedOracleFallback() { forced_skip = previous_; }

struct ExactRegion::Impl {
  CSet set;
  Parts parts;
  std::vector<CSegment> boundary;
  std::vector<CGAL::Bbox_2> boxes;  // conservative (outward-rounded) boxes of `boundary`
  std::size_t cycles = 0;
  Rational area = 0;

  explicit Impl(Computed c) : set(std::move(c.set)), parts(std::move(c.parts)) {
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

ExactRegion::ExactRegion() : impl_(std::make_shared<const Impl>(Computed{})) {}
ExactRegion::ExactRegion(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

ExactRegion ExactRegion::of(const PolygonSet& set) {
  std::vector<CPolygon> polygons;
  for (const Polygon& p : set) polygons.push_back(cpolygon(p));
  return ExactRegion(std::make_shared<const Impl>(joined(std::move(polygons))));
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
  return ExactRegion(std::make_shared<const Impl>(joined(std::move(pieces))));
}

// On a failure of CGAL (see above): the operation on sets rebuilt from the polygons with holes
// (a fresh arrangement; enough for most failures of sets carried through many operations), then
// in two halves along a vertical line, recursively, then part by part.
ExactRegion ExactRegion::apply(ClipOp op, const ExactRegion& other) const {
  std::optional<Computed> r;
  if (forced_skip < 1) {
    r = attempt([&] {
      CSet s = impl_->set;
      apply_in_place(s, op, other.impl_->set);
      return s;
    });
  }
  if (!r && forced_skip < 2) {
    r = in_rebuilt_sets(op, impl_->parts, other.impl_->parts);
    if (r) ++rebuilt_uses;
  }
  if (!r) {
    if (forced_skip >= 3) {
      ++part_by_part_uses;
      r = read(part_by_part(op, impl_->parts, other.impl_->parts));
    } else {
      r = fallbacks(op, impl_->parts, other.impl_->parts, kMaxSplits);
    }
  }
  return ExactRegion(std::make_shared<const Impl>(std::move(*r)));
}

bool ExactRegion::empty() const { return impl_->parts.empty(); }
Rational ExactRegion::area() const { return impl_->area; }
std::size_t ExactRegion::boundary_cycles() const { return impl_->cycles; }
std::size_t ExactRegion::boundary_edges() const { return impl_->boundary.size(); }

BigInt ExactRegion::perimeter_ceil() const {
  BigInt sum = 0;
  for (const CSegment& s : impl_->boundary)
    sum += ceil_sqrt(to_rational(CGAL::exact(s.squared_length())));
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
    case CGAL::ON_POSITIVE_SIDE:
      return Location::kInside;
    case CGAL::ON_NEGATIVE_SIDE:
      return Location::kOutside;
    default:
      return Location::kOnBoundary;
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
    if (px < b.xmin() - r || px > b.xmax() + r || py < b.ymin() - r || py > b.ymax() + r) continue;
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
  if (s.a == s.b)
    return CGAL::squared_distance(cpoint(s.a), CSegment(cpoint(t.a), cpoint(t.b))) > limit;
  if (t.a == t.b)
    return CGAL::squared_distance(cpoint(t.a), CSegment(cpoint(s.a), cpoint(s.b))) > limit;
  const CSegment a(cpoint(s.a), cpoint(s.b)), b(cpoint(t.a), cpoint(t.b));
  return CGAL::squared_distance(a, b) > limit;
}

}  // namespace edgeland::test
