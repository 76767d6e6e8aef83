#pragma once
// 128-bit signed integer used for every exact product in the kernel.
#include <cstdint>
#include <string>

#include "edgeland/kernel/export.hpp"

// The kernel's exact arithmetic needs 128-bit integers, which GCC and Clang provide as __int128
// on 64-bit targets and on WebAssembly, and MSVC and GCC on 32-bit x86 do not (README.md,
// "Supported platforms"). These two aliases are the only places a public header names the type
// (ctest library.int128_one_spelling), so a port would change them alone.
#if !defined(__SIZEOF_INT128__)
#error "edgeland needs 128-bit integers (__int128): see README.md, Supported platforms"
#endif

namespace edgeland {

using Int128 = __int128;
using UInt128 = unsigned __int128;

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

}  // namespace edgeland
