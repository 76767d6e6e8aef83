#pragma once
// The portable Int128 (kernel/.../portable_int128.hpp) against the compiler's __int128, every
// operation on one pair of values: the kernel test (tests/kernel/portable_int128_test.cpp) and
// the fuzz target int128_portable (fuzz/int128_decoders.cpp) share it.
#include <cstdint>
#include <limits>

#include "edgeland/kernel/portable_int128.hpp"

namespace edgeland::test {

using NativeInt128 = __int128;
using NativeUInt128 = unsigned __int128;

inline PortableInt128 portable(NativeInt128 v) { return v; }
inline NativeInt128 native(PortableInt128 v) { return static_cast<NativeInt128>(v); }

// The first operation whose results differ for a and b ("+", "to double", ...), or nullptr.
inline const char* first_difference(NativeInt128 a, NativeInt128 b) {
  constexpr NativeInt128 kMin = std::numeric_limits<NativeInt128>::min();
  const PortableInt128 pa = portable(a), pb = portable(b);
  const NativeUInt128 ua = static_cast<NativeUInt128>(a), ub = static_cast<NativeUInt128>(b);
  const PortableUInt128 qa = pa, qb = pb;
  if (native(pa + pb) != static_cast<NativeInt128>(ua + ub)) return "+";
  if (native(pa - pb) != static_cast<NativeInt128>(ua - ub)) return "-";
  if (native(pa * pb) != static_cast<NativeInt128>(ua * ub)) return "*";
  if (native(-pa) != static_cast<NativeInt128>(NativeUInt128{0} - ua)) return "unary -";
  if (native(~pa) != ~a) return "~";
  if ((pa == pb) != (a == b) || (pa < pb) != (a < b) || (pa > pb) != (a > b) ||
      (pa <= pb) != (a <= b)) {
    return "compare";
  }
  if ((qa < qb) != (ua < ub)) return "unsigned compare";
  if (native(pa & pb) != (a & b) || native(pa | pb) != (a | b) || native(pa ^ pb) != (a ^ b)) {
    return "bitwise";
  }
  if (b != 0 && !(a == kMin && b == -1)) {  // undefined natively
    if (native(pa / pb) != a / b) return "/";
    if (native(pa % pb) != a % b) return "%";
  }
  if (ub != 0) {
    if (static_cast<NativeUInt128>(qa / qb) != ua / ub) return "unsigned /";
    if (static_cast<NativeUInt128>(qa % qb) != ua % ub) return "unsigned %";
  }
  const int shift = static_cast<int>(ub % 128);
  if (native(pa << shift) != static_cast<NativeInt128>(ua << shift)) return "<<";
  if (native(pa >> shift) != (a >> shift)) return ">>";
  if (static_cast<NativeUInt128>(qa >> shift) != (ua >> shift)) return "unsigned >>";
  if (static_cast<double>(pa) != static_cast<double>(a)) return "to double";
  if (static_cast<double>(qa) != static_cast<double>(ua)) return "unsigned to double";
  if (static_cast<float>(pa) != static_cast<float>(a)) return "to float";
  if (static_cast<std::int64_t>(pa) != static_cast<std::int64_t>(a)) return "to int64";
  if (static_cast<std::uint32_t>(pa) != static_cast<std::uint32_t>(a)) return "to uint32";
  if (static_cast<bool>(pa) != static_cast<bool>(a)) return "to bool";
  const double d = static_cast<double>(a) / 3;  // any double in range, truncated back
  if (native(PortableInt128(d)) != static_cast<NativeInt128>(d)) return "from double";
  return nullptr;
}

}  // namespace edgeland::test
