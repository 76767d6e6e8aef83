// Scaling peers' decimal cases to the integer grid (see integer_operands.hpp).
#include "integer_operands.hpp"

#include <algorithm>
#include <cctype>

#include "edgeland/kernel/point.hpp"

namespace edgeland::test {
namespace {

template <class F>
void for_each_coordinate(const DecimalGeometry& g, F f) {
  for (const DecimalPolygon& polygon : g)
    for (const DecimalRing& ring : polygon)
      for (const DecimalPoint& p : ring) f(p.x, p.y);
}

bool in_range_at(const DecimalGeometry& a, const DecimalGeometry& b, int power) {
  const BigInt bound(kCoordBound);
  bool ok = true;
  for (const DecimalGeometry* g : {&a, &b})
    for_each_coordinate(*g, [&](const Decimal& x, const Decimal& y) {
      if (ok && (abs(scale_and_round(x, power)) > bound || abs(scale_and_round(y, power)) > bound))
        ok = false;
    });
  return ok;
}

// max(width, height) of both operands' box after scaling by 10^power.
BigInt extent_at(const DecimalGeometry& a, const DecimalGeometry& b, int power) {
  std::optional<BigInt> lo[2], hi[2];
  for (const DecimalGeometry* g : {&a, &b})
    for_each_coordinate(*g, [&](const Decimal& x, const Decimal& y) {
      const BigInt c[2] = {scale_and_round(x, power), scale_and_round(y, power)};
      for (int k = 0; k < 2; ++k) {
        if (!lo[k] || c[k] < *lo[k]) lo[k] = c[k];
        if (!hi[k] || c[k] > *hi[k]) hi[k] = c[k];
      }
    });
  if (!lo[0]) return 0;
  return std::max(*hi[0] - *lo[0], *hi[1] - *lo[1]);
}

std::string parameter_name(const PeerCase& peer, Scaling scaling) {
  const char* suffix = scaling == Scaling::kFine     ? "_fine"
                       : scaling == Scaling::kCoarse ? "_coarse"
                                                     : "_peer";
  std::string name = peer.file + "_" + peer.name + suffix;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// Decimal digits of |value| before the point (0 for |value| < 1).
int integer_digits(const Decimal& value) {
  if (value.mantissa == 0) return 0;
  return std::max(0, static_cast<int>(BigInt(abs(value.mantissa)).str().size()) + value.exponent);
}

}  // namespace

int fine_power(const DecimalGeometry& a, const DecimalGeometry& b) {
  int power = 0;
  int magnitude =
      0;  // max over coordinates of floor(log10 |c|) + 1 (decimal digits before the point)
  for (const DecimalGeometry* g : {&a, &b})
    for_each_coordinate(*g, [&](const Decimal& x, const Decimal& y) {
      power = std::max({power, fraction_digits(x), fraction_digits(y)});
      magnitude = std::max({magnitude, integer_digits(x), integer_digits(y)});
    });
  // kCoordBound has 10 digits: start where the largest coordinate has at most 10, then step
  // down exactly (the scan from the digit estimate takes one or two steps, not dozens).
  power = std::min(power, 10 - magnitude);
  while (!in_range_at(a, b, power)) --power;
  return power;
}

std::optional<int> coarse_power(const DecimalGeometry& a, const DecimalGeometry& b) {
  const int fine = fine_power(a, b);
  // The extent at the fine power has d digits; kCoarseExtent has 3: start d - 3 powers lower.
  const int digits = static_cast<int>(extent_at(a, b, fine).str().size());
  int power = std::min(fine, fine - (digits - 3));
  while (extent_at(a, b, power) <= kCoarseExtent && power < fine) ++power;
  while (extent_at(a, b, power) > kCoarseExtent) --power;
  if (power >= fine) return std::nullopt;
  return power;
}

IntegerPolygons to_integer_polygons(const DecimalGeometry& g, int power) {
  IntegerPolygons out;
  for (const DecimalPolygon& polygon : g) {
    std::vector<Ring> rings;
    for (const DecimalRing& ring : polygon) {
      Ring r;
      for (const DecimalPoint& p : ring)
        r.push_back({scale_and_round(p.x, power).convert_to<std::int64_t>(),
                     scale_and_round(p.y, power).convert_to<std::int64_t>()});
      if (r.size() > 1 && r.back() == r.front()) r.pop_back();
      rings.push_back(std::move(r));
    }
    out.push_back(std::move(rings));
  }
  return out;
}

std::vector<ScaledCase> scaled_variants(const PeerCase& peer) {
  const DecimalGeometry a = read_decimal_wkt(peer.a);
  const DecimalGeometry b = read_decimal_wkt(peer.b);
  std::vector<ScaledCase> out;
  const int fine = fine_power(a, b);
  out.push_back({peer, Scaling::kFine, fine, to_integer_polygons(a, fine),
                 to_integer_polygons(b, fine), parameter_name(peer, Scaling::kFine)});
  const std::optional<int> coarse = coarse_power(a, b);
  if (coarse)
    out.push_back({peer, Scaling::kCoarse, *coarse, to_integer_polygons(a, *coarse),
                   to_integer_polygons(b, *coarse), parameter_name(peer, Scaling::kCoarse)});
  // The peer's own grid, unless it is one of the two above already.
  if (peer.peer_scale && *peer.peer_scale != fine && peer.peer_scale != coarse)
    out.push_back({peer, Scaling::kPeer, *peer.peer_scale, to_integer_polygons(a, *peer.peer_scale),
                   to_integer_polygons(b, *peer.peer_scale), parameter_name(peer, Scaling::kPeer)});
  return out;
}

std::vector<Ring> all_rings(const IntegerPolygons& polygons) {
  std::vector<Ring> rings;
  for (const auto& polygon : polygons) rings.insert(rings.end(), polygon.begin(), polygon.end());
  return rings;
}

}  // namespace edgeland::test
