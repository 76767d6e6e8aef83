#include "symbolic_int.hpp"

#include <boost/multiprecision/cpp_int.hpp>
#include <chrono>
#include <cstdio>

#include "edgeland/kernel/point.hpp"

namespace edgeland::proofs {
namespace {

thread_local Prover* active_prover = nullptr;

unsigned common_width(const SymInt& a, const SymInt& b) {
  if (a.bits() != b.bits()) throw std::logic_error("SymInt: operands of different widths");
  return a.bits();
}

// Z3 prints huge terms; an obligation line shows only their start.
std::string shorten(std::string text, std::size_t limit = 90) {
  for (char& c : text) {
    if (c == '\n') c = ' ';
  }
  if (text.size() > limit) text = text.substr(0, limit - 3) + "...";
  return text;
}

}  // namespace

std::string pow2(unsigned n) { return (boost::multiprecision::cpp_int(1) << n).str(); }
std::string signed_min(unsigned bits) { return "-" + pow2(bits - 1); }
std::string signed_max(unsigned bits) {
  return ((boost::multiprecision::cpp_int(1) << (bits - 1)) - 1).str();
}

SymInt::SymInt(Prover& prover, z3::expr term, unsigned bits)
    : prover_(&prover), term_(std::move(term)), bits_(bits) {}

SymInt::SymInt(std::int64_t constant)
    : SymInt(Prover::current(), Prover::current().num(constant), Prover::current().bits()) {}

SymInt operator+(const SymInt& a, const SymInt& b) {
  const unsigned bits = common_width(a, b);
  const z3::expr r = a.term() + b.term();
  return SymInt(a.prover(), a.prover().require_in_range("add", r, bits), bits);
}

SymInt operator-(const SymInt& a, const SymInt& b) {
  const unsigned bits = common_width(a, b);
  const z3::expr r = a.term() - b.term();
  return SymInt(a.prover(), a.prover().require_in_range("sub", r, bits), bits);
}

SymInt operator*(const SymInt& a, const SymInt& b) {
  const unsigned bits = common_width(a, b);
  const z3::expr r = a.term() * b.term();
  return SymInt(a.prover(), a.prover().require_in_range("mul", r, bits), bits);
}

SymInt operator-(const SymInt& a) {
  const z3::expr r = -a.term();
  return SymInt(a.prover(), a.prover().require_in_range("neg", r, a.bits()), a.bits());
}

SymInt magnitude(const SymInt& a) {
  // As arith::magnitude: a, or -a when a < 0 (the negation is the operation that can overflow).
  const z3::expr r = z3::ite(a.term() < 0, -a.term(), a.term());
  return SymInt(a.prover(), a.prover().require_in_range("abs", r, a.bits()), a.bits());
}

SymInt floor_div(const SymInt& n, const SymInt& d) {
  const unsigned bits = common_width(n, d);
  Prover& p = n.prover();
  p.establish("floor_div divisor > 0", d.term() > 0);
  const z3::expr q = z3::expr(n.term() / d.term());  // Int division: floor for d > 0
  return SymInt(p, p.require_in_range("floor_div", q, bits), bits);
}

Prover::Prover(unsigned bits, unsigned rlimit, bool verbose)
    : bits_(bits), rlimit_(rlimit), verbose_(verbose), previous_(active_prover) {
  active_prover = this;
}

Prover::~Prover() { active_prover = previous_; }

Prover& Prover::current() {
  if (active_prover == nullptr) throw std::logic_error("SymInt literal without an active Prover");
  return *active_prover;
}

z3::expr Prover::num(const std::string& decimal) { return ctx_.int_val(decimal.c_str()); }
z3::expr Prover::num(std::int64_t value) { return ctx_.int_val(static_cast<int64_t>(value)); }

SymInt Prover::coordinate(const std::string& name) {
  const std::string b = std::to_string(kCoordBound);
  return integer(name, "-" + b, b);
}

SymInt Prover::integer(const std::string& name, const std::string& lo, const std::string& hi) {
  const z3::expr v = ctx_.int_const(name.c_str());
  inputs_.emplace_back(name, v);
  hypotheses_.push_back(num(lo) <= v && v <= num(hi));
  return SymInt(*this, v, bits_);
}

void Prover::assume(const z3::expr& fact) { hypotheses_.push_back(fact); }

void Prover::establish(const std::string& claim, const z3::expr& fact,
                       const std::vector<z3::expr>& generalize) {
  discharge(claim, fact, fact, generalize);
  hypotheses_.push_back(fact);
}

z3::expr Prover::require_in_range(const char* op, const z3::expr& value, unsigned bits) {
  const std::string name =
      std::string(op) + "#" + std::to_string(obligations_ + 1) + " in int" + std::to_string(bits);
  discharge(name, num(signed_min(bits)) <= value && value <= num(signed_max(bits)), value);
  return value;
}

void Prover::discharge(const std::string& name, const z3::expr& goal, const z3::expr& shown_value,
                       const std::vector<z3::expr>& generalize) {
  ++obligations_;
  // A fresh plain SMT solver per obligation. Z3's default solver first runs its QF_NIA tactic,
  // which exhausted 50 M rlimit units on "2*den > 0 given den > 0" here; the SMT core with
  // its nonlinear arithmetic module answers every query of this directory in milliseconds.
  z3::params params(ctx_);
  params.set("rlimit", rlimit_);  // deterministic budget; never a wall-clock timeout
  z3::solver s(ctx_, z3::solver::simple());
  s.set(params);
  z3::expr_vector from(ctx_), to(ctx_);
  for (const z3::expr& term : generalize) {
    from.push_back(term);
    to.push_back(ctx_.int_const(("g" + std::to_string(++generalized_)).c_str()));
  }
  for (z3::expr h : hypotheses_) s.add(from.empty() ? h : h.substitute(from, to));
  s.add(from.empty() ? !goal : (!goal).substitute(from, to));
  const auto start = std::chrono::steady_clock::now();
  const z3::check_result r = s.check();
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  solver_seconds_ += secs;
  if (r == z3::unsat) {
    if (verbose_) {
      std::printf("  proved  %-28s %7.3f s  %s\n", name.c_str(), secs,
                  shorten(shown_value.to_string()).c_str());
    }
    return;
  }
  if (r == z3::sat) {
    std::printf("  REFUTED %-28s %7.3f s  %s\n", name.c_str(), secs,
                shorten(shown_value.to_string()).c_str());
    if (!generalize.empty()) {
      std::printf("  (a model of the generalized query: the inputs below may not reproduce it)\n");
    }
    throw ObligationFailed(ObligationFailed::Kind::kRefuted,
                           counterexample(name, s.get_model(), shown_value),
                           "obligation " + name + " refuted");
  }
  std::printf("  UNKNOWN %-28s %7.3f s  (%s)\n", name.c_str(), secs, s.reason_unknown().c_str());
  throw ObligationFailed(ObligationFailed::Kind::kUnknown, Counterexample{name, {}, ""},
                         "obligation " + name + " undecided: " + s.reason_unknown());
}

Counterexample Prover::counterexample(const std::string& name, const z3::model& m,
                                      const z3::expr& shown_value) const {
  Counterexample c;
  c.obligation = name;
  for (const auto& [input_name, term] : inputs_) {
    c.inputs.emplace_back(input_name, m.eval(term, true).get_decimal_string(0));
  }
  const z3::expr v = m.eval(shown_value, true);
  c.value = v.is_numeral() ? v.get_decimal_string(0) : v.to_string();
  return c;
}

}  // namespace edgeland::proofs
