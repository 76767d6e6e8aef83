#pragma once
// The theorems proven about the kernel's arithmetic, one ctest test each (see README.md).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "symbolic_int.hpp"

namespace edgeland::proofs {

struct Theorem {
  Theorem(std::string n, std::string s, unsigned b, std::function<void(Prover&)> f)
      : name(std::move(n)), statement(std::move(s)), bits(b), body(std::move(f)) {}
  std::string name;
  std::string statement;  // what a proof of it means, in one line
  unsigned bits;          // machine width the formulas compute in
  // Runs the kernel's formulas on SymInt inputs; every operation is an obligation.
  std::function<void(Prover&)> body;
  // A theorem that must be REFUTED (the prover must find a counterexample), to show that a
  // failing obligation is detected. `replay` re-checks the counterexample with concrete
  // machine arithmetic and returns true when it really overflows.
  bool expect_refuted = false;
  std::function<bool(const Counterexample&)> replay;
};

std::vector<Theorem> predicate_theorems();   // orient, dot_from, line_intersection, normalizing
std::vector<Theorem> rounding_theorems();    // round_half_up: range, rule, output bound
std::vector<Theorem> area_theorems();        // twice-area accumulation (area.cpp)
std::vector<Theorem> centroid_theorems();    // moment sums and denominator (centroid.cpp)
std::vector<Theorem> refutation_theorems();  // orient in int64 at the int32 bound
std::vector<Theorem> probe_theorems();       // rays, exact points, closed pixels, grid sizing
std::vector<Theorem> shape_theorems();       // the shape builders (shapes.hpp)
std::vector<Theorem> portable_int128_theorems();  // the portable Int128's multiply

// Input coordinates, declared in this order (braced initialization evaluates left to right,
// so counterexamples list them in reading order).
struct PointTripleInputs {
  SymInt ax, ay, bx, by, cx, cy;
};
PointTripleInputs point_triple_inputs(Prover& prover);

// The inputs of formulas::line_intersection (segments p0->p1 and q0->q1) as coordinates.
struct SegmentPairInputs {
  SymInt p0x, p0y, p1x, p1y, q0x, q0y, q1x, q1y;
};
SegmentPairInputs segment_pair_inputs(Prover& prover);

}  // namespace edgeland::proofs
