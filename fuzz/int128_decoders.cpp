// The `int128_portable` target (decoders.hpp): the portable Int128 against the compiler's
// __int128 on decoded pairs, every operation (tests/support/int128_differential.hpp).
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <string>

#include "decoders.hpp"
#include "int128_differential.hpp"

namespace edgeland::fuzz {
namespace {

using test::NativeInt128;
using test::NativeUInt128;

// A value of every width: two words, then shifted right by a decoded amount (most of the
// kernel's values are far below 2^127, and the division's fast and slow paths part at 2^64).
NativeInt128 value(FuzzedDataProvider& in) {
  const auto lo = in.ConsumeIntegral<std::uint64_t>();
  const auto hi = in.ConsumeIntegral<std::uint64_t>();
  const NativeInt128 full = static_cast<NativeInt128>((static_cast<NativeUInt128>(hi) << 64) | lo);
  return full >> in.ConsumeIntegralInRange<int>(0, 127);
}

std::string hex(NativeInt128 v) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (int shift = 124; shift >= 0; shift -= 4) {
    out += digits[static_cast<int>((static_cast<NativeUInt128>(v) >> shift) & 15)];
  }
  return out;
}

}  // namespace

std::optional<Finding> run_int128_portable(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  while (in.remaining_bytes() > 0) {
    const NativeInt128 a = value(in), b = value(in);
    if (const char* op = test::first_difference(a, b)) {
      return Finding{std::string("portable Int128 differs from __int128 in ") + op + " of 0x" +
                         hex(a) + " and 0x" + hex(b),
                     ""};
    }
  }
  return std::nullopt;
}

}  // namespace edgeland::fuzz
