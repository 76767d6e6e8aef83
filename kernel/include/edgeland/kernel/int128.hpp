#pragma once
// 128-bit signed integer used for every exact product in the kernel.
#include <cstdint>
#include <string>

#include "edgeland/kernel/export.hpp"

namespace edgeland {

using Int128 = __int128;

// Decimal text of an Int128 (neither iostreams nor std::to_string know the type).
EDGELAND_EXPORT std::string to_string(Int128 value);

// |value| as an unsigned 128-bit number; defined for every value including the minimum.
constexpr unsigned __int128 unsigned_abs(Int128 value) noexcept {
  return value < 0 ? (unsigned __int128)0 - (unsigned __int128)value : (unsigned __int128)value;
}

}  // namespace edgeland
