#pragma once
// Int128 / UInt128 as Boost.Multiprecision integers (the tests' exact references), from the two
// words: the same in the native build and the portable one (-DEDGELAND_PORTABLE_INT128), where
// Int128 is a class Boost does not know.
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>

#include "edgeland/kernel/int128.hpp"

namespace edgeland::test {

inline boost::multiprecision::cpp_int big(UInt128 v) {
  boost::multiprecision::cpp_int out = static_cast<std::uint64_t>(v >> 64);
  out <<= 64;
  out += static_cast<std::uint64_t>(v);
  return out;
}

inline boost::multiprecision::cpp_int big(Int128 v) {
  const boost::multiprecision::cpp_int magnitude = big(unsigned_abs(v));
  return v < 0 ? boost::multiprecision::cpp_int(-magnitude) : magnitude;
}

}  // namespace edgeland::test
