#pragma once
// A material of the landscape: 0 is empty space, 1..255 are solid materials.
//
// A strong type, so that a number out of range cannot pass silently: as a plain uint8_t,
// `fill(shape, 260)` filled material 4 and `replace(shape, 1, -1)` wrote 255 with no warning,
// even under -Wconversion (issue 27, point 8). Any integer converts implicitly, checked: a value
// outside 0..255 throws InvalidMaterial (spatial/errors.hpp) before anything happens, at compile
// time where the value is a constant expression (`constexpr Material m = 300;` does not
// compile). So every call written with a literal (`fill(shape, 2)`) reads as before, and a
// computed number is checked exactly once, where it becomes a material. value() gives the
// number back (an explicit step: a Material is not an integer, so it never indexes, adds or
// shifts by accident).
#include <array>
#include <compare>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "edgeland/kernel/export.hpp"

namespace edgeland {

namespace detail {
// Throws InvalidMaterial(number); out of line, so this header needs no error class.
[[noreturn]] EDGELAND_EXPORT void throw_invalid_material(std::int64_t number);
}  // namespace detail

// The integer types a material number may come as: every integer type but bool and the
// character types (std::in_range takes no others, and 'a' is no material).
template <class T>
concept MaterialNumber = std::integral<T> && !std::same_as<T, bool> && !std::same_as<T, char> &&
                         !std::same_as<T, wchar_t> && !std::same_as<T, char8_t> &&
                         !std::same_as<T, char16_t> && !std::same_as<T, char32_t>;

// A game's own unscoped enumeration of materials (`enum Rock { kBedrock = 1, kDirt = 2 };`)
// converts like its number; a scoped one (`enum class`) does not convert implicitly, as nothing
// does from a scoped enumeration (the deleted constructor below says how to pass one).
template <class E>
concept UnscopedMaterialEnum =
    std::is_enum_v<E> && std::is_convertible_v<E, std::underlying_type_t<E>> &&
    MaterialNumber<std::underlying_type_t<E>>;
template <class E>
concept ScopedEnum = std::is_enum_v<E> && !std::is_convertible_v<E, std::underlying_type_t<E>>;

class Material {
 public:
  // Empty space.
  constexpr Material() noexcept = default;
  // Checked: 0..255, else InvalidMaterial (its `number` is the value given, saturated to the
  // int64 range).
  template <MaterialNumber T>
  constexpr Material(T number) : value_(checked(number)) {}  // NOLINT: implicit by design
  // An unscoped enumerator: its number, checked the same way.
  template <UnscopedMaterialEnum E>
  constexpr Material(E number)  // NOLINT: implicit by design
      : value_(checked(static_cast<std::underlying_type_t<E>>(number))) {}
  // A scoped enumerator (enum class) is refused at compile time; the compiler quotes this line:
  template <ScopedEnum E>
  Material(E) = delete;  // an enum class: pass Material(static_cast<int>(e))

  // The material's number, 0..255.
  constexpr std::uint8_t value() const noexcept { return value_; }
  // Not empty space.
  constexpr bool solid() const noexcept { return value_ != 0; }

  friend constexpr bool operator==(Material, Material) noexcept = default;
  friend constexpr std::strong_ordering operator<=>(Material, Material) noexcept = default;

 private:
  template <class T>
  static constexpr std::uint8_t checked(T number) {
    if (!std::in_range<std::uint8_t>(number)) {
      constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
      detail::throw_invalid_material(
          std::cmp_greater(number, kMax) ? kMax : static_cast<std::int64_t>(number));
    }
    return static_cast<std::uint8_t>(number);
  }
  std::uint8_t value_ = 0;
};

// The number in decimal, as edit logs write it.
inline std::string to_string(Material m) { return std::to_string(m.value()); }

inline constexpr Material kEmpty{};
// Materials 0..255: an array indexed by Material::value() has this many entries.
inline constexpr std::size_t kMaterialCount = 256;

// What Landscape::relabel makes of each material under its shape: material m becomes
// map[m]. A new map is the identity (nothing changes); set() changes one entry, uniform() maps
// every material to one. "An explosion that spares bedrock" is
// MaterialMap::uniform(kEmpty).set(bedrock, bedrock); fill(s, m) is relabel(s, uniform(m)),
// replace(s, a, b) is relabel(s, MaterialMap().set(a, b)).
class MaterialMap {
 public:
  constexpr MaterialMap() noexcept {
    for (std::size_t i = 0; i < kMaterialCount; ++i) to_[i] = static_cast<std::uint8_t>(i);
  }
  static constexpr MaterialMap uniform(Material to) noexcept {
    MaterialMap map;
    for (std::uint8_t& entry : map.to_) entry = to.value();
    return map;
  }
  constexpr MaterialMap& set(Material from, Material to) noexcept {
    to_[from.value()] = to.value();
    return *this;
  }
  constexpr Material operator[](Material from) const noexcept { return to_[from.value()]; }
  friend constexpr bool operator==(const MaterialMap&, const MaterialMap&) noexcept = default;

 private:
  std::array<std::uint8_t, kMaterialCount> to_{};
};

}  // namespace edgeland

template <>
struct std::hash<edgeland::Material> {
  std::size_t operator()(edgeland::Material m) const noexcept { return m.value(); }
};
