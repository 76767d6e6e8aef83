// Twice the signed area (area.cpp, thesis 2.2) summed in Int128 cannot overflow for up to N
// vertices in total. twice_signed_area(ring) adds formulas::cross(p_i, p_(i+1)) over the
// ring's edges; twice_signed_area(set) adds the rings' results. Proof by induction over the
// running sum S_k after k terms:
//   a term is bounded: |cross(a, b)| <= T = 2 B^2 (proven on the formula itself);
//   invariant |S_k| <= k*T, base S_0 = 0;
//   step (ring): for k < N, S_k + term is in Int128 range (the addition's obligation) and
//   |S_k + term| <= (k+1)*T;
//   step (set): a ring of m vertices adds |A| <= m*T, so for k + m <= N the addition is in
//   range and the invariant holds with k + m.
// N = floor((2^127 - 1) / T).
#include <boost/multiprecision/cpp_int.hpp>

#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/point.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

using boost::multiprecision::cpp_int;

const cpp_int kB = kCoordBound;
const cpp_int kTermBound = 2 * kB * kB;  // |x_a*y_b - y_a*x_b| <= 2 B^2
const cpp_int kMaxVertices = ((cpp_int(1) << 127) - 1) / kTermBound;

z3::expr within(const z3::expr& v, const z3::expr& limit) { return -limit <= v && v <= limit; }

void area_sum(Prover& p) {
  const z3::expr T = p.num(kTermBound.str()), N = p.num(kMaxVertices.str());
  const SymInt ax = p.coordinate("ax"), ay = p.coordinate("ay");
  const SymInt bx = p.coordinate("bx"), by = p.coordinate("by");
  const SymInt term = formulas::cross<SymInt>(ax, ay, bx, by);
  p.establish("|cross(a, b)| <= T = " + kTermBound.str(), within(term.term(), T));

  // Ring step: S_k + term.
  const SymInt k = p.integer("k", "0", cpp_int(kMaxVertices - 1).str());
  const SymInt s = p.integer("S_k", signed_min(p.bits()), signed_max(p.bits()));
  p.assume(within(s.term(), k.term() * T));
  const SymInt next = s + term;
  p.establish("|S_k + term| <= (k+1)*T", within(next.term(), (k.term() + 1) * T));

  // Set step: S_k + A where A is the area of a ring of m vertices, k + m <= N.
  const SymInt m = p.integer("m", "0", kMaxVertices.str());
  const SymInt a = p.integer("A", signed_min(p.bits()), signed_max(p.bits()));
  p.assume(within(a.term(), m.term() * T) && k.term() + m.term() <= N);
  const SymInt total = s + a;
  p.establish("|S_k + A| <= (k+m)*T", within(total.term(), (k.term() + m.term()) * T));
}

// supporting_line (supporting_line.cpp): the offset cross(d, p) of a line whose direction d is
// a coordinate difference reduced by its gcd, so |d_x|, |d_y| <= 2 B.
void line_offset(Prover& p) {
  const std::string two_b = cpp_int(2 * kB).str(), minus_two_b = cpp_int(-2 * kB).str();
  const SymInt dx = p.integer("dx", minus_two_b, two_b), dy = p.integer("dy", minus_two_b, two_b);
  const SymInt px = p.coordinate("px"), py = p.coordinate("py");
  formulas::line_offset<SymInt>(dx, dy, px, py);
}

}  // namespace

std::vector<Theorem> area_theorems() {
  return {Theorem("area_sum_int128",
                  "twice_signed_area sums of cross(p_i, p_(i+1)) fit Int128 for up to N = " +
                      kMaxVertices.str() + " vertices in all",
                  128, area_sum),
          Theorem("line_offset_int128",
                  "supporting_line's offset cross(d, p) fits Int128 for |d| <= 2 kCoordBound", 128,
                  line_offset)};
}

}  // namespace edgeland::proofs
