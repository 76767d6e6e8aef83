#include "support/validate_bruteforce.hpp"

#include <algorithm>
#include <vector>

namespace edgeland::testing {
namespace {

using I128 = __int128;

// Cross product of (a - o) and (b - o); exact for |coordinates| < 2^62.
I128 cross(Point64 o, Point64 a, Point64 b) {
  return I128(a.x - o.x) * I128(b.y - o.y) - I128(a.y - o.y) * I128(b.x - o.x);
}

int sgn(I128 v) { return (v > 0) - (v < 0); }

bool between(std::int64_t lo, std::int64_t v, std::int64_t hi) {
  return std::min(lo, hi) <= v && v <= std::max(lo, hi);
}

// p lies on the closed segment a-b.
bool on_closed_segment(Point64 p, Point64 a, Point64 b) {
  return cross(a, b, p) == 0 && between(a.x, p.x, b.x) && between(a.y, p.y, b.y);
}

// Interiors of both segments cross at a single point.
bool proper_crossing(Point64 a0, Point64 a1, Point64 b0, Point64 b1) {
  const int d1 = sgn(cross(a0, a1, b0)), d2 = sgn(cross(a0, a1, b1));
  const int d3 = sgn(cross(b0, b1, a0)), d4 = sgn(cross(b0, b1, a1));
  return d1 * d2 < 0 && d3 * d4 < 0;
}

// Collinear with a common part of positive length, directed the same way.
bool same_direction_overlap(Point64 a0, Point64 a1, Point64 b0, Point64 b1) {
  if (cross(a0, a1, b0) != 0 || cross(a0, a1, b1) != 0) return false;
  const I128 dx = a1.x - a0.x, dy = a1.y - a0.y;
  auto along = [&](Point64 p) { return I128(p.x - a0.x) * dx + I128(p.y - a0.y) * dy; };
  const I128 b_lo = std::min(along(b0), along(b1)), b_hi = std::max(along(b0), along(b1));
  const I128 lo = std::max<I128>(0, b_lo), hi = std::min<I128>(dx * dx + dy * dy, b_hi);
  return lo < hi && along(b1) > along(b0);
}

// Winding number of `ring` around p, all coordinates doubled; returns -1 for "on the boundary"
// encoded separately through `on_boundary`.
int winding_doubled(const Ring& ring, Point64 p2, bool& on_boundary) {
  on_boundary = false;
  int wn = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 a{2 * ring[i].x, 2 * ring[i].y};
    const Point64 b{2 * ring[(i + 1) % n].x, 2 * ring[(i + 1) % n].y};
    if (on_closed_segment(p2, a, b)) {
      on_boundary = true;
      return 0;
    }
    if (a.y <= p2.y) {
      if (b.y > p2.y && cross(a, b, p2) > 0) ++wn;
    } else if (b.y <= p2.y && cross(a, b, p2) < 0) {
      --wn;
    }
  }
  return wn;
}

// Some piece of an edge of `a`, cut at the vertices of `b` on it, runs strictly inside `b`.
bool edge_piece_inside(const Ring& a, const Ring& b) {
  const std::size_t n = a.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point64 p = a[i], q = a[(i + 1) % n];
    std::vector<Point64> cuts{p, q};
    for (const Point64 v : b) {
      if (on_closed_segment(v, p, q)) cuts.push_back(v);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const Point64 mid2{cuts[k].x + cuts[k + 1].x, cuts[k].y + cuts[k + 1].y};
      bool on_boundary = false;
      if (winding_doubled(b, mid2, on_boundary) != 0 && !on_boundary) return true;
    }
  }
  return false;
}

bool in_bound(Point64 p) {
  return -kCoordBound <= p.x && p.x <= kCoordBound && -kCoordBound <= p.y && p.y <= kCoordBound;
}

I128 twice_area_shoelace(const Ring& r) {
  I128 s = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point64 a = r[i], b = r[(i + 1) % r.size()];
    s += I128(a.x) * I128(b.y) - I128(b.x) * I128(a.y);
  }
  return s;
}

}  // namespace

bool bruteforce_segments_meet(Point64 a0, Point64 a1, Point64 b0, Point64 b1) {
  if (proper_crossing(a0, a1, b0, b1)) return true;
  return on_closed_segment(a0, b0, b1) || on_closed_segment(a1, b0, b1) ||
         on_closed_segment(b0, a0, a1) || on_closed_segment(b1, a0, a1);
}

bool bruteforce_interiors_overlap(const Ring& a, const Ring& b) {
  // Boxes that meet at most along their border leave no room for a common interior point.
  auto box = [](const Ring& r) {
    Point64 lo = r[0], hi = r[0];
    for (const Point64 p : r) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = box(a);
  const auto [blo, bhi] = box(b);
  if (std::max(alo.x, blo.x) >= std::min(ahi.x, bhi.x) ||
      std::max(alo.y, blo.y) >= std::min(ahi.y, bhi.y)) {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Point64 a0 = a[i], a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Point64 b0 = b[j], b1 = b[(j + 1) % b.size()];
      if (proper_crossing(a0, a1, b0, b1) || same_direction_overlap(a0, a1, b0, b1)) return true;
    }
  }
  return edge_piece_inside(a, b) || edge_piece_inside(b, a);
}

std::set<std::pair<Rule, std::size_t>> BruteForceFindings::rules_by_polygon() const {
  std::set<std::pair<Rule, std::size_t>> out;
  for (const auto& [rule, polygon, index] : ring_rules) out.emplace(rule, polygon);
  for (const auto& [polygon, e, f] : self_intersections) {
    out.emplace(Rule::kSelfIntersection, polygon);
  }
  for (const auto& [i, j] : overlaps) {
    out.emplace(Rule::kOverlappingInteriors, i);
    out.emplace(Rule::kOverlappingInteriors, j);
  }
  return out;
}

BruteForceFindings validate_bruteforce(const PolygonSet& set) {
  BruteForceFindings f;
  std::vector<std::size_t> valid;
  for (std::size_t p = 0; p < set.size(); ++p) {
    const Ring& r = set[p];
    const std::size_t n = r.size();
    if (n < 3) {
      f.ring_rules.emplace(Rule::kTooFewVertices, p, kNone);
      continue;
    }
    bool structural = true;
    for (std::size_t i = 0; i < n; ++i) {
      if (!in_bound(r[i])) {
        f.ring_rules.emplace(Rule::kCoordinateOutOfRange, p, i);
        structural = false;
      }
      if (r[i] == r[(i + 1) % n]) {
        f.ring_rules.emplace(Rule::kRepeatedVertex, p, i);
        structural = false;
      }
    }
    if (!structural) continue;
    bool simple = true;
    for (std::size_t i = 0; i < n; ++i) {
      const Point64 prev = r[(i + n - 1) % n], at = r[i], next = r[(i + 1) % n];
      if (on_closed_segment(next, prev, at) || on_closed_segment(prev, at, next)) {
        f.ring_rules.emplace(Rule::kSpike, p, (i + n - 1) % n);
        simple = false;
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // edges n-1 and 0 meet at vertex 0
        if (bruteforce_segments_meet(r[i], r[i + 1], r[j], r[(j + 1) % n])) {
          f.self_intersections.emplace(p, i, j);
          simple = false;
        }
      }
    }
    if (!simple) continue;
    if (twice_area_shoelace(r) <= 0) {
      f.ring_rules.emplace(Rule::kNotCounterClockwise, p, kNone);
      continue;
    }
    valid.push_back(p);
  }
  for (std::size_t a = 0; a < valid.size(); ++a) {
    for (std::size_t b = a + 1; b < valid.size(); ++b) {
      if (bruteforce_interiors_overlap(set[valid[a]], set[valid[b]])) {
        f.overlaps.emplace(valid[a], valid[b]);
      }
    }
  }
  return f;
}

}  // namespace edgeland::testing
