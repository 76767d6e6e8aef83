#pragma once
// A symbolic machine integer for proving the kernel's formulas (kernel/.../formulas.hpp) free
// of overflow, and the Prover that discharges its proof obligations with Z3.
//
// formulas.hpp is written once over a number type W. The library uses arith::Checked<Int128>;
// a proof instantiates the very same templates with W = SymInt. A SymInt carries an exact Z3
// integer term (theory of integers, not bit-vectors: see TOOLCHAIN.md) and the width of the
// signed machine type the operation computes in. Before every +, -, *, unary - and floor_div
// the Prover asks Z3 whether, under the theorem's hypotheses (every input coordinate within
// kCoordBound, plus any path condition), the exact result can leave
// [-2^(bits-1), 2^(bits-1) - 1]. "unsat" discharges the obligation. By induction over the
// operations, if every obligation is discharged, every machine intermediate equals the exact
// value, so the machine result is the exact one. "sat" yields a counterexample (the input
// values) and the proof fails; "unknown" (rlimit exhausted) fails too.
#include <z3++.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace edgeland::proofs {

class Prover;

class SymInt {
 public:
  SymInt(Prover& prover, z3::expr term, unsigned bits);
  // A literal inside a formula, e.g. W(2) in round_half_up: the current prover's width.
  explicit SymInt(std::int64_t constant);

  const z3::expr& term() const { return term_; }
  unsigned bits() const { return bits_; }
  Prover& prover() const { return *prover_; }

  friend SymInt operator+(const SymInt& a, const SymInt& b);
  friend SymInt operator-(const SymInt& a, const SymInt& b);
  friend SymInt operator*(const SymInt& a, const SymInt& b);
  friend SymInt operator-(const SymInt& a);
  // The absolute value as arith::magnitude: obliges |a| to be in range.
  friend SymInt magnitude(const SymInt& a);
  // Floor division as arith::floor_div: obliges the divisor to be positive (the only case the
  // kernel's floor_div supports) and the quotient to be in range. For a positive divisor
  // Z3's integer `div` is exactly floor division.
  friend SymInt floor_div(const SymInt& n, const SymInt& d);

 private:
  Prover* prover_;
  z3::expr term_;
  unsigned bits_;
};

// The input values of a failed obligation, as decimal text, in declaration order.
struct Counterexample {
  std::string obligation;
  std::vector<std::pair<std::string, std::string>> inputs;
  std::string value;  // the exact value that left the range (or the claim's terms)
};

// Thrown by the first obligation that is not discharged; the driver reports it.
struct ObligationFailed : std::runtime_error {
  enum class Kind { kRefuted, kUnknown };
  ObligationFailed(Kind k, Counterexample c, const std::string& message)
      : std::runtime_error(message), kind(k), counterexample(std::move(c)) {}
  Kind kind;
  Counterexample counterexample;
};

// The proof state of one theorem: hypotheses, declared inputs, discharged obligations.
// One Prover is active at a time (formula literals pick it up through current()).
class Prover {
 public:
  Prover(unsigned bits, unsigned rlimit, bool verbose);
  ~Prover();
  Prover(const Prover&) = delete;
  Prover& operator=(const Prover&) = delete;

  static Prover& current();

  z3::context& ctx() { return ctx_; }
  unsigned bits() const { return bits_; }

  // An input coordinate c with |c| <= kCoordBound (point.hpp), at the prover's width.
  SymInt coordinate(const std::string& name);
  // An input integer in [lo, hi] (decimal text), at the prover's width.
  SymInt integer(const std::string& name, const std::string& lo, const std::string& hi);
  // An integer numeral (decimal text, any size).
  z3::expr num(const std::string& decimal);
  z3::expr num(std::int64_t value);

  // Adds a hypothesis (a path condition or the premise of the theorem).
  void assume(const z3::expr& fact);
  // Proves `fact` under the current hypotheses, then keeps it as a hypothesis (a lemma).
  // Each term in `generalize` is replaced, in the hypotheses and in the fact alike, by a fresh
  // unconstrained constant before asking Z3. That is sound (every model of the original
  // query is one of the generalized query, with the constant set to the term's value) and
  // turns a degree-3 polynomial question into a degree-2 one Z3 answers at once.
  void establish(const std::string& claim, const z3::expr& fact,
                 const std::vector<z3::expr>& generalize = {});
  // The obligation behind every SymInt operation.
  z3::expr require_in_range(const char* op, const z3::expr& value, unsigned bits);

  int obligations() const { return obligations_; }
  double solver_seconds() const { return solver_seconds_; }

 private:
  // Proves `goal` under the hypotheses: unsat of (hypotheses && !goal). Throws otherwise.
  void discharge(const std::string& name, const z3::expr& goal, const z3::expr& shown_value,
                 const std::vector<z3::expr>& generalize = {});
  Counterexample counterexample(const std::string& name, const z3::model& m,
                                const z3::expr& shown_value) const;

  z3::context ctx_;
  unsigned bits_;
  unsigned rlimit_;
  bool verbose_;
  std::vector<z3::expr> hypotheses_;
  std::vector<std::pair<std::string, z3::expr>> inputs_;
  int generalized_ = 0;
  int obligations_ = 0;
  double solver_seconds_ = 0;
  Prover* previous_;
};

// Decimal text of 2^n, -(2^n), 2^n - 1 for range bounds.
std::string pow2(unsigned n);
std::string signed_min(unsigned bits);
std::string signed_max(unsigned bits);

}  // namespace edgeland::proofs
