// centroid() (centroid.cpp) sums formulas::moment_term over every edge of the set, in Int128,
// and multiplies the total twice-area by 3 (formulas::centroid_denominator). Both stay in range
// for up to N = kMaxCentroidVertices (centroid.hpp) vertices in all. Proof as for the area sum
// (theorems_area.cpp), by induction over the running sum S_k after k terms:
//   a term is bounded: |(c_a + c_b) cross(a, b)| <= T = 4 B^3, proven on the formula itself
//   (with the lemma |cross(a, b)| <= 2 B^2 and cross generalized, a degree-2 question);
//   invariant |S_k| <= k*T; step: for k < N, S_k + term is in range and |S_k + term| <= (k+1)*T.
// N must satisfy N*T <= 2^127 - 1: the theorem uses the header's constant, so a constant too
// large fails the proof. The denominator: the total twice-area of at most N vertices is at most
// N * 2 B^2 in magnitude (area_sum_int128's invariant), and 3 times that fits.
#include <boost/multiprecision/cpp_int.hpp>

#include "edgeland/kernel/centroid.hpp"
#include "edgeland/kernel/formulas.hpp"
#include "edgeland/kernel/point.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

using boost::multiprecision::cpp_int;

const cpp_int kB = kCoordBound;
const cpp_int kCrossBound = 2 * kB * kB;
const cpp_int kTermBound = 4 * kB * kB * kB;
const cpp_int kMaxVertices = kMaxCentroidVertices;

z3::expr within(const z3::expr& v, const z3::expr& limit) { return -limit <= v && v <= limit; }

void centroid_sums(Prover& p) {
  const z3::expr T = p.num(kTermBound.str());
  const SymInt ax = p.coordinate("ax"), ay = p.coordinate("ay");
  const SymInt bx = p.coordinate("bx"), by = p.coordinate("by");
  const SymInt cross = formulas::cross<SymInt>(ax, ay, bx, by);
  p.establish("|cross(a, b)| <= 2 B^2", within(cross.term(), p.num(kCrossBound.str())));
  for (const bool along_x : {true, false}) {
    const SymInt& ca = along_x ? ax : ay;
    const SymInt& cb = along_x ? bx : by;
    const SymInt term = formulas::moment_term<SymInt>(ca, cb, ax, ay, bx, by);
    p.establish(
        std::string("|moment term ") + (along_x ? "x" : "y") + "| <= T = " + kTermBound.str(),
        within(term.term(), T), {cross.term()});
  }
  // One step of either sum: S_k + term, for k < N.
  const SymInt term = formulas::moment_term<SymInt>(ax, bx, ax, ay, bx, by);
  const SymInt k = p.integer("k", "0", cpp_int(kMaxVertices - 1).str());
  const SymInt s = p.integer("S_k", signed_min(p.bits()), signed_max(p.bits()));
  p.assume(within(s.term(), k.term() * T));
  const SymInt next = s + term;
  p.establish("|S_k + term| <= (k+1)*T", within(next.term(), (k.term() + 1) * T));
  // The denominator of at most N vertices' twice-area.
  const SymInt area = p.integer("A", signed_min(p.bits()), signed_max(p.bits()));
  p.assume(within(area.term(), p.num(cpp_int(kMaxVertices * kCrossBound).str())));
  formulas::centroid_denominator<SymInt>(area);
}

}  // namespace

std::vector<Theorem> centroid_theorems() {
  return {Theorem("centroid_sums_int128",
                  "centroid's moment sums of (c_a + c_b) cross(a, b) and 3 * twice-area fit "
                  "Int128 for up to N = " +
                      kMaxVertices.str() + " vertices in all",
                  128, centroid_sums)};
}

}  // namespace edgeland::proofs
