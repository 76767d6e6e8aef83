#pragma once
// 128-bit integers from two 64-bit words, for compilers without __int128 (MSVC, clang on
// Windows) and for the portable build on every other (-DEDGELAND_PORTABLE_INT128=ON).
//
// PortableInt128 and PortableUInt128 behave as GCC's __int128 and unsigned __int128 do, bit for
// bit: two's complement, + - * wrapping modulo 2^128, / and % truncating toward zero, >> on a
// signed value arithmetic, conversions to narrower integers keeping the low bits, to double
// rounded to nearest (ties to even). The kernel's proofs guarantee that no exact computation
// ever wraps; the checked build tests it (checked.hpp), so wrapping only has to agree with the
// native type where a test compares them (tests/kernel/portable_int128_test.cpp, fuzz target
// int128_portable). Division by zero and shifts by 128 or more are undefined, as natively.
//
// The multiply is the one piece of real arithmetic here: multiply_words() below, schoolbook on
// 32-bit halves, proven in proofs/ (theorem portable_multiply) on this very template.
#include <bit>
#include <compare>
#include <concepts>
#include <cstdint>
#include <limits>

namespace edgeland {

namespace detail::wide {

// Two 64-bit words of a 128-bit value (or their symbolic stand-ins in proofs/).
template <class W>
struct WordPair {
  W lo;
  W hi;
};

// The halves of a 64-bit word, and a low half moved up (x < 2^32: nothing is lost).
constexpr std::uint64_t low_half(std::uint64_t x) noexcept { return x & 0xffffffffu; }
constexpr std::uint64_t high_half(std::uint64_t x) noexcept { return x >> 32; }
constexpr std::uint64_t half_up(std::uint64_t x) noexcept { return x << 32; }
// The product of two halves: at most (2^32 - 1)^2, so it never wraps a word.
constexpr std::uint64_t half_product(std::uint64_t a, std::uint64_t b) noexcept { return a * b; }
// Word arithmetic modulo 2^64.
constexpr std::uint64_t wrapping_add(std::uint64_t a, std::uint64_t b) noexcept { return a + b; }
constexpr std::uint64_t wrapping_mul(std::uint64_t a, std::uint64_t b) noexcept { return a * b; }

// The full product a * b of two words as (lo, hi) words. Each partial product of halves is at
// most (2^32 - 1)^2, the middle column at most 3 (2^32 - 1), so no step wraps; hi 2^64 + lo =
// a b exactly (proofs/: theorem portable_multiply, on this template with exact integers).
template <class W>
constexpr WordPair<W> multiply_words(W a, W b) noexcept {
  const W a0 = low_half(a), a1 = high_half(a), b0 = low_half(b), b1 = high_half(b);
  const W p00 = half_product(a0, b0), p01 = half_product(a0, b1), p10 = half_product(a1, b0),
          p11 = half_product(a1, b1);
  const W mid = high_half(p00) + low_half(p01) + low_half(p10);
  return {half_up(low_half(mid)) + low_half(p00),
          p11 + high_half(p01) + high_half(p10) + high_half(mid)};
}

// (a * b) mod 2^128 of two values given as words: the low words' full product, plus the two
// cross products' low words in the high word; a.hi b.hi 2^128 vanishes. The same for signed
// and unsigned values (two's complement). Proven with multiply_words.
template <class W>
constexpr WordPair<W> multiply_wrapping(WordPair<W> a, WordPair<W> b) noexcept {
  const WordPair<W> low = multiply_words(a.lo, b.lo);
  const W cross = wrapping_add(wrapping_mul(a.lo, b.hi), wrapping_mul(a.hi, b.lo));
  return {low.lo, wrapping_add(low.hi, cross)};
}

using Words128 = WordPair<std::uint64_t>;

constexpr int bit_width(Words128 x) noexcept {
  return x.hi != 0 ? 64 + static_cast<int>(std::bit_width(x.hi))
                   : static_cast<int>(std::bit_width(x.lo));
}
constexpr bool less(Words128 a, Words128 b) noexcept {
  return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo;
}
constexpr Words128 subtract(Words128 a, Words128 b) noexcept {
  return {a.lo - b.lo, a.hi - b.hi - (a.lo < b.lo ? 1 : 0)};
}
// x << n and x >> n (logical) for n in 0..127.
constexpr Words128 shift_up(Words128 x, int n) noexcept {
  if (n == 0) return x;
  if (n >= 64) return {0, x.lo << (n - 64)};
  return {x.lo << n, (x.hi << n) | (x.lo >> (64 - n))};
}
constexpr Words128 shift_down(Words128 x, int n) noexcept {
  if (n == 0) return x;
  if (n >= 64) return {x.hi >> (n - 64), 0};
  return {(x.lo >> n) | (x.hi << (64 - n)), x.hi >> n};
}

// Unsigned n / d as (quotient, remainder) in (lo, hi): one hardware division when both fit a
// word, else shift and subtract from the divisor's highest position under the dividend's (at
// most 128 steps, each keeping r < 2 step: the schoolbook binary division).
constexpr WordPair<Words128> divide_unsigned(Words128 n, Words128 d) noexcept {
  if (n.hi == 0 && d.hi == 0) return {{n.lo / d.lo, 0}, {n.lo % d.lo, 0}};
  if (less(n, d)) return {{0, 0}, n};
  const int shift = bit_width(n) - bit_width(d);
  Words128 q{0, 0}, r = n, step = shift_up(d, shift);
  for (int i = shift; i >= 0; --i) {
    q = shift_up(q, 1);
    if (!less(r, step)) {
      r = subtract(r, step);
      q.lo |= 1;
    }
    step = shift_down(step, 1);
  }
  return {q, r};
}

}  // namespace detail::wide

// A 128-bit integer held as two words, signed (two's complement) or not.
template <bool Signed>
class PortableInteger128 {
 public:
  using Words = detail::wide::WordPair<std::uint64_t>;

  constexpr PortableInteger128() noexcept = default;
  // Every integer converts implicitly, as to __int128 (a signed one sign-extended; a native
  // 128-bit one, where the compiler has it, word for word).
  template <std::integral T>
  constexpr PortableInteger128(T value) noexcept  // NOLINT: implicit, as the native type
      : lo_(static_cast<std::uint64_t>(value)), hi_(high_word_of(value)) {}
  // A floating-point value truncated toward zero, as natively (defined for |value| < 2^127).
  template <std::floating_point T>
  explicit constexpr PortableInteger128(T value) noexcept {
    const T magnitude = value < 0 ? -value : value;
    constexpr T kWord = T(18446744073709551616.0);  // 2^64: m / 2^64 and what is left are exact
    const auto hi = static_cast<std::uint64_t>(magnitude / kWord);
    lo_ = static_cast<std::uint64_t>(magnitude - static_cast<T>(hi) * kWord);
    hi_ = hi;
    if (value < 0) *this = -*this;
  }
  // The other signedness converts implicitly too, keeping the bits (as natively).
  constexpr PortableInteger128(PortableInteger128<!Signed> other) noexcept  // NOLINT
      : lo_(other.low_word()), hi_(other.high_word()) {}

  static constexpr PortableInteger128 from_words(std::uint64_t lo, std::uint64_t hi) noexcept {
    PortableInteger128 r;
    r.lo_ = lo;
    r.hi_ = hi;
    return r;
  }
  constexpr std::uint64_t low_word() const noexcept { return lo_; }
  constexpr std::uint64_t high_word() const noexcept { return hi_; }
  constexpr bool negative() const noexcept { return Signed && (hi_ >> 63) != 0; }

  // To a narrower integer: the low bits, as a static_cast of the native type; to bool: != 0; to
  // a native 128-bit integer: both words.
  template <std::integral T>
  explicit constexpr operator T() const noexcept {
    if constexpr (std::is_same_v<T, bool>) {
      return (lo_ | hi_) != 0;
    } else if constexpr (sizeof(T) > sizeof(std::uint64_t)) {
      return static_cast<T>((static_cast<T>(hi_) << 64) | static_cast<T>(lo_));
    } else {
      return static_cast<T>(lo_);
    }
  }
  // To double or float: rounded to nearest, ties to even, as the native conversion.
  template <std::floating_point T>
  explicit constexpr operator T() const noexcept {
    const PortableInteger128<false> mag = negative() ? -*this : *this;
    const T value = mag.template to_float_magnitude<T>();
    return negative() ? -value : value;
  }

  // --- arithmetic, as the native type (wrapping) ---------------------------------------------
  friend constexpr PortableInteger128 operator+(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    const std::uint64_t lo = a.lo_ + b.lo_;
    return from_words(lo, a.hi_ + b.hi_ + (lo < a.lo_ ? 1 : 0));
  }
  friend constexpr PortableInteger128 operator-(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    return from_words(a.lo_ - b.lo_, a.hi_ - b.hi_ - (a.lo_ < b.lo_ ? 1 : 0));
  }
  friend constexpr PortableInteger128 operator*(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    const Words r = detail::wide::multiply_wrapping(a.words(), b.words());
    return from_words(r.lo, r.hi);
  }
  friend constexpr PortableInteger128 operator/(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    return a.divide(b).quotient;
  }
  friend constexpr PortableInteger128 operator%(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    return a.divide(b).remainder;
  }
  constexpr PortableInteger128 operator-() const noexcept { return PortableInteger128{} - *this; }
  constexpr PortableInteger128 operator+() const noexcept { return *this; }
  constexpr PortableInteger128 operator~() const noexcept { return from_words(~lo_, ~hi_); }
  constexpr bool operator!() const noexcept { return (lo_ | hi_) == 0; }

  friend constexpr PortableInteger128 operator&(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    return from_words(a.lo_ & b.lo_, a.hi_ & b.hi_);
  }
  friend constexpr PortableInteger128 operator|(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    return from_words(a.lo_ | b.lo_, a.hi_ | b.hi_);
  }
  friend constexpr PortableInteger128 operator^(PortableInteger128 a,
                                                PortableInteger128 b) noexcept {
    return from_words(a.lo_ ^ b.lo_, a.hi_ ^ b.hi_);
  }
  // Shifts by 0..127 (the count converts from any integer, as natively).
  friend constexpr PortableInteger128 operator<<(PortableInteger128 a, int n) noexcept {
    if (n == 0) return a;
    if (n >= 64) return from_words(0, a.lo_ << (n - 64));
    return from_words(a.lo_ << n, (a.hi_ << n) | (a.lo_ >> (64 - n)));
  }
  // Arithmetic (sign-filling) for a signed value, logical for an unsigned one.
  friend constexpr PortableInteger128 operator>>(PortableInteger128 a, int n) noexcept {
    const std::uint64_t fill = a.negative() ? ~std::uint64_t{0} : 0;
    if (n == 0) return a;
    if (n >= 64) {
      const std::uint64_t lo = n == 64 ? a.hi_ : (a.hi_ >> (n - 64)) | (fill << (128 - n));
      return from_words(lo, fill);
    }
    return from_words((a.lo_ >> n) | (a.hi_ << (64 - n)), (a.hi_ >> n) | (fill << (64 - n)));
  }

  constexpr PortableInteger128& operator+=(PortableInteger128 b) noexcept {
    return *this = *this + b;
  }
  constexpr PortableInteger128& operator-=(PortableInteger128 b) noexcept {
    return *this = *this - b;
  }
  constexpr PortableInteger128& operator*=(PortableInteger128 b) noexcept {
    return *this = *this * b;
  }
  constexpr PortableInteger128& operator/=(PortableInteger128 b) noexcept {
    return *this = *this / b;
  }
  constexpr PortableInteger128& operator%=(PortableInteger128 b) noexcept {
    return *this = *this % b;
  }
  constexpr PortableInteger128& operator&=(PortableInteger128 b) noexcept {
    return *this = *this & b;
  }
  constexpr PortableInteger128& operator|=(PortableInteger128 b) noexcept {
    return *this = *this | b;
  }
  constexpr PortableInteger128& operator^=(PortableInteger128 b) noexcept {
    return *this = *this ^ b;
  }
  constexpr PortableInteger128& operator<<=(int n) noexcept { return *this = *this << n; }
  constexpr PortableInteger128& operator>>=(int n) noexcept { return *this = *this >> n; }
  constexpr PortableInteger128& operator++() noexcept { return *this = *this + 1; }
  constexpr PortableInteger128& operator--() noexcept { return *this = *this - 1; }
  constexpr PortableInteger128 operator++(int) noexcept {
    const PortableInteger128 old = *this;
    ++*this;
    return old;
  }
  constexpr PortableInteger128 operator--(int) noexcept {
    const PortableInteger128 old = *this;
    --*this;
    return old;
  }

  friend constexpr bool operator==(PortableInteger128 a, PortableInteger128 b) noexcept {
    return a.lo_ == b.lo_ && a.hi_ == b.hi_;
  }
  friend constexpr std::strong_ordering operator<=>(PortableInteger128 a,
                                                    PortableInteger128 b) noexcept {
    if (a.hi_ != b.hi_) {
      if constexpr (Signed) {
        return static_cast<std::int64_t>(a.hi_) <=> static_cast<std::int64_t>(b.hi_);
      } else {
        return a.hi_ <=> b.hi_;
      }
    }
    return a.lo_ <=> b.lo_;
  }

 private:
  template <bool>
  friend class PortableInteger128;

  struct Division {
    PortableInteger128 quotient;
    PortableInteger128 remainder;
  };

  constexpr Words words() const noexcept { return {lo_, hi_}; }

  // The high word of an integer: of its sign extension for one of 64 bits or fewer (all ones
  // for a negative value, else zero), its own for a wider one.
  template <std::integral T>
  static constexpr std::uint64_t high_word_of(T value) noexcept {
    if constexpr (sizeof(T) > sizeof(std::uint64_t)) {
      return static_cast<std::uint64_t>(value >> 64);
    } else if constexpr (std::is_signed_v<T>) {
      return value < 0 ? ~std::uint64_t{0} : 0;
    } else {
      return 0;
    }
  }

  // Truncating division: the magnitudes' quotient and remainder, the quotient negative when
  // the signs differ and the remainder taking the dividend's sign (C++'s rule).
  constexpr Division divide(PortableInteger128 d) const noexcept {
    const bool n_neg = negative(), d_neg = d.negative();
    const PortableInteger128 un = n_neg ? -*this : *this, ud = d_neg ? -d : d;
    const auto qr = detail::wide::divide_unsigned(un.words(), ud.words());
    PortableInteger128 q = from_words(qr.lo.lo, qr.lo.hi), r = from_words(qr.hi.lo, qr.hi.hi);
    if (n_neg != d_neg) q = -q;
    if (n_neg) r = -r;
    return {q, r};
  }

  constexpr int bit_width() const noexcept { return detail::wide::bit_width(words()); }

  // An unsigned value as a float type, rounded once: its top 64 bits with a sticky bit for the
  // bits below (so a halfway case stays a halfway case only when it is one), then scaled by a
  // power of two, which is exact.
  template <class T>
  constexpr T to_float_magnitude() const noexcept {
    if (hi_ == 0) return static_cast<T>(lo_);
    const int shift = bit_width() - 64;
    const PortableInteger128 top = *this >> shift;
    const bool sticky = (*this - (top << shift)) != PortableInteger128{};
    T value = static_cast<T>(top.lo_ | (sticky ? 1 : 0));
    for (int i = 0; i < shift; ++i) value *= 2;
    return value;
  }

  std::uint64_t lo_ = 0;
  std::uint64_t hi_ = 0;
};

using PortableInt128 = PortableInteger128<true>;
using PortableUInt128 = PortableInteger128<false>;

}  // namespace edgeland

// The limits of the native types, for generic code (numeric_limits<__int128> exists too).
template <bool Signed>
class std::numeric_limits<edgeland::PortableInteger128<Signed>> {
  using T = edgeland::PortableInteger128<Signed>;

 public:
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = Signed;
  static constexpr bool is_integer = true;
  static constexpr bool is_exact = true;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = !Signed;
  static constexpr int digits = Signed ? 127 : 128;
  static constexpr int radix = 2;
  static constexpr T min() noexcept {
    return Signed ? T::from_words(0, std::uint64_t{1} << 63) : T(0);
  }
  static constexpr T lowest() noexcept { return min(); }
  static constexpr T max() noexcept {
    return T::from_words(~std::uint64_t{0}, Signed ? ~std::uint64_t{0} >> 1 : ~std::uint64_t{0});
  }
};
