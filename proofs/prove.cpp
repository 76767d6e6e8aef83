// edgeland_prove: runs the named theorems (theorems.hpp) and exits 0 only when each one
// ends as expected: proven, or refuted with a replayed counterexample for a theorem that
// must fail. Any refuted or undecided obligation prints its counterexample and exits 1.
//
//   edgeland_prove --list
//   edgeland_prove [--bits N] [--rlimit UNITS] [--quiet] THEOREM... | --all
// --bits overrides the machine width (e.g. to find how much headroom a formula has).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "edgeland/kernel/point.hpp"
#include "theorems.hpp"

namespace edgeland::proofs {
namespace {

// Z3 rlimit units per obligation (about 1.4 M units/s on the reference machine): far above
// what any obligation here needs, and deterministic, unlike a wall-clock timeout
// (TOOLCHAIN.md pitfall 1).
constexpr unsigned kDefaultRlimit = 50'000'000;

std::vector<Theorem> all_theorems() {
  std::vector<Theorem> all;
  for (auto group :
       {predicate_theorems, rounding_theorems, area_theorems, centroid_theorems, probe_theorems,
        shape_theorems, portable_int128_theorems, refutation_theorems}) {
    for (Theorem& t : group()) all.push_back(std::move(t));
  }
  return all;
}

void print_counterexample(const Counterexample& c, unsigned bits) {
  std::printf("counterexample for %s:\n", c.obligation.c_str());
  for (const auto& [name, value] : c.inputs)
    std::printf("  %s = %s\n", name.c_str(), value.c_str());
  std::printf("  value = %s  (int%u range is [%s, %s])\n", c.value.c_str(), bits,
              signed_min(bits).c_str(), signed_max(bits).c_str());
}

// Returns true when the theorem ended as expected.
bool run(const Theorem& t, unsigned bits, unsigned rlimit, bool verbose) {
  std::printf("theorem %s (int%u, |coord| <= %lld)\n  %s\n", t.name.c_str(), bits,
              static_cast<long long>(kCoordBound), t.statement.c_str());
  const auto start = std::chrono::steady_clock::now();
  Prover prover(bits, rlimit, verbose);
  bool proven = false;
  bool as_expected = false;
  try {
    t.body(prover);
    proven = true;
    as_expected = !t.expect_refuted;
  } catch (const ObligationFailed& failure) {
    if (failure.kind == ObligationFailed::Kind::kRefuted) {
      print_counterexample(failure.counterexample, bits);
      as_expected = t.expect_refuted && t.replay && t.replay(failure.counterexample);
    } else {
      std::printf("%s\n", failure.what());
    }
  }
  const double secs =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const char* verdict = proven                            ? "PROVEN"
                        : t.expect_refuted && as_expected ? "REFUTED AS EXPECTED"
                                                          : "NOT PROVEN";
  std::printf("%s %s: %d obligations, %.3f s (solver %.3f s)%s\n", verdict, t.name.c_str(),
              prover.obligations(), secs, prover.solver_seconds(),
              t.expect_refuted && !as_expected ? ", but a confirmed refutation was expected" : "");
  return as_expected;
}

int main_impl(int argc, char** argv) {
  unsigned bits_override = 0;
  unsigned rlimit = kDefaultRlimit;
  bool verbose = true;
  bool run_all = false;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--list") {
      for (const Theorem& t : all_theorems()) std::printf("%s\n", t.name.c_str());
      return 0;
    } else if (arg == "--bits" && i + 1 < argc) {
      bits_override = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (arg == "--rlimit" && i + 1 < argc) {
      rlimit = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (arg == "--quiet") {
      verbose = false;
    } else if (arg == "--all") {
      run_all = true;
    } else {
      names.push_back(arg);
    }
  }
  const std::vector<Theorem> theorems = all_theorems();
  bool ok = true;
  int ran = 0;
  for (const Theorem& t : theorems) {
    bool wanted = run_all;
    for (const std::string& n : names) wanted = wanted || n == t.name;
    if (!wanted) continue;
    ok = run(t, bits_override != 0 ? bits_override : t.bits, rlimit, verbose) && ok;
    ++ran;
  }
  if (ran == 0 || ran < static_cast<int>(names.size())) {
    std::fprintf(stderr, "unknown theorem name (see --list)\n");
    return 2;
  }
  return ok ? 0 : 1;
}

}  // namespace
}  // namespace edgeland::proofs

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress visible in ctest logs, even on a hang
  return edgeland::proofs::main_impl(argc, argv);
}
