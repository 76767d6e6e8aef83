#include "edgeland/kernel/int128.hpp"

#include <algorithm>

namespace edgeland {

std::string to_string(Int128 value) {
  UInt128 mag = unsigned_abs(value);
  std::string digits;
  do {
    digits.push_back(static_cast<char>('0' + static_cast<int>(mag % 10)));
    mag /= 10;
  } while (mag != 0);
  if (value < 0) digits.push_back('-');
  std::reverse(digits.begin(), digits.end());
  return digits;
}

}  // namespace edgeland
