// Exact decimal parsing and power-of-ten scaling (see exact_decimal.hpp).
#include "exact_decimal.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace edgeland::test {
namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

BigInt power_of_ten(int n) {
  BigInt p = 1;
  for (int i = 0; i < n; ++i) p *= 10;
  return p;
}

// floor(n / d) for d > 0 (Boost.Multiprecision's division truncates toward zero).
BigInt floor_div(const BigInt& n, const BigInt& d) {
  BigInt q = n / d;
  if (q * d != n && n < 0) q -= 1;
  return q;
}

}  // namespace

std::optional<Decimal> parse_decimal(std::string_view text, std::size_t& pos) {
  std::size_t i = pos;
  bool negative = false;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
  std::string digits;
  int exponent = 0;
  bool seen_point = false;
  for (; i < text.size() && (is_digit(text[i]) || (text[i] == '.' && !seen_point)); ++i) {
    if (text[i] == '.') {
      seen_point = true;
    } else {
      digits.push_back(text[i]);
      if (seen_point) --exponent;
    }
  }
  if (digits.empty()) return std::nullopt;
  // A leading zero would make GMP read the digits as octal.
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    bool negative_exponent = false;
    if (j < text.size() && (text[j] == '-' || text[j] == '+')) negative_exponent = text[j++] == '-';
    int e = 0;
    const std::size_t first = j;
    for (; j < text.size() && is_digit(text[j]); ++j) e = e * 10 + (text[j] - '0');
    if (j > first) {
      exponent += negative_exponent ? -e : e;
      i = j;
    }
  }
  Decimal d{BigInt(digits), exponent};
  if (negative) d.mantissa = -d.mantissa;
  pos = i;
  return d;
}

BigInt scale_and_round(const Decimal& value, int power) {
  const int k = value.exponent + power;
  if (k >= 0) return value.mantissa * power_of_ten(k);
  // nearest integer to m / d, ties up: floor((2m + d) / 2d)
  const BigInt d = power_of_ten(-k);
  return floor_div(2 * value.mantissa + d, 2 * d);
}

int fraction_digits(const Decimal& value) {
  if (value.mantissa == 0) return 0;
  BigInt m = value.mantissa;
  int e = value.exponent;
  while (e < 0 && m % 10 == 0) {
    m /= 10;
    ++e;
  }
  return e < 0 ? -e : 0;
}

}  // namespace edgeland::test
