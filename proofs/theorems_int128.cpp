// The portable Int128's multiply (kernel/.../portable_int128.hpp), proven on its own templates:
// multiply_words (64 x 64 -> 128 bits on 32-bit halves) and multiply_wrapping (128 x 128 bits
// modulo 2^128), instantiated with a symbolic word. Every word operation the templates perform
// is an obligation: + on words and half_product must not wrap (the code relies on that), half_up
// must get a value below 2^32; wrapping_add and wrapping_mul are defined modulo 2^64, as
// uint64_t's. The native __int128 needs none of this; MSVC and the portable build run exactly this
// code.
#include <string>
#include <vector>

#include "edgeland/kernel/portable_int128.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

// A 64-bit unsigned machine word as an exact Z3 integer in [0, 2^64 - 1].
struct Word {
  z3::expr v;
};

z3::expr pow2_expr(unsigned n) { return Prover::current().num(pow2(n)); }

// The exact result of an operation that must not wrap: its range is an obligation.
Word no_wrap(const char* op, const z3::expr& exact) {
  Prover& p = Prover::current();
  p.establish(std::string(op) + " stays in [0, 2^64 - 1]", 0 <= exact && exact < pow2_expr(64));
  return {exact};
}

Word operator+(const Word& a, const Word& b) { return no_wrap("word +", a.v + b.v); }
// Both factors below 2^32, so the product is at most (2^32 - 1)^2: proven, and kept as the
// bound the sums of products are then checked against.
Word half_product(const Word& a, const Word& b) {
  Prover& p = Prover::current();
  const z3::expr h = pow2_expr(32);
  p.establish("half_product gets halves (< 2^32)", 0 <= a.v && a.v < h && 0 <= b.v && b.v < h);
  const z3::expr product = a.v * b.v;
  p.establish("a half product is at most (2^32 - 1)^2",
              0 <= product && product <= (h - 1) * (h - 1));
  return {product};
}
Word low_half(const Word& x) { return {z3::mod(x.v, pow2_expr(32))}; }
Word high_half(const Word& x) { return {x.v / pow2_expr(32)}; }  // Int div: floor for x >= 0
Word half_up(const Word& x) {
  Prover::current().establish("half_up gets a half (< 2^32)", x.v < pow2_expr(32));
  return {x.v * pow2_expr(32)};
}
Word wrapping_add(const Word& a, const Word& b) { return {z3::mod(a.v + b.v, pow2_expr(64))}; }
Word wrapping_mul(const Word& a, const Word& b) { return {z3::mod(a.v * b.v, pow2_expr(64))}; }

Word word(Prover& p, const std::string& name) {
  return {p.integer(name, "0", signed_max(65)).term()};  // [0, 2^64 - 1]
}

using Words = detail::wide::WordPair<Word>;

// The schoolbook identity on halves, a b = a1 b1 2^64 + (a0 b1 + a1 b0) 2^32 + a0 b0, as a
// lemma over the very product terms multiply_words formed; with the products then generalized
// to free integers, the claims about the words are linear (but for div and mod by constants).
std::vector<z3::expr> halves_lemma(Prover& p, const Word& a, const Word& b) {
  const z3::expr h = pow2_expr(32);
  const z3::expr a0 = low_half(a).v, a1 = high_half(a).v, b0 = low_half(b).v, b1 = high_half(b).v;
  p.establish("a = a1 2^32 + a0, b = b1 2^32 + b0", a.v == a1 * h + a0 && b.v == b1 * h + b0);
  const std::vector<z3::expr> products = {a0 * b0, a0 * b1, a1 * b0, a1 * b1};
  p.establish("a b = a1 b1 2^64 + (a0 b1 + a1 b0) 2^32 + a0 b0",
              a.v * b.v == products[3] * h * h + (products[1] + products[2]) * h + products[0],
              {a0, a1, b0, b1});
  std::vector<z3::expr> generalized = products;
  generalized.push_back(a.v * b.v);
  return generalized;
}

void multiply_words(Prover& p) {
  const Word a = word(p, "a"), b = word(p, "b");
  const Words r = detail::wide::multiply_words(a, b);
  p.establish("lo < 2^64 and hi < 2^64", r.lo.v < pow2_expr(64) && r.hi.v < pow2_expr(64));
  p.establish("hi 2^64 + lo = a b", r.hi.v * pow2_expr(64) + r.lo.v == a.v * b.v,
              halves_lemma(p, a, b));
}

void multiply_wrapping(Prover& p) {
  const Words a{word(p, "a.lo"), word(p, "a.hi")}, b{word(p, "b.lo"), word(p, "b.hi")};
  const Words r = detail::wide::multiply_wrapping(a, b);
  const z3::expr w = pow2_expr(64);
  // multiply_words' claim for the low words, as proven by the theorem above.
  const Words low = detail::wide::multiply_words(a.lo, b.lo);
  std::vector<z3::expr> products = halves_lemma(p, a.lo, b.lo);
  p.establish("low.hi 2^64 + low.lo = a.lo b.lo", low.hi.v * w + low.lo.v == a.lo.v * b.lo.v,
              products);
  // The product expanded over the words; then every word product a free integer.
  const z3::expr product = (a.hi.v * w + a.lo.v) * (b.hi.v * w + b.lo.v);
  const std::vector<z3::expr> cross = {a.lo.v * b.lo.v, a.lo.v * b.hi.v, a.hi.v * b.lo.v,
                                       a.hi.v * b.hi.v};
  p.establish("(a b) = words' products",
              product == cross[3] * w * w + (cross[1] + cross[2]) * w + cross[0],
              {a.lo.v, a.hi.v, b.lo.v, b.hi.v});
  products.insert(products.end(), cross.begin(), cross.end());
  products.push_back(product);
  p.establish("hi 2^64 + lo = (a b) mod 2^128", r.hi.v * w + r.lo.v == z3::mod(product, w * w),
              products);
}

// checked.hpp's 128-bit overflow test on magnitudes: with limit = 2^127 (a negative product) or
// 2^127 - 1, `ub > limit / ua` exactly when the product passes the limit.
void multiply_overflow_test(Prover& p, bool negative) {
  const z3::expr ua = p.integer("|a|", "1", signed_max(129)).term();
  const z3::expr ub = p.integer("|b|", "0", signed_max(129)).term();
  const z3::expr limit = negative ? pow2_expr(127) : pow2_expr(127) - 1;
  p.establish("ub > limit / ua <=> ua ub > limit", (ub > limit / ua) == (ua * ub > limit));
}

}  // namespace

std::vector<Theorem> portable_int128_theorems() {
  std::vector<Theorem> t;
  t.push_back({"portable_multiply_words",
               "multiply_words: no step wraps a 64-bit word, hi 2^64 + lo = a b", 128,
               multiply_words});
  t.push_back({"portable_multiply_wrapping",
               "multiply_wrapping: hi 2^64 + lo = (a b) mod 2^128 for all words", 128,
               multiply_wrapping});
  t.push_back({"portable_multiply_overflow_test",
               "mul_overflows: |b| > limit / |a| exactly when |a b| > limit (2^127, 2^127 - 1)",
               128, [](Prover& p) {
                 multiply_overflow_test(p, true);
                 multiply_overflow_test(p, false);
               }});
  return t;
}

}  // namespace edgeland::proofs
