#pragma once
// Decimal numbers as peers' test files write them ("4.00000000000000089", "-5.51073e-014"),
// held exactly as mantissa * 10^exponent, and scaled by a power of ten to the integer grid
// without ever passing through a double: the scaled coordinates of a case are the exact
// rounding of what the peer wrote, so a failure here replays bit for bit anywhere.
#include <optional>
#include <string_view>

#include "cgal_reference.hpp"  // BigInt (GMP)

namespace edgeland::test {

struct Decimal {
  BigInt mantissa;   // the digits, with the sign
  int exponent = 0;  // value = mantissa * 10^exponent
};

// Parses an optional sign, digits with at most one '.', and an optional exponent (e/E, sign,
// digits) starting at text[pos]; advances pos past it. nullopt (pos unchanged) when there is
// no number there.
std::optional<Decimal> parse_decimal(std::string_view text, std::size_t& pos);

// round(value * 10^power) to the nearest integer, ties toward +infinity (the kernel's
// round_to_grid rule, so that a half-unit is resolved the same way everywhere).
BigInt scale_and_round(const Decimal& value, int power);

// The smallest power p >= 0 such that value * 10^p is an integer.
int fraction_digits(const Decimal& value);

}  // namespace edgeland::test
