// Peers' test suites and bug reports, run through edgeland (tests/peers/README.md): every input
// pair that Boost.Geometry, GEOS/JTS, Clipper/Clipper2 and CGAL test their overlays with or
// were reported to fail on, scaled to the integer grid (integer_operands.hpp), is
//   * imported as OGC polygons (import_polygons) and normalized under every fill rule, each
//     result checked against the exact winding-number region (winding_reference.hpp);
//   * clipped by every operation, both differences, in checked mode: each output must be
//     valid and meet clip.hpp's accuracy contract against CGAL's exact result
//     (accuracy_contract.hpp), and is fed back into one more operation (xor with its subject,
//     which maps every result onto another: (A op B) xor A), checked the same way.
// No output of edgeland is stored anywhere: the only oracle is the exact reference.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"
#include "integer_operands.hpp"
#include "winding_reference.hpp"

namespace edgeland::test {
namespace {

const std::vector<ScaledCase>& all_cases() {
  static const std::vector<ScaledCase> cases = [] {
    std::vector<ScaledCase> out;
    for (const PeerCase& peer : read_peer_case_dir(EDGELAND_PEER_DATA_DIR)) {
      auto variants = scaled_variants(peer);
      out.insert(out.end(), variants.begin(), variants.end());
    }
    return out;
  }();
  return cases;
}

std::string describe(const ScaledCase& c) {
  return c.peer.file + ".wkt:" + std::to_string(c.peer.line) + " case " + c.peer.name + " from " +
         c.peer.source + ", coordinates x 10^" + std::to_string(c.power) +
         (c.scaling == Scaling::kFine     ? " (fine)"
          : c.scaling == Scaling::kCoarse ? " (coarse)"
                                          : " (the peer's own grid)");
}

std::vector<Point64> vertices_of(const std::vector<Ring>& rings) {
  std::vector<Point64> v;
  for (const Ring& r : rings) v.insert(v.end(), r.begin(), r.end());
  return v;
}

// Under the sanitizers (EDGELAND_PEERS_WITHOUT_ORACLE) the exact reference is left out: its
// CGAL lazy numbers, slow under ASan's allocator, were most of that pass's time, and the
// sanitizers are there for edgeland's code, which runs the same without it. Every output is
// still validated and fed on; the gcc pass checks each against the reference.
#ifdef EDGELAND_PEERS_WITHOUT_ORACLE
constexpr bool kExactOracle = false;
#else
constexpr bool kExactOracle = true;
#endif

// `o` is the region `exact_of()` computes, of `rings` under some rule: valid, and within the
// contract.
template <class Exact>
void expect_region(Exact&& exact_of, const std::vector<Ring>& rings, const Outcome& o,
                   const std::string& what) {
  ASSERT_TRUE(o.ok()) << what << ": " << o.error;
  const ValidationReport report = validate(o.result->polygons);
  EXPECT_TRUE(report.ok()) << what << ": invalid output " << to_wkt(o.result->polygons);
  if (!kExactOracle) return;
  const FilledRegion exact = exact_of();
  ASSERT_EQ(exact.region.area(), exact.trapezoid_area) << "reference broken for " << what;
  const ContractReport contract =
      check_contract(exact_region(exact.region), *o.result, vertices_of(rings),
                     what + " rings = " + to_wkt(PolygonSet(rings.begin(), rings.end())));
  EXPECT_TRUE(contract.ok()) << contract.failure;
}

// `o` is the fill of `rings` by `rule`.
void expect_fill(const std::vector<Ring>& rings, FillRule rule, const Outcome& o,
                 const std::string& what) {
  expect_region([&] { return filled_region(rings, rule); }, rings, o,
                what + " " + fill_rule_name(rule));
}

// One clip in checked mode: valid output meeting the contract. Returns the output if any.
std::optional<PolygonSet> expect_clip(ClipOp op, const PolygonSet& s, const PolygonSet& c,
                                      const std::string& what) {
  const Outcome o = run_clip(op, s, c);
  EXPECT_TRUE(o.ok()) << what << ": " << o.error;
  if (!o.ok()) return std::nullopt;
  EXPECT_TRUE(validate(o.result->polygons).ok())
      << what << ": invalid output " << to_wkt(o.result->polygons) << "\n  "
      << describe_case(op, s, c);
  if (!kExactOracle) return o.result->polygons;
  const ContractReport contract = check_clip(op, s, c, *o.result);
  EXPECT_TRUE(contract.ok()) << what << ": " << contract.failure;
  return o.result->polygons;
}

class PeerCases : public ::testing::TestWithParam<std::size_t> {
 protected:
  const ScaledCase& peer_case() const { return all_cases()[GetParam()]; }
};

TEST_P(PeerCases, OperandsImportAsTheirExactOgcRegion) {
  const ScaledCase& c = peer_case();
  SCOPED_TRACE(describe(c));
  for (const IntegerPolygons* operand : {&c.a, &c.b})
    expect_region([&] { return ogc_region(*operand); }, all_rings(*operand), run_import(*operand),
                  operand == &c.a ? "import a" : "import b");
}

TEST_P(PeerCases, RawRingsNormalizeUnderEveryFillRule) {
  const ScaledCase& c = peer_case();
  SCOPED_TRACE(describe(c));
  for (const IntegerPolygons* operand : {&c.a, &c.b}) {
    const std::vector<Ring> rings = all_rings(*operand);
    for (FillRule rule :
         {FillRule::kEvenOdd, FillRule::kNonZero, FillRule::kPositive, FillRule::kNegative})
      expect_fill(rings, rule, run_normalize(rings, rule),
                  std::string("normalize ") + (operand == &c.a ? "a" : "b"));
  }
}

TEST_P(PeerCases, EveryOperationMeetsTheContractAndFeedsTheNext) {
  const ScaledCase& c = peer_case();
  SCOPED_TRACE(describe(c));
  const Outcome a = run_import(c.a), b = run_import(c.b);
  ASSERT_TRUE(a.ok()) << a.error;
  ASSERT_TRUE(b.ok()) << b.error;
  const PolygonSet& pa = a.result->polygons;
  const PolygonSet& pb = b.result->polygons;
  struct Step {
    ClipOp op;
    const PolygonSet& subject;
    const PolygonSet& clip;
    const char* name;
  };
  for (const Step& step : {Step{ClipOp::kUnion, pa, pb, "a union b"},
                           Step{ClipOp::kIntersection, pa, pb, "a intersection b"},
                           Step{ClipOp::kDifference, pa, pb, "a difference b"},
                           Step{ClipOp::kDifference, pb, pa, "b difference a"},
                           Step{ClipOp::kXor, pa, pb, "a xor b"}}) {
    const auto out = expect_clip(step.op, step.subject, step.clip, step.name);
    // Closure: the output is an input like any other.
    if (out)
      expect_clip(ClipOp::kXor, *out, step.subject, std::string("(") + step.name + ") xor subject");
  }
}

std::string parameter_name(const ::testing::TestParamInfo<std::size_t>& info) {
  return all_cases()[info.param].test_name;
}

INSTANTIATE_TEST_SUITE_P(Peers, PeerCases, ::testing::Range<std::size_t>(0, all_cases().size()),
                         parameter_name);

}  // namespace
}  // namespace edgeland::test
