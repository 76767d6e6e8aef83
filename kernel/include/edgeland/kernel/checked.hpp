#pragma once
// Overflow-checked integer arithmetic.
//
// NOT API: installed only because the public inline predicates (predicates.hpp) compute
// through it; edgeland::arith may change without notice. Do not include it yourself.
//
// Every construction in the kernel computes through `Checked<T>`. The coordinate bound
// (point.hpp) is chosen so that no operation can leave its type for in-range input; the
// proofs in proofs/ show it for every formula in formulas.hpp, instantiated with a symbolic
// integer type instead of `Checked<T>`. In the checked build (EDGELAND_CHECKED) every
// operation also tests for overflow and aborts with a message, so a broken proof obligation
// is caught at run time in tests and fuzzers too. The release build trusts the proof.
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <type_traits>

#include "edgeland/kernel/int128.hpp"

namespace edgeland::arith {

[[noreturn]] inline void overflow_trap(const char* what) noexcept {
  std::fprintf(stderr, "edgeland: integer overflow in checked %s\n", what);
  std::abort();
}

#if defined(EDGELAND_CHECKED) && EDGELAND_CHECKED
inline constexpr bool kChecked = true;
#else
inline constexpr bool kChecked = false;
#endif

// Overflow tests. GCC and Clang have __builtin_*_overflow; the portable build (and MSVC, which
// has neither the builtins nor __int128) tests the sign bits of the wrapped result instead:
// a + b overflows exactly when a and b share a sign the sum lacks, a - b when a and b differ
// in sign and the difference lacks a's. T is std::int64_t or Int128.
template <class T>
constexpr T wrapping_add(T a, T b) noexcept {
  if constexpr (std::is_same_v<T, std::int64_t>) {
    return static_cast<T>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
  } else {
    return static_cast<T>(static_cast<UInt128>(a) + static_cast<UInt128>(b));
  }
}
template <class T>
constexpr T wrapping_sub(T a, T b) noexcept {
  if constexpr (std::is_same_v<T, std::int64_t>) {
    return static_cast<T>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
  } else {
    return static_cast<T>(static_cast<UInt128>(a) - static_cast<UInt128>(b));
  }
}
template <class T>
constexpr bool add_overflows(T a, T b, T* out) noexcept {
#if EDGELAND_NATIVE_INT128
  return __builtin_add_overflow(a, b, out);
#else
  *out = wrapping_add(a, b);
  return ((a ^ *out) & (b ^ *out)) < 0;
#endif
}
template <class T>
constexpr bool sub_overflows(T a, T b, T* out) noexcept {
#if EDGELAND_NATIVE_INT128
  return __builtin_sub_overflow(a, b, out);
#else
  *out = wrapping_sub(a, b);
  return ((a ^ b) & (a ^ *out)) < 0;
#endif
}

// 128-bit multiply-with-overflow: clang lowers __builtin_mul_overflow on __int128 to
// __muloti4, which libgcc does not provide, so the 128-bit check is done by hand (and so the
// same in both builds): the magnitudes' product fits when |b| <= limit / |a|.
constexpr bool mul_overflows(Int128 a, Int128 b, Int128* out) noexcept {
  using U = UInt128;
  const U ua = unsigned_abs(a), ub = unsigned_abs(b);
  const bool negative = (a < 0) != (b < 0);
  const U limit = negative ? (U(1) << 127) : (U(1) << 127) - 1;
  if (ua != 0 && ub > limit / ua) return true;
  const U mag = ua * ub;
  *out = negative ? Int128(U(0) - mag) : Int128(mag);
  return false;
}
// 64-bit: the exact product in 128 bits (|a b| <= 2^126), then its range.
constexpr bool mul_overflows(std::int64_t a, std::int64_t b, std::int64_t* out) noexcept {
#if EDGELAND_NATIVE_INT128
  return __builtin_mul_overflow(a, b, out);
#else
  const Int128 exact = Int128(a) * Int128(b);
  *out = static_cast<std::int64_t>(exact);
  return exact != Int128(*out);
#endif
}

template <class T>
constexpr T add(T a, T b) noexcept {
  if constexpr (kChecked) {
    T r{};
    if (add_overflows(a, b, &r)) overflow_trap("add");
    return r;
  } else {
    return a + b;
  }
}

template <class T>
constexpr T sub(T a, T b) noexcept {
  if constexpr (kChecked) {
    T r{};
    if (sub_overflows(a, b, &r)) overflow_trap("sub");
    return r;
  } else {
    return a - b;
  }
}

template <class T>
constexpr T mul(T a, T b) noexcept {
  if constexpr (kChecked) {
    T r{};
    if (mul_overflows(a, b, &r)) overflow_trap("mul");
    return r;
  } else {
    return a * b;
  }
}

// An integer that computes through the helpers above. Formulas are written once over a
// number type; the library instantiates them with Checked<Int128>, the proofs with Z3 terms.
template <class T>
struct Checked {
  T v{};
  constexpr Checked() = default;
  constexpr Checked(T value) : v(value) {}  // NOLINT: implicit on purpose, formulas read as math
  // The portable Int128 is a class, so a literal reaches it through a second conversion.
  template <std::integral I>
  requires(!std::integral<T>) constexpr Checked(I value) : v(value) {}  // NOLINT: as above
  // Widening from a narrower checked type (formulas that take differences in 64 bits).
  template <class U>
  requires(sizeof(U) < sizeof(T)) explicit constexpr Checked(Checked<U> narrow)
      : v(static_cast<T>(narrow.v)) {}
  friend constexpr Checked operator+(Checked a, Checked b) { return Checked(add(a.v, b.v)); }
  friend constexpr Checked operator-(Checked a, Checked b) { return Checked(sub(a.v, b.v)); }
  friend constexpr Checked operator*(Checked a, Checked b) { return Checked(mul(a.v, b.v)); }
  friend constexpr Checked operator-(Checked a) { return Checked(sub(T(0), a.v)); }
  friend constexpr bool operator==(Checked a, Checked b) { return a.v == b.v; }
  friend constexpr auto operator<=>(Checked a, Checked b) { return a.v <=> b.v; }
};

// The absolute value (formulas find it by ADL; the proofs oblige -a to be in range).
template <class T>
constexpr Checked<T> magnitude(Checked<T> a) noexcept {
  return a.v < 0 ? -a : a;
}

// Floor division for a positive divisor (the only kind the kernel uses).
template <class T>
constexpr Checked<T> floor_div(Checked<T> n, Checked<T> d) noexcept {
  T q = n.v / d.v;
  if (n.v % d.v != 0 && n.v < 0) q -= 1;
  return Checked<T>(q);
}

}  // namespace edgeland::arith
