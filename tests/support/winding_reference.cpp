// Slab decomposition of a winding-number fill (see winding_reference.hpp).
#include "winding_reference.hpp"

#include <algorithm>

namespace edgeland::test {
namespace {

struct Seg {
  Point64 lo, hi;    // lo.x < hi.x
  int dir;           // +1 when the ring runs from lo to hi (+x), -1 otherwise
  std::size_t ring;  // index into the rings
};

bool filled(FillRule rule, int w) {
  switch (rule) {
    case FillRule::kEvenOdd:
      return w % 2 != 0;
    case FillRule::kNonZero:
      return w != 0;
    case FillRule::kPositive:
      return w > 0;
    case FillRule::kNegative:
      return w < 0;
  }
  return false;
}

// Height of the segment's line at abscissa x (lo.x <= x <= hi.x).
Rational y_at(const Seg& s, const Rational& x) {
  return Rational(s.lo.y) +
         Rational(s.hi.y - s.lo.y) * (x - Rational(s.lo.x)) / Rational(s.hi.x - s.lo.x);
}

// The slab decomposition; `counter` is reset per slab, told of each segment crossed going up
// (ring, dir) and asked whether the gap above is filled.
template <class Counter>
FilledRegion slab_region(const std::vector<Ring>& rings, Counter counter) {
  std::vector<Seg> segs;
  std::vector<Rational> xs;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point64 a = ring[i], b = ring[(i + 1) % ring.size()];
      xs.push_back(Rational(a.x));
      if (a.x == b.x) continue;  // vertical or degenerate: changes no slab's winding
      const std::size_t r = static_cast<std::size_t>(&ring - rings.data());
      segs.push_back(a.x < b.x ? Seg{a, b, 1, r} : Seg{b, a, -1, r});
    }
  }
  // Crossing abscissas of every pair of non-parallel segments whose x-ranges overlap.
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const Seg &s = segs[i], &t = segs[j];
      const Rational lo = std::max(s.lo.x, t.lo.x), hi = std::min(s.hi.x, t.hi.x);
      if (lo >= hi) continue;
      const Rational ds = y_at(s, lo) - y_at(t, lo), de = y_at(s, hi) - y_at(t, hi);
      if ((ds < 0 && de > 0) || (ds > 0 && de < 0)) xs.push_back(lo + (hi - lo) * ds / (ds - de));
    }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  FilledRegion out;
  std::vector<std::vector<QPoint>> pieces;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const Rational &x0 = xs[k], &x1 = xs[k + 1];
    struct Active {
      Rational y0, y1;
      int dir;
      std::size_t ring;
    };
    std::vector<Active> act;
    for (const Seg& s : segs)
      if (Rational(s.lo.x) <= x0 && Rational(s.hi.x) >= x1)
        act.push_back({y_at(s, x0), y_at(s, x1), s.dir, s.ring});
    // No crossing inside the slab: ordering by (y0, y1) is the order at every abscissa.
    std::sort(act.begin(), act.end(), [](const Active& a, const Active& b) {
      return a.y0 != b.y0 ? a.y0 < b.y0 : a.y1 < b.y1;
    });
    counter.reset();
    std::size_t run_start = 0;
    bool in_run = false;
    for (std::size_t j = 0; j < act.size(); ++j) {
      counter.cross(act[j].ring, act[j].dir);
      const bool f = counter.filled() && j + 1 < act.size();
      if (f && !in_run) {
        run_start = j;
        in_run = true;
      }
      if (in_run && (!f || j + 1 == act.size())) {
        const std::size_t top = f ? j + 1 : j;
        const Active &b = act[run_start], &t = act[top];
        const Rational area = (x1 - x0) * ((t.y0 - b.y0) + (t.y1 - b.y1)) / 2;
        if (area > 0) {
          out.trapezoid_area += area;
          ++out.trapezoids;
          pieces.push_back({{x0, b.y0}, {x1, b.y1}, {x1, t.y1}, {x0, t.y0}});
        }
        in_run = false;
      }
    }
  }
  out.region = ExactRegion::of_rational_polygons(pieces);
  return out;
}

}  // namespace

FilledRegion filled_region(const std::vector<Ring>& rings, FillRule rule) {
  struct Sum {
    FillRule rule;
    int w = 0;
    void reset() { w = 0; }
    void cross(std::size_t, int dir) { w += dir; }
    bool filled() const { return edgeland::test::filled(rule, w); }
  };
  return slab_region(rings, Sum{rule});
}

FilledRegion ogc_region(const std::vector<std::vector<Ring>>& polygons) {
  std::vector<Ring> rings;
  std::vector<int> weight;  // +1 exterior, -1 hole
  for (const auto& polygon : polygons)
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      rings.push_back(polygon[k]);
      weight.push_back(k == 0 ? 1 : -1);
    }
  // Per ring its own winding number; the value is the sum of the weights of the rings that
  // wind around the point at all.
  struct Indicators {
    const std::vector<int>* weight;
    std::vector<int> w;
    int value = 0;
    void reset() {
      w.assign(weight->size(), 0);
      value = 0;
    }
    void cross(std::size_t ring, int dir) {
      const bool before = w[ring] != 0;
      w[ring] += dir;
      value += (*weight)[ring] * ((w[ring] != 0) - int{before});
    }
    bool filled() const { return value > 0; }
  };
  return slab_region(rings, Indicators{&weight, {}, 0});
}

}  // namespace edgeland::test
