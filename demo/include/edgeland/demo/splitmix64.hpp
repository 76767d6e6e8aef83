#pragma once
// splitmix64 (Steele, Lea, Flood 2014; the seeding generator of xoshiro): a seeded integer
// random sequence that is the same on every platform and compiler. The one generator of the
// demo's world and edits, the physics scene, and the seeded inputs of the tests, benchmarks and
// fuzzers' mutators (std:: distributions differ between standard libraries; these must not).
// Integers only: the demo's world must be reproducible bit for bit.
#include <cstdint>

namespace edgeland::demo {

// The splitmix64 output function: a bijective mix of 64 bits.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t seed) noexcept : state_(seed) {}

  constexpr std::uint64_t next() noexcept { return mix64(state_ += 0x9e3779b97f4a7c15ull); }

  // Uniform in [lo, hi] (lo <= hi, hi - lo < 2^32): multiply-shift of 32 random bits, whose
  // bias of at most 2^-32 per value does not matter for a demo. The demo's draws.
  constexpr std::int64_t between(std::int64_t lo, std::int64_t hi) noexcept {
    const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<std::int64_t>(((next() >> 32) * span) >> 32);
  }

  // next() modulo n (n >= 1), 0 for n = 0: the draws of the tests' and the physics scene's
  // seeded inputs, whose sequences predate between() and stay as they were.
  constexpr std::uint64_t below(std::uint64_t n) noexcept { return n == 0 ? 0 : next() % n; }

  // True with probability percent / 100.
  constexpr bool chance(int percent) noexcept { return between(0, 99) < percent; }

 private:
  std::uint64_t state_;
};

}  // namespace edgeland::demo
