// A theorem that is false on purpose: orient computed in int64 at the int32 coordinate bound.
// Its products reach about 2^64, so the prover must find a counterexample. The test passes
// only when it does AND the counterexample, replayed through the same formulas::orient
// template on real int64 arithmetic, really overflows. This shows that a failing obligation
// is detected and reported with its inputs (README.md, "A proof that must fail").
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>

#include "edgeland/kernel/formulas.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

// int64 arithmetic that wraps like the hardware but remembers the first overflow (orient
// needs only - and *).
struct ReplayInt64 {
  std::int64_t v = 0;
  static inline const char* first_overflow = nullptr;
  static void note(bool overflowed, const char* op) {
    if (overflowed && first_overflow == nullptr) first_overflow = op;
  }
  friend ReplayInt64 operator-(ReplayInt64 a, ReplayInt64 b) {
    std::int64_t r = 0;
    note(__builtin_sub_overflow(a.v, b.v, &r), "sub");
    return {r};
  }
  friend ReplayInt64 operator*(ReplayInt64 a, ReplayInt64 b) {
    std::int64_t r = 0;
    note(__builtin_mul_overflow(a.v, b.v, &r), "mul");
    return {r};
  }
};

bool replay_orient_int64(const Counterexample& c) {
  std::map<std::string, std::int64_t> in;
  for (const auto& [name, value] : c.inputs) in[name] = std::stoll(value);
  ReplayInt64::first_overflow = nullptr;
  const ReplayInt64 r = formulas::orient<ReplayInt64>({in["ax"]}, {in["ay"]}, {in["bx"]},
                                                      {in["by"]}, {in["cx"]}, {in["cy"]});
  std::printf("replay with real int64 arithmetic: %s (wrapped result %lld)\n",
              ReplayInt64::first_overflow ? ReplayInt64::first_overflow : "no overflow",
              static_cast<long long>(r.v));
  return ReplayInt64::first_overflow != nullptr;
}

}  // namespace

std::vector<Theorem> refutation_theorems() {
  Theorem t{"orient_int64_must_be_refuted",
            "orient computed in int64 with |coord| <= 2^31-1 overflows (expected: REFUTED)", 64,
            [](Prover& p) {
              const PointTripleInputs in = point_triple_inputs(p);
              formulas::orient<SymInt>(in.ax, in.ay, in.bx, in.by, in.cx, in.cy);
            }};
  t.expect_refuted = true;
  t.replay = replay_orient_int64;
  return {t};
}

}  // namespace edgeland::proofs
