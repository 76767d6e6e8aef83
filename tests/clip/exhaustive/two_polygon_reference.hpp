#pragma once
// A fast exact reference for one boolean operation on two simple polygons with small integer
// coordinates, in integers only, for the bounded-exhaustive checks (a million cases, too many
// for CGAL at ~0.1 ms per operation; it is cross-checked against CGAL on a sample).
//
// Every point is scaled by S = 2 * lcm(denominators of all proper crossings), so crossings and
// midpoints of sub-segments are integer points. Each edge of either polygon is split at every
// point where it meets the other polygon; each piece knows, on its left and on its right,
// whether it is inside A and inside B (left of a polygon's own edge is inside; for the other
// polygon, the midpoint decides, or the direction of a collinear edge through it). The exact
// boundary of a OP b is the set of pieces whose two sides differ, and the boundary of the
// output's pieces (clip/README.md: union keeps a whole and adds b - a) the set of pieces
// whose two side LABELS differ.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::test {

struct Scaled {
  Int128 x = 0, y = 0;
  friend bool operator==(const Scaled&, const Scaled&) = default;
  friend auto operator<=>(const Scaled&, const Scaled&) = default;
};

inline Int128 cross(const Scaled& o, const Scaled& a, const Scaled& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
inline Int128 dot(const Scaled& o, const Scaled& a, const Scaled& b) {
  return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y);
}

inline bool on_closed(const Scaled& p, const Scaled& a, const Scaled& b) {
  return cross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Squared distance from p to the closed segment ab compared with r2 (all scaled): the sign
// of dist^2 - r2, exactly.
inline int compare_distance(const Scaled& p, const Scaled& a, const Scaled& b, Int128 r2) {
  const Int128 len2 = dot(a, b, b);
  const Int128 t = dot(a, b, p);
  Int128 d2num, d2den = 1;
  if (t <= 0)
    d2num = dot(a, p, p);
  else if (t >= len2)
    d2num = dot(b, p, p);
  else {
    const Int128 c = cross(a, b, p);
    d2num = c * c;
    d2den = len2;
  }
  const Int128 lhs = d2num, rhs = r2 * d2den;
  return (lhs > rhs) - (lhs < rhs);
}

// std::lcm for Int128 (the standard's needs a built-in integer type; the portable build's
// Int128 is a class).
inline Int128 least_common_multiple(Int128 a, Int128 b) {
  Int128 x = a < 0 ? -a : a, y = b < 0 ? -b : b;
  const Int128 product_over = x;
  while (y != 0) {
    const Int128 r = x % y;
    x = y;
    y = r;
  }
  return x == 0 ? Int128(0) : product_over / x * (b < 0 ? -b : b);
}

class TwoPolygonReference {
 public:
  struct Piece {
    Scaled p, q;            // p < q
    bool in_a[2], in_b[2];  // [0]: left of p->q, [1]: right
  };

  TwoPolygonReference(const Polygon& a, const Polygon& b) : a_(a), b_(b) {
    Int128 lcm = 1;
    for_each_crossing([&](Int128 d) { lcm = least_common_multiple(lcm, d); });
    scale_ = 2 * lcm;
    for (int which = 0; which < 2; ++which) {
      const Polygon& self = which == 0 ? a_ : b_;
      for (std::size_t i = 0; i < self.size(); ++i) split_edge(which, i);
    }
    std::sort(pieces_.begin(), pieces_.end(),
              [](const Piece& u, const Piece& v) { return u.p != v.p ? u.p < v.p : u.q < v.q; });
    pieces_.erase(
        std::unique(pieces_.begin(), pieces_.end(),
                    [](const Piece& u, const Piece& v) { return u.p == v.p && u.q == v.q; }),
        pieces_.end());
  }

  Int128 scale() const { return scale_; }
  Scaled scaled(Point64 p) const { return {Int128(p.x) * scale_, Int128(p.y) * scale_}; }
  const std::vector<Piece>& pieces() const { return pieces_; }

  static bool result(ClipOp op, bool a, bool b) {
    switch (op) {
      case ClipOp::kUnion:
        return a || b;
      case ClipOp::kIntersection:
        return a && b;
      case ClipOp::kDifference:
        return a && !b;
      case ClipOp::kXor:
        return a != b;
    }
    return false;
  }
  // The output piece a point belongs to (0: none), clip/README.md's operation table.
  static int label(ClipOp op, bool a, bool b) {
    switch (op) {
      case ClipOp::kUnion:
        return a ? 1 : b ? 2 : 0;
      case ClipOp::kIntersection:
        return a && b ? 1 : 0;
      case ClipOp::kDifference:
        return a && !b ? 1 : 0;
      case ClipOp::kXor:
        return a && !b ? 1 : b && !a ? 2 : 0;
    }
    return 0;
  }
  static bool on_result_boundary(ClipOp op, const Piece& s) {
    return result(op, s.in_a[0], s.in_b[0]) != result(op, s.in_a[1], s.in_b[1]);
  }
  static bool on_piece_boundary(ClipOp op, const Piece& s) {
    return label(op, s.in_a[0], s.in_b[0]) != label(op, s.in_a[1], s.in_b[1]);
  }

  // Twice the exact area of a OP b, times S^2.
  Int128 twice_area_scaled(ClipOp op) const {
    Int128 sum = 0;
    for (const Piece& s : pieces_) {
      if (!on_result_boundary(op, s)) continue;
      const bool inside_left = result(op, s.in_a[0], s.in_b[0]);
      const Scaled &u = inside_left ? s.p : s.q, &v = inside_left ? s.q : s.p;
      sum += u.x * v.y - u.y * v.x;
    }
    return sum;
  }

  // Sum over the boundary pieces of ceil(length): an integer >= the exact perimeter.
  Int128 perimeter_ceil(ClipOp op) const {
    Int128 sum = 0;
    for (const Piece& s : pieces_) {
      if (!on_result_boundary(op, s)) continue;
      const Int128 len2 = dot(s.p, s.q, s.q);
      Int128 k =
          static_cast<Int128>(std::sqrt(static_cast<double>(len2)) / static_cast<double>(scale_));
      while (k > 0 && (k - 1) * (k - 1) * scale_ * scale_ >= len2) --k;
      while (k * k * scale_ * scale_ < len2) ++k;
      sum += k;
    }
    return sum;
  }

  // Whether the boundary of a OP b (or of the output's pieces) comes within sqrt(r2)/S of p.
  bool near_boundary(ClipOp op, const Scaled& p, Int128 r2, bool pieces_too) const {
    for (const Piece& s : pieces_) {
      const bool b = pieces_too ? on_piece_boundary(op, s) : on_result_boundary(op, s);
      if (b && compare_distance(p, s.p, s.q, r2) <= 0) return true;
    }
    return false;
  }

  // Whether p is in the closure of a OP b.
  bool in_closure(ClipOp op, const Scaled& p) const {
    // On a piece, p touches exactly the sides of the pieces through it.
    bool on_any = false;
    for (const Piece& s : pieces_)
      if (on_closed(p, s.p, s.q)) {
        on_any = true;
        if (result(op, s.in_a[0], s.in_b[0]) || result(op, s.in_a[1], s.in_b[1])) return true;
      }
    return !on_any && result(op, inside(a_, p), inside(b_, p));
  }

  // Strictly inside (p not on the ring).
  bool inside(const Polygon& poly, const Scaled& p) const {
    int w = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Scaled u = scaled(poly[i]), v = scaled(poly[(i + 1) % poly.size()]);
      if (u.y <= p.y && v.y > p.y && cross(u, v, p) > 0) ++w;
      if (u.y > p.y && v.y <= p.y && cross(u, v, p) < 0) --w;
    }
    return w != 0;
  }

 private:
  // Calls f(|d|) for every proper crossing at a non-vertex point, d its denominator.
  template <class F>
  void for_each_crossing(F&& f) const {
    for (std::size_t i = 0; i < a_.size(); ++i)
      for (std::size_t j = 0; j < b_.size(); ++j) {
        Int128 d, t, u;
        if (crossing(a_[i], a_[(i + 1) % a_.size()], b_[j], b_[(j + 1) % b_.size()], d, t, u)) f(d);
      }
  }

  // Segment pq against rs: true for a single common point p + (t/d)(q - p) with d > 0,
  // 0 <= t <= d, 0 <= u <= d (u along rs).
  static bool crossing(Point64 p, Point64 q, Point64 r, Point64 s, Int128& d, Int128& t,
                       Int128& u) {
    const Int128 ex = q.x - p.x, ey = q.y - p.y, fx = s.x - r.x, fy = s.y - r.y;
    d = ex * fy - ey * fx;
    if (d == 0) return false;
    const Int128 wx = r.x - p.x, wy = r.y - p.y;
    t = wx * fy - wy * fx;
    u = wx * ey - wy * ex;
    if (d < 0) {
      d = -d;
      t = -t;
      u = -u;
    }
    return 0 <= t && t <= d && 0 <= u && u <= d;
  }

  void split_edge(int which, std::size_t i) {
    const Polygon& self = which == 0 ? a_ : b_;
    const Polygon& other = which == 0 ? b_ : a_;
    const Point64 p = self[i], q = self[(i + 1) % self.size()];
    const Scaled sp = scaled(p), sq = scaled(q);
    std::vector<Scaled> pts{sp, sq};
    for (std::size_t j = 0; j < other.size(); ++j) {
      const Point64 r = other[j], s = other[(j + 1) % other.size()];
      const Scaled sr = scaled(r);
      if (on_closed(sr, sp, sq)) pts.push_back(sr);
      Int128 d, t, u;
      if (crossing(p, q, r, s, d, t, u))
        pts.push_back({sp.x + (sq.x - sp.x) / d * t, sp.y + (sq.y - sp.y) / d * t});
    }
    std::sort(pts.begin(), pts.end(),
              [&](const Scaled& x, const Scaled& y) { return dot(sp, sq, x) < dot(sp, sq, y); });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      const Scaled u = pts[k], v = pts[k + 1];
      const Scaled mid{(u.x + v.x) / 2, (u.y + v.y) / 2};
      bool self_side[2] = {true, false};
      bool other_side[2];
      const int on = on_other_edge(other, mid, u, v);
      if (on == 0)
        other_side[0] = other_side[1] = inside(other, mid);
      else {
        other_side[0] = on > 0;  // same direction: its inside is on our left
        other_side[1] = on < 0;
      }
      Piece piece;
      piece.p = u;
      piece.q = v;
      for (int side = 0; side < 2; ++side) {
        piece.in_a[side] = which == 0 ? self_side[side] : other_side[side];
        piece.in_b[side] = which == 0 ? other_side[side] : self_side[side];
      }
      if (v < u) {  // store as p < q: the sides swap
        std::swap(piece.p, piece.q);
        std::swap(piece.in_a[0], piece.in_a[1]);
        std::swap(piece.in_b[0], piece.in_b[1]);
      }
      pieces_.push_back(piece);
    }
  }

  // +1 / -1 when mid lies on an edge of `other` running in the same / opposite direction as
  // u->v (necessarily collinear: the piece crosses nothing), 0 when on none.
  int on_other_edge(const Polygon& other, const Scaled& mid, const Scaled& u,
                    const Scaled& v) const {
    for (std::size_t j = 0; j < other.size(); ++j) {
      const Scaled r = scaled(other[j]), s = scaled(other[(j + 1) % other.size()]);
      if (!on_closed(mid, r, s)) continue;
      const Int128 dir = (v.x - u.x) * (s.x - r.x) + (v.y - u.y) * (s.y - r.y);
      return dir > 0 ? 1 : -1;
    }
    return 0;
  }

  Polygon a_, b_;
  Int128 scale_ = 2;
  std::vector<Piece> pieces_;
};

}  // namespace edgeland::test
