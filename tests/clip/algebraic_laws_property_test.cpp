// Algebraic laws of the four operations (issue 4, "Verification"), on generated valid inputs.
// Areas are compared "within the contract": each clipper output may differ from its exact
// result by at most that result's perimeter, so a law relating k outputs holds up to the sum
// of their k perimeter bounds (exact integers from the CGAL reference).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "generators.hpp"
#include "polygon_set_helpers.hpp"

namespace edgeland::test {
namespace {

// Runs op(a, b) in checked mode or fails the property with the exception's message.
PolygonSet run(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  const Outcome o = run_clip(op, a, b);
  if (!o.ok()) RC_FAIL(o.error);
  return o.result->polygons;
}

Rational area(const PolygonSet& s) { return Rational(BigInt(to_string(twice_area(s)))) / 2; }

// The exact perimeter bound of a OP b.
Rational slack(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  return Rational(ExactRegion::of(a).apply(op, ExactRegion::of(b)).perimeter_ceil());
}

// Area bound of the band within 1.5 of the boundary of the exact a OP b, which contains the
// symmetric difference of the output and the exact result (accuracy_contract.hpp, check 5).
Rational band(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  const ExactRegion r = ExactRegion::of(a).apply(op, ExactRegion::of(b));
  return 3 * Rational(r.perimeter_ceil()) + Rational(99, 14) * Rational(r.boundary_cycles());
}

PolygonSet concat(PolygonSet a, const PolygonSet& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::string law_failure(const std::string& law, const OperandPair& p, const Rational& lhs,
                        const Rational& rhs, const Rational& bound) {
  return law + ": " + lhs.str() + " vs " + rhs.str() + " (allowed " + bound.str() +
         ")\n  A = " + to_wkt(p.a) + "\n  B = " + to_wkt(p.b);
}

// A - B and A * B are computed from the same input edges, so together they must form a valid
// set (disjoint interiors), and they partition A up to the contract.
RC_GTEST_PROP(ClipLaws, IntersectionAndDifferencePartitionTheSubject, ()) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const PolygonSet inter = run(ClipOp::kIntersection, p.a, p.b);
  const PolygonSet diff = run(ClipOp::kDifference, p.a, p.b);
  const ValidationReport v = validate(concat(inter, diff));
  if (!v.ok())
    RC_FAIL("A*B and A-B overlap: " + v.violations.front().describe() + "\n  A = " + to_wkt(p.a) +
            "\n  B = " + to_wkt(p.b) + "\n  A*B = " + to_wkt(inter) + "\n  A-B = " + to_wkt(diff));
  const Rational bound =
      slack(ClipOp::kIntersection, p.a, p.b) + slack(ClipOp::kDifference, p.a, p.b);
  const Rational lhs = area(inter) + area(diff), rhs = area(p.a);
  if (abs(Rational(lhs - rhs)) > bound)
    RC_FAIL(law_failure("|A*B| + |A-B| = |A|", p, lhs, rhs, bound));
}

RC_GTEST_PROP(ClipLaws, UnionIsTheSumOfBothDifferencesAndTheIntersection, ()) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const Rational u = area(run(ClipOp::kUnion, p.a, p.b));
  const Rational parts = area(run(ClipOp::kDifference, p.a, p.b)) +
                         area(run(ClipOp::kIntersection, p.a, p.b)) +
                         area(run(ClipOp::kDifference, p.b, p.a));
  const Rational bound = slack(ClipOp::kUnion, p.a, p.b) + slack(ClipOp::kDifference, p.a, p.b) +
                         slack(ClipOp::kIntersection, p.a, p.b) +
                         slack(ClipOp::kDifference, p.b, p.a);
  if (abs(Rational(u - parts)) > bound)
    RC_FAIL(law_failure("|A+B| = |A-B| + |A*B| + |B-A|", p, u, parts, bound));
}

RC_GTEST_PROP(ClipLaws, XorIsUnionMinusIntersection, ()) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const Rational x = area(run(ClipOp::kXor, p.a, p.b));
  const Rational rhs =
      area(run(ClipOp::kUnion, p.a, p.b)) - area(run(ClipOp::kIntersection, p.a, p.b));
  const Rational bound = slack(ClipOp::kXor, p.a, p.b) + slack(ClipOp::kUnion, p.a, p.b) +
                         slack(ClipOp::kIntersection, p.a, p.b);
  if (abs(Rational(x - rhs)) > bound)
    RC_FAIL(law_failure("|A^B| = |A+B| - |A*B|", p, x, rhs, bound));
}

// The output is a function of the inputs: the same call twice gives the same bytes.
RC_GTEST_PROP(ClipLaws, EveryOperationIsDeterministic, ()) {
  const OperandPair p = *gen::operand_pair();
  const ClipOp op =
      *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor);
  RC_ASSERT(run(op, p.a, p.b) == run(op, p.a, p.b));
}

// Operations of a set with itself and with the empty set. The output of union with the empty
// set is the documented canonical form of the input (clip.hpp, CANONICAL OUTPUT), computed
// independently by canonical_form(); on a canonical set (a library output) union and
// intersection with itself and union/difference/xor with the empty set give it back
// byte-identical.
RC_GTEST_PROP(ClipLaws, OperationsWithItselfAndWithTheEmptySet, ()) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const PolygonSet& a = p.a;
  const PolygonSet none;
  const PolygonSet canon = canonical_form(a);
  auto expect = [&](const char* law, const PolygonSet& got, const PolygonSet& want) {
    if (got != want)
      RC_FAIL(std::string(law) + "\n  A = " + to_wkt(a) + "\n  got  " + to_wkt(got) + "\n  want " +
              to_wkt(want));
  };
  expect("A + {} = canonical(A)", run(ClipOp::kUnion, a, none), canon);
  expect("{} + A = canonical(A)", run(ClipOp::kUnion, none, a), canon);
  expect("A - {} = canonical(A)", run(ClipOp::kDifference, a, none), canon);
  expect("A ^ {} = canonical(A)", run(ClipOp::kXor, a, none), canon);
  expect("{} ^ A = canonical(A)", run(ClipOp::kXor, none, a), canon);
  expect("A * {} = {}", run(ClipOp::kIntersection, a, none), none);
  expect("{} * A = {}", run(ClipOp::kIntersection, none, a), none);
  expect("{} - A = {}", run(ClipOp::kDifference, none, a), none);
  expect("A + A = canonical(A)", run(ClipOp::kUnion, a, a), canon);
  expect("A * A = canonical(A)", run(ClipOp::kIntersection, a, a), canon);
  expect("A - A = {}", run(ClipOp::kDifference, a, a), none);
  expect("A ^ A = {}", run(ClipOp::kXor, a, a), none);
  // On a library output (canonical) the same operations are the identity, byte for byte.
  const PolygonSet c = run(ClipOp::kUnion, a, none);
  expect("C + C = C", run(ClipOp::kUnion, c, c), c);
  expect("C * C = C", run(ClipOp::kIntersection, c, c), c);
  expect("C + {} = C", run(ClipOp::kUnion, c, none), c);
  expect("C - {} = C", run(ClipOp::kDifference, c, none), c);
}

// The result of an operation is again a valid input, and a second identical operation with
// the same clip operand changes almost nothing for union, intersection and difference (they
// are idempotent as set operations: (A op B) op B = A op B). With S = A op B computed and
// R its exact value, |exact(S op B) - S| <= area(S xor R) <= band(R), and the second output
// is within its own contract of exact(S op B).
RC_GTEST_PROP(ClipLaws, RepeatingAnOperationWithTheSameClipIsStable, ()) {
  const OperandPair p = *gen::operand_pair();
  RC_TAG(p.scenario);
  const ClipOp op = *rc::gen::element(ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference);
  const PolygonSet once = run(op, p.a, p.b);
  const PolygonSet twice = run(op, once, p.b);
  const Rational bound = slack(op, once, p.b) + band(op, p.a, p.b);
  if (abs(Rational(area(twice) - area(once))) > bound)
    RC_FAIL(law_failure(std::string("(A op B) op B = A op B, op = ") + op_name(op), p, area(twice),
                        area(once), bound));
}

}  // namespace
}  // namespace edgeland::test
