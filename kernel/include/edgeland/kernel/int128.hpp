#pragma once
// 128-bit signed integer used for every exact product in the kernel.
#include <cstdint>
#include <string>

#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/portable_int128.hpp"

// Int128 is the compiler's __int128 on GCC, and on Clang off Windows (there Clang follows
// MSVC's runtime, which lacks the 128-bit division helpers). Everywhere else (MSVC, clang-cl,
// clang for MinGW, 32-bit targets without __int128), and on any compiler when the build sets
// EDGELAND_PORTABLE_INT128 (CMake option -DEDGELAND_PORTABLE_INT128=ON, which the library
// exports to its users: the two are different types, so library and game must agree), it is
// PortableInt128 (portable_int128.hpp), bit for bit the same arithmetic. README.md, "Supported
// platforms". These aliases are the only places a public header names __int128 (ctest
// library.int128_one_spelling).
#if defined(EDGELAND_PORTABLE_INT128) && EDGELAND_PORTABLE_INT128
#define EDGELAND_NATIVE_INT128 0
#elif defined(__SIZEOF_INT128__) && !defined(_MSC_VER) && !(defined(__clang__) && defined(_WIN32))
#define EDGELAND_NATIVE_INT128 1
#else
#define EDGELAND_NATIVE_INT128 0
#endif

namespace edgeland {

#if EDGELAND_NATIVE_INT128
using Int128 = __int128;
using UInt128 = unsigned __int128;
#else
using Int128 = PortableInt128;
using UInt128 = PortableUInt128;
#endif

// Decimal text of an Int128 (neither iostreams nor std::to_string know the type).
EDGELAND_EXPORT std::string to_string(Int128 value);

// An Int128's two's-complement bits as two 64-bit words, low first, and back: how a binary format
// stores one (spatial's region records). The bits as they are: no arithmetic, no overflow.
constexpr std::uint64_t int128_low(Int128 value) noexcept {
  return static_cast<std::uint64_t>(static_cast<UInt128>(value));
}
constexpr std::uint64_t int128_high(Int128 value) noexcept {
  return static_cast<std::uint64_t>(static_cast<UInt128>(value) >> 64);
}
constexpr Int128 int128_from_words(std::uint64_t low, std::uint64_t high) noexcept {
  return static_cast<Int128>(static_cast<UInt128>(high) << 64 | low);
}

// |value| as an unsigned 128-bit number; defined for every value including the minimum.
constexpr UInt128 unsigned_abs(Int128 value) noexcept {
  return value < 0 ? UInt128{0} - static_cast<UInt128>(value) : static_cast<UInt128>(value);
}

// The two's complement words of a value, low word first, and back: the one representation
// that is the same for both kinds of Int128 (and the C API's el_int128).
struct Int128Words {
  std::uint64_t lo = 0;
  std::int64_t hi = 0;
};
constexpr Int128Words to_words(Int128 value) noexcept {
  return {static_cast<std::uint64_t>(value), static_cast<std::int64_t>(value >> 64)};
}
constexpr Int128 from_words(Int128Words words) noexcept {
  return static_cast<Int128>((static_cast<UInt128>(static_cast<std::uint64_t>(words.hi)) << 64) |
                             UInt128{words.lo});
}

}  // namespace edgeland
