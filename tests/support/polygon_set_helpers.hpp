#pragma once
// Small exact helpers on integer polygon sets for the clipper tests, written from the
// definitions and sharing no code with the library under test: area, point location of
// rational points, the documented canonical form, and a tiny WKT reader for test literals.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/point.hpp"
#include "edgeland/kernel/polygon.hpp"

namespace edgeland::test {

// Twice the signed area of a ring by the shoelace formula (each term < 2^63, exact).
inline Int128 twice_area(const Ring& ring) {
  Int128 sum = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    sum += Int128(a.x) * b.y - Int128(a.y) * b.x;
  }
  return sum;
}
inline Int128 twice_area(const PolygonSet& set) {
  Int128 sum = 0;
  for (const Polygon& p : set) sum += twice_area(p);
  return sum;
}

inline std::size_t vertex_count(const PolygonSet& set) {
  std::size_t n = 0;
  for (const Polygon& p : set) n += p.size();
  return n;
}

// A rational sample point (x / den, y / den) with a small positive den (1, 2 or 4 in the
// tests), so that scaled coordinates stay below 2^34 and all products fit Int128.
struct SamplePoint {
  std::int64_t x = 0, y = 0, den = 1;
};

// Sign of the cross product (b - a) x (p - a) with a, b scaled by den.
inline int side_of(Point64 a, Point64 b, const SamplePoint& p) {
  const Int128 ax = Int128(a.x) * p.den, ay = Int128(a.y) * p.den;
  const Int128 bx = Int128(b.x) * p.den, by = Int128(b.y) * p.den;
  const Int128 c = (bx - ax) * (p.y - ay) - (by - ay) * (p.x - ax);
  return (c > 0) - (c < 0);
}

inline bool on_segment(Point64 a, Point64 b, const SamplePoint& p) {
  if (side_of(a, b, p) != 0) return false;
  const Int128 px = p.x, py = p.y;
  const Int128 lox = Int128(std::min(a.x, b.x)) * p.den, hix = Int128(std::max(a.x, b.x)) * p.den;
  const Int128 loy = Int128(std::min(a.y, b.y)) * p.den, hiy = Int128(std::max(a.y, b.y)) * p.den;
  return lox <= px && px <= hix && loy <= py && py <= hiy;
}

// Winding number of the ring around p (p not on the ring): crossings of the upward and
// downward edges with the horizontal line through p, to the right of p.
inline int winding(const Ring& ring, const SamplePoint& p) {
  int w = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point64 a = ring[i], b = ring[(i + 1) % n];
    const Int128 ay = Int128(a.y) * p.den, by = Int128(b.y) * p.den;
    if (ay <= p.y && by > p.y && side_of(a, b, p) > 0) ++w;
    if (ay > p.y && by <= p.y && side_of(a, b, p) < 0) --w;
  }
  return w;
}

enum class Where { kInside, kOnBoundary, kOutside };

// Location of p with respect to the closed union of the members of a set.
inline Where locate(const PolygonSet& set, const SamplePoint& p) {
  bool inside = false;
  for (const Polygon& poly : set) {
    for (std::size_t i = 0; i < poly.size(); ++i)
      if (on_segment(poly[i], poly[(i + 1) % poly.size()], p)) return Where::kOnBoundary;
    if (winding(poly, p) != 0) inside = true;
  }
  return inside ? Where::kInside : Where::kOutside;
}

// The canonical form documented in clip.hpp, from its definition: no collinear consecutive
// vertices, each ring starting at its lexicographically smallest vertex, rings sorted by
// that vertex (ties: by the rest of the ring). Expects valid polygons.
inline PolygonSet canonical_form(PolygonSet set) {
  for (Polygon& p : set) {
    bool changed = true;
    while (changed && p.size() > 3) {
      changed = false;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t n = p.size();
        const Point64 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
        const Int128 cr = Int128(b.x - a.x) * (c.y - a.y) - Int128(b.y - a.y) * (c.x - a.x);
        if (cr == 0) {
          p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
          changed = true;
          break;
        }
      }
    }
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
  }
  // Sorted by first vertex; clip.hpp leaves ties (rings starting at one shared vertex) open,
  // and the only natural total order extending it is lexicographic on the whole ring.
  std::sort(set.begin(), set.end());
  return set;
}

// Reads "POLYGON ((x y, ...))", "MULTIPOLYGON (((...)), ((...)))" or "MULTIPOLYGON EMPTY"
// with integer coordinates and closed rings (no holes: the kernel model has none). Each ring
// becomes one Polygon without its closing vertex. Throws std::invalid_argument otherwise.
inline PolygonSet parse_wkt(std::string_view text) {
  PolygonSet out;
  std::size_t i = 0;
  auto skip = [&] {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  };
  auto expect = [&](char c) {
    skip();
    if (i >= text.size() || text[i] != c)
      throw std::invalid_argument("parse_wkt: expected '" + std::string(1, c) + "' in " +
                                  std::string(text));
    ++i;
  };
  auto number = [&] {
    skip();
    const std::size_t start = i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    if (start == i) throw std::invalid_argument("parse_wkt: expected a number");
    return std::stoll(std::string(text.substr(start, i - start)));
  };
  auto ring = [&] {
    expect('(');
    Polygon r;
    while (true) {
      const std::int64_t x = number();
      const std::int64_t y = number();
      r.push_back({x, y});
      skip();
      if (i < text.size() && text[i] == ',') {
        ++i;
        continue;
      }
      expect(')');
      break;
    }
    if (r.size() < 2 || r.front() != r.back())
      throw std::invalid_argument("parse_wkt: ring not closed");
    r.pop_back();
    return r;
  };
  auto polygon = [&] {
    expect('(');
    out.push_back(ring());
    skip();
    if (i < text.size() && text[i] == ',') throw std::invalid_argument("parse_wkt: holes");
    expect(')');
  };
  skip();
  if (text.substr(i, 12) == "MULTIPOLYGON") {
    i += 12;
    skip();
    if (text.substr(i, 5) == "EMPTY") return out;
    expect('(');
    while (true) {
      polygon();
      skip();
      if (i < text.size() && text[i] == ',') {
        ++i;
        continue;
      }
      expect(')');
      break;
    }
  } else if (text.substr(i, 7) == "POLYGON") {
    i += 7;
    polygon();
  } else {
    throw std::invalid_argument("parse_wkt: unsupported geometry");
  }
  return out;
}

}  // namespace edgeland::test
