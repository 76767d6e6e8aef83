#pragma once
// splitmix64 (Steele, Lea, Flood 2014; the seeding generator of xoshiro): the project's one
// seeded integer random sequence and its 64-bit mix, the same on every platform and compiler
// (std:: distributions differ between standard libraries; these must not). Used by the game's
// island keys, the net test clients' edit streams, the store's sweep, the demo's world, the
// physics scene, and the seeded inputs of the tests, benchmarks and fuzzers' mutators.
// Installed with the kernel so that every target above it, installed or not, reaches it.
// Integers only: whatever is built from it is reproducible bit for bit.
#include <cstdint>

namespace edgeland {

// splitmix64's increment (2^64 / the golden ratio, odd).
inline constexpr std::uint64_t kSplitMix64Gamma = 0x9e3779b97f4a7c15ull;

// The splitmix64 output function: a bijective mix of 64 bits.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t seed) noexcept : state_(seed) {}

  constexpr std::uint64_t next() noexcept { return mix64(state_ += kSplitMix64Gamma); }

  // Uniform in [lo, hi] (lo <= hi, hi - lo < 2^32): multiply-shift of 32 random bits, whose
  // bias of at most 2^-32 per value does not matter for seeded inputs. The demo's draws.
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

}  // namespace edgeland
