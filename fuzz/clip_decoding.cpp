// The clipper's targets' decoding (clip_decoding.hpp): a palette of points and the shapes
// drawn from it.
#include "clip_decoding.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "edgeland/io/clip_log.hpp"
#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::fuzz {
namespace {

std::int64_t clamp_coord(std::int64_t v) { return std::clamp(v, -kCoordBound, kCoordBound); }
Point64 clamped(std::int64_t x, std::int64_t y) { return {clamp_coord(x), clamp_coord(y)}; }

}  // namespace

std::string op_line(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  return std::string(op_name(op)) + "\n  A = " + to_wkt(a) + "\n  B = " + to_wkt(b);
}

std::string pair_log(ClipOp op, const PolygonSet& a, const PolygonSet& b) {
  return "set " + to_wkt(a) + "\n" + log::step_keyword(log::step_kind(op)) + " " + to_wkt(b) + "\n";
}

std::size_t vertex_count(const PolygonSet& set) {
  std::size_t n = 0;
  for (const Polygon& p : set) n += p.size();
  return n;
}

Decoder::Decoder(Provider& in) : in_(in) {
  pick_window();
  const int n = in_.ConsumeIntegralInRange(3, 10);
  for (int i = 0; i < n; ++i) add_point();
}

void Decoder::absorb(const PolygonSet& set) {
  const std::size_t n = vertex_count(set);
  if (n == 0) return;
  const int take = in_.ConsumeIntegralInRange(0, 4);
  for (int i = 0; i < take; ++i) {
    std::size_t k = in_.ConsumeIntegralInRange<std::size_t>(0, n - 1);
    for (const Polygon& p : set) {
      if (k < p.size()) {
        remember(p[k]);
        break;
      }
      k -= p.size();
    }
  }
}

PolygonSet Decoder::valid_set() {
  std::vector<Ring> rings;
  std::size_t vertices = 0;
  const int shapes = in_.ConsumeIntegralInRange<int>(1, kMaxShapes);
  for (int s = 0; s < shapes && vertices < kMaxSetVertices; ++s) {
    for (Ring& ring : shape()) {
      vertices += ring.size();
      rings.push_back(std::move(ring));
    }
  }
  const bool try_direct = in_.ConsumeBool();
  const FillRule rule = in_.PickValueInArray(kRules);
  if (try_direct) {
    PolygonSet direct;
    for (Ring ring : rings) {
      if (twice_signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
      direct.push_back(std::move(ring));
    }
    if (validate(direct, 0).ok()) return direct;
  }
  return normalize(rings, rule, ClipOptions{.checked = true}).polygons;
}

std::vector<Ring> Decoder::raw_rings(bool out_of_range) {
  std::vector<Ring> rings(in_.ConsumeIntegralInRange<std::size_t>(1, 6));
  for (Ring& ring : rings) {
    const std::size_t n = in_.ConsumeIntegralInRange<std::size_t>(0, 12);
    for (std::size_t i = 0; i < n; ++i) {
      Point64 p = in_.ConsumeBool() ? pick() : fresh();
      if (out_of_range && in_.ConsumeIntegralInRange(0, 31) == 0) {
        (in_.ConsumeBool() ? p.x : p.y) = in_.ConsumeIntegral<std::int64_t>();
      }
      ring.push_back(p);
    }
  }
  return rings;
}

void Decoder::pick_window() {
  switch (in_.ConsumeIntegralInRange(0, 5)) {
    case 0:
      lo_ = 0, hi_ = 8;
      break;
    case 1:
      lo_ = -64, hi_ = 64;
      break;
    case 2:
      lo_ = -kSmallBound, hi_ = kSmallBound;
      break;
    case 3:
      lo_ = kCoordBound - 32, hi_ = kCoordBound;
      break;
    case 4:
      lo_ = -kCoordBound, hi_ = -kCoordBound + 32;
      break;
    default:
      lo_ = -kCoordBound, hi_ = kCoordBound;
      break;
  }
}

std::int64_t Decoder::coord() { return in_.ConsumeIntegralInRange(lo_, hi_); }

Point64 Decoder::fresh() { return {coord(), coord()}; }

Point64 Decoder::pick() {
  if (palette_.empty()) return fresh();
  return palette_[in_.ConsumeIntegralInRange<std::size_t>(0, palette_.size() - 1)];
}

void Decoder::remember(Point64 p) {
  if (palette_.size() < kMaxPalette) {
    palette_.push_back(p);
  } else {
    palette_[in_.ConsumeIntegralInRange<std::size_t>(0, kMaxPalette - 1)] = p;
  }
}

Point64 Decoder::unit_offset() {
  static constexpr std::array<Point64, 8> kUnits{
      {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}}};
  return in_.PickValueInArray(kUnits);
}

// A lattice point on the segment a-b (a vertex on an edge).
Point64 Decoder::on_segment(Point64 a, Point64 b) {
  const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t g = std::gcd(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
  if (g == 0) return a;
  const std::int64_t k = in_.ConsumeIntegralInRange<std::int64_t>(0, g);
  return {a.x + dx / g * k, a.y + dy / g * k};
}

std::int64_t Decoder::extreme_coord() {
  static constexpr std::array<std::int64_t, 4> kExtremes{-kCoordBound, -kCoordBound + 1,
                                                         kCoordBound - 1, kCoordBound};
  return in_.ConsumeBool() ? in_.PickValueInArray(kExtremes) : coord();
}

void Decoder::add_point() {
  Point64 p;
  switch (in_.ConsumeIntegralInRange(0, 5)) {
    case 0:
      p = fresh();
      break;
    case 1:  // at the range limits
      p = {extreme_coord(), extreme_coord()};
      break;
    case 2:  // on an edge between two earlier points
      p = on_segment(pick(), pick());
      break;
    case 3: {  // next to an earlier point
      const Point64 q = pick(), u = unit_offset();
      p = clamped(q.x + u.x, q.y + u.y);
      break;
    }
    case 4: {  // one unit beside an edge
      const Point64 q = on_segment(pick(), pick()), u = unit_offset();
      p = clamped(q.x + u.x, q.y + u.y);
      break;
    }
    default: {  // near the middle of two points
      const Point64 a = pick(), b = pick();
      p = {std::midpoint(a.x, b.x), std::midpoint(a.y, b.y)};
      break;
    }
  }
  remember(p);
}

// One shape as one or more rings (any orientation; not necessarily simple).
std::vector<Ring> Decoder::shape() {
  switch (in_.ConsumeIntegralInRange(0, 5)) {
    case 0:
      return {{pick(), pick(), pick()}};
    case 1: {  // axis-aligned box spanned by two palette points
      const Point64 a = pick(), b = pick();
      return {{{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}}};
    }
    case 2: {
      Ring ring(in_.ConsumeIntegralInRange<std::size_t>(3, 8));
      for (Point64& p : ring) p = pick();
      return {ring};
    }
    case 3: {  // one-unit sliver along a-b
      const Point64 a = pick(), b = pick(), u = unit_offset();
      const Point64 bu = clamped(b.x + u.x, b.y + u.y);
      if (in_.ConsumeBool()) return {{a, b, bu}};
      return {{a, b, bu, clamped(a.x + u.x, a.y + u.y)}};
    }
    case 4:
      return {fan()};
    default:
      return strips();
  }
}

// Many edges through one pixel: spokes out of centre c alternate with points in the 3x3
// block around it, so edges of both operands cross near c at non-integer points.
Ring Decoder::fan() {
  const Point64 c = pick();
  const std::int64_t radius = in_.ConsumeIntegralInRange<std::int64_t>(2, 1 << 16);
  std::vector<Point64> directions(in_.ConsumeIntegralInRange<std::size_t>(3, 10));
  for (Point64& d : directions) {
    do {
      d = {in_.ConsumeIntegralInRange(-3, 3), in_.ConsumeIntegralInRange(-3, 3)};
    } while (d == Point64{0, 0} && in_.remaining_bytes() > 0);
    if (d == Point64{0, 0}) d = {1, 0};
  }
  std::sort(directions.begin(), directions.end(), angle_less);
  Ring ring;
  for (const Point64& d : directions) {
    ring.push_back(clamped(c.x + radius * d.x, c.y + radius * d.y));
    const Point64 u = unit_offset();
    ring.push_back(in_.ConsumeBool() ? c : clamped(c.x + u.x, c.y + u.y));
  }
  return ring;
}

// A box cut into vertical strips: members that share whole edges (a valid set as is).
std::vector<Ring> Decoder::strips() {
  const Point64 a = pick(), b = pick();
  const std::int64_t x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
  const std::int64_t y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
  std::vector<std::int64_t> cuts{x0, x1};
  const int n = in_.ConsumeIntegralInRange(0, 4);
  for (int i = 0; i < n && x1 > x0; ++i) {
    cuts.push_back(in_.ConsumeIntegralInRange(x0, x1));
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<Ring> rings;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    rings.push_back({{cuts[i], y0}, {cuts[i + 1], y0}, {cuts[i + 1], y1}, {cuts[i], y1}});
  }
  if (rings.empty()) rings.push_back({a, b, pick()});
  return rings;
}

}  // namespace edgeland::fuzz
