// Bounded-exhaustive check of orientation() and orient_det() (predicates.hpp) on every point
// triple, quadruple and quintuple of a 5x5 grid: the small unit grid, and a 5x5 grid spread
// over the whole coordinate range. Properties (Knuth, "Axioms and Hulls", CC systems; his
// axioms are for points in general position, so each is checked where its premises hold):
//   exact     orient_det(p,q,r) equals the 3x3 determinant |p 1; q 1; r 1| expanded by
//             Sarrus's rule in cpp_int, and orientation() is its sign
//   axiom 1   cyclic symmetry: pqr == qrp
//   axiom 2   antisymmetry: pqr == -prq == -qpr
//   collinear repeated points are collinear; two points r, s on line pq (p != q) are
//             collinear with p and with q
//   axiom 4   interiority: tqr & ptr & pqt => pqr
//   identity  orient_det(p,q,r) = orient_det(t,q,r) + orient_det(p,t,r) + orient_det(p,q,t)
//   axiom 5   transitivity: tsp & tsq & tsr & tpq & tqr => tpr
//   axiom 5'  dual transitivity: stp & stq & str & tpq & tqr => tpr
// where pqr means orientation(p, q, r) == kCounterClockwise.
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "case_log.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "grids.hpp"

namespace edgeland::exhaustive {
namespace {

using boost::multiprecision::cpp_int;

cpp_int sarrus(Point64 a, Point64 b, Point64 c) {
  const cpp_int ax = a.x, ay = a.y, bx = b.x, by = b.y, cx = c.x, cy = c.y;
  return ax * by + bx * cy + cx * ay - cx * by - ax * cy - bx * ay;
}

std::string triple(Point64 p, Point64 q, Point64 r) { return str(p) + str(q) + str(r); }

// The orientation signs of all n^3 ordered triples, from the library.
class SignTable {
 public:
  explicit SignTable(const std::vector<Point64>& pts) : n_(pts.size()), s_(n_ * n_ * n_) {
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t j = 0; j < n_; ++j)
        for (std::size_t k = 0; k < n_; ++k)
          s_[(i * n_ + j) * n_ + k] = static_cast<signed char>(orientation(pts[i], pts[j], pts[k]));
  }
  int operator()(std::size_t i, std::size_t j, std::size_t k) const {
    return s_[(i * n_ + j) * n_ + k];
  }
  bool ccw(std::size_t i, std::size_t j, std::size_t k) const { return (*this)(i, j, k) > 0; }

 private:
  std::size_t n_;
  std::vector<signed char> s_;
};

bool check_grid(const char* name, const std::vector<Point64>& pts) {
  const std::size_t n = pts.size();
  const SignTable o(pts);
  const std::string g = std::string(" [") + name + "]";
  CaseLog exact("orient_det == Sarrus determinant, orientation == sign" + g);
  CaseLog cyclic("axiom 1 cyclic symmetry" + g), anti("axiom 2 antisymmetry" + g);
  CaseLog collinear("collinearity consistency" + g), interior("axiom 4 interiority" + g);
  CaseLog identity("orient_det 4-point identity" + g);
  CaseLog trans("axiom 5 transitivity" + g), dual("axiom 5' dual transitivity" + g);

  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < n; ++k) {
        const Point64 p = pts[i], q = pts[j], r = pts[k];
        const cpp_int det = sarrus(p, q, r);
        const int sign = det.sign();
        exact.expect(cpp_int(to_string(orient_det(p, q, r))) == det && o(i, j, k) == sign,
                     [&] { return triple(p, q, r); });
        cyclic.expect(o(i, j, k) == o(j, k, i), [&] { return triple(p, q, r); });
        anti.expect(o(i, j, k) == -o(i, k, j) && o(i, j, k) == -o(j, i, k),
                    [&] { return triple(p, q, r); });
        if (i == j || j == k || i == k) {
          collinear.expect(o(i, j, k) == 0, [&] { return triple(p, q, r) + " repeated point"; });
        }
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {        // p
    for (std::size_t j = 0; j < n; ++j) {      // q
      for (std::size_t k = 0; k < n; ++k) {    // r
        for (std::size_t l = 0; l < n; ++l) {  // t (or s)
          const Point64 p = pts[i], q = pts[j], r = pts[k], t = pts[l];
          if (i != j && o(i, j, k) == 0 && o(i, j, l) == 0) {
            collinear.expect(o(i, k, l) == 0 && o(j, k, l) == 0,
                             [&] { return triple(p, q, r) + str(t); });
          }
          if (o.ccw(l, j, k) && o.ccw(i, l, k) && o.ccw(i, j, l)) {
            interior.expect(o.ccw(i, j, k), [&] { return triple(p, q, r) + " t=" + str(t); });
          }
          identity.expect(orient_det(p, q, r) ==
                              orient_det(t, q, r) + orient_det(p, t, r) + orient_det(p, q, t),
                          [&] { return triple(p, q, r) + " t=" + str(t); });
        }
      }
    }
  }
  for (std::size_t it = 0; it < n; ++it) {
    for (std::size_t is = 0; is < n; ++is) {
      for (std::size_t ip = 0; ip < n; ++ip) {
        if (!o.ccw(it, is, ip) && !o.ccw(is, it, ip)) continue;  // prune: no premise holds
        for (std::size_t iq = 0; iq < n; ++iq) {
          if (!o.ccw(it, ip, iq)) continue;
          for (std::size_t ir = 0; ir < n; ++ir) {
            auto describe = [&] {
              return "t=" + str(pts[it]) + " s=" + str(pts[is]) + " p=" + str(pts[ip]) +
                     " q=" + str(pts[iq]) + " r=" + str(pts[ir]);
            };
            if (!o.ccw(it, iq, ir)) continue;
            if (o.ccw(it, is, ip) && o.ccw(it, is, iq) && o.ccw(it, is, ir)) {
              trans.expect(o.ccw(it, ip, ir), describe);
            }
            if (o.ccw(is, it, ip) && o.ccw(is, it, iq) && o.ccw(is, it, ir)) {
              dual.expect(o.ccw(it, ip, ir), describe);
            }
          }
        }
      }
    }
  }
  bool ok = true;
  for (const CaseLog* c :
       {&exact, &cyclic, &anti, &collinear, &interior, &identity, &trans, &dual}) {
    ok = c->report() && ok;
  }
  return ok;
}

}  // namespace
}  // namespace edgeland::exhaustive

int main() {
  using namespace edgeland::exhaustive;
  const bool unit = check_grid("5x5 unit grid", grid(5));
  const bool wide = check_grid("5x5 over the full range", full_range_grid(5));
  return unit && wide ? 0 : 1;
}
