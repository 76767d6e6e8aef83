// The proofs model arith::floor_div (checked.hpp) by Z3's integer division, which for a
// positive divisor is floor division. This check ties that model to the code: floor_div on
// Checked<Int128> satisfies the definition d*q <= n < d*(q+1) (verified in cpp_int) for
// every n in [-300, 300] and d in [1, 40], and for n near 0, +-2^64 and the ends of the
// Int128 range against divisors from 1 to 2^127 - 1. round_to_grid (the function built on
// it) then obeys the rounding rule for every num in [-80, 80] over den in [1, 24].
#include <boost/multiprecision/cpp_int.hpp>
#include <limits>
#include <string>
#include <vector>

#include "case_log.hpp"
#include "edgeland/kernel/checked.hpp"
#include "edgeland/kernel/predicates.hpp"

namespace edgeland::exhaustive {
namespace {

using boost::multiprecision::cpp_int;
using W = arith::Checked<Int128>;

cpp_int big(Int128 v) {
  const UInt128 u = unsigned_abs(v);
  cpp_int r = cpp_int(static_cast<std::uint64_t>(u >> 64)) << 64;
  r += static_cast<std::uint64_t>(u);
  return v < 0 ? cpp_int(-r) : r;
}

void check_floor(CaseLog& log, Int128 n, Int128 d) {
  const Int128 q = arith::floor_div(W(n), W(d)).v;
  const cpp_int N = big(n), D = big(d), Q = big(q);
  log.expect(D * Q <= N && N < D * (Q + 1),
             [&] { return to_string(n) + " / " + to_string(d) + " gave " + to_string(q); });
}

}  // namespace
}  // namespace edgeland::exhaustive

int main() {
  using namespace edgeland;
  using namespace edgeland::exhaustive;
  constexpr Int128 kMax = std::numeric_limits<Int128>::max();
  constexpr Int128 kMin = std::numeric_limits<Int128>::min();

  CaseLog small("floor_div(n, d) == floor(n / d), |n| <= 300, 1 <= d <= 40");
  for (Int128 n = -300; n <= 300; ++n) {
    for (Int128 d = 1; d <= 40; ++d) check_floor(small, n, d);
  }

  CaseLog extremes("floor_div at 0, +-2^64 and the ends of Int128");
  std::vector<Int128> numerators,
      divisors = {
          1,        2,        3,   7, Int128(1) << 63, Int128(1) << 64, (Int128(1) << 64) + 1,
          kMax / 2, kMax - 1, kMax};
  for (Int128 base : {Int128(0), Int128(1) << 64, -(Int128(1) << 64), kMin + 8, kMax - 8}) {
    for (int k = -8; k <= 8; ++k) numerators.push_back(base + k);
  }
  for (Int128 n : numerators) {
    for (Int128 d : divisors) check_floor(extremes, n, d);
  }

  CaseLog rule("round_to_grid(num/den): R - 1/2 <= num/den < R + 1/2");
  for (Int128 den = 1; den <= 24; ++den) {
    for (Int128 num = -80; num <= 80; ++num) {
      const Point64 r = round_to_grid(RationalPoint{num, -num, den});
      // 2*den*R - den <= 2*num < 2*den*R + den, per axis (the y axis rounds -num).
      auto obeys = [&](std::int64_t v, Int128 x) {
        return den * (2 * v - 1) <= 2 * x && 2 * x < den * (2 * v + 1);
      };
      rule.expect(obeys(r.x, num) && obeys(r.y, -num),
                  [&] { return to_string(num) + "/" + to_string(den) + " -> " + str(r); });
    }
  }
  const bool a = small.report(), b = extremes.report(), c = rule.report();
  return a && b && c ? 0 : 1;
}
