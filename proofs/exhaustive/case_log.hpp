#pragma once
// Bookkeeping for a bounded-exhaustive check: counts the cases, prints the first failures
// with their inputs, and prints the totals ctest shows (`ctest -L proofs -V`).
#include <cstdint>
#include <cstdio>
#include <string>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"

namespace edgeland::exhaustive {

inline std::string str(Point64 p) {
  return "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
}

class CaseLog {
 public:
  explicit CaseLog(std::string what) : what_(std::move(what)) {}

  // One case: `ok` is the property; `describe` (called only on failure) names the inputs.
  template <class Describe>
  void expect(bool ok, Describe&& describe) {
    ++cases_;
    if (ok) return;
    if (++failures_ <= kShownFailures)
      std::printf("FAIL %s: %s\n", what_.c_str(), describe().c_str());
  }

  std::uint64_t cases() const { return cases_; }
  std::uint64_t failures() const { return failures_; }

  // Prints "<what>: N cases, F failures" and returns whether all passed.
  bool report() const {
    std::printf("%-64s %9llu cases, %llu failures\n", what_.c_str(),
                static_cast<unsigned long long>(cases_),
                static_cast<unsigned long long>(failures_));
    return failures_ == 0 && cases_ > 0;
  }

 private:
  static constexpr std::uint64_t kShownFailures = 10;
  std::string what_;
  std::uint64_t cases_ = 0;
  std::uint64_t failures_ = 0;
};

}  // namespace edgeland::exhaustive
