#pragma once
// Integer points and the one coordinate bound of the library.
#include <compare>
#include <cstdint>
#include <functional>

namespace edgeland {

// Every coordinate the library accepts satisfies |c| <= kCoordBound: the whole symmetric
// int32 range. The proofs in proofs/ show that with this bound no intermediate of any
// predicate or construction leaves its type (differences fit 33 bits, orientation determinants
// 65 and dot products 66 bits, intersection numerators 98 of the 128 available). Coordinates are
// stored in int64 so that differences and doubled coordinates never need a cast.
inline constexpr std::int64_t kCoordBound = 2147483647;  // 2^31 - 1

struct Point64 {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend constexpr bool operator==(const Point64&, const Point64&) = default;
  // Lexicographic (x, then y): the sweep order used throughout the library.
  friend constexpr auto operator<=>(const Point64&, const Point64&) = default;
};

constexpr bool coord_in_range(std::int64_t c) noexcept {
  return c >= -kCoordBound && c <= kCoordBound;
}
constexpr bool in_range(Point64 p) noexcept { return coord_in_range(p.x) && coord_in_range(p.y); }

struct Point64Hash {
  std::size_t operator()(const Point64& p) const noexcept {
    // splitmix-style mix of both coordinates; deterministic across platforms.
    std::uint64_t h = static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(p.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace edgeland
