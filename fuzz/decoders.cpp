#include "decoders.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <exception>
#include <functional>
#include <numeric>
#include <utility>
#include <vector>

#include "edgeland/clip/clip.hpp"
#include "edgeland/io/clip_log.hpp"
#include "edgeland/io/wkt_reader.hpp"
#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/area.hpp"
#include "edgeland/kernel/canonical_form.hpp"
#include "edgeland/kernel/int128.hpp"
#include "edgeland/kernel/perimeter.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::fuzz {
namespace {

using Provider = FuzzedDataProvider;

constexpr std::size_t kMaxPalette = 24;
constexpr std::size_t kMaxShapes = 6;
constexpr std::size_t kMaxSetVertices = 64;     // per decoded operand
constexpr std::size_t kMaxStateVertices = 400;  // a sequence stops growing past this
constexpr std::size_t kMaxSteps = 12;
constexpr std::int64_t kSmallBound = std::int64_t{1} << 20;  // "small input": reference checks

constexpr std::array<ClipOp, 4> kOps{ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference,
                                     ClipOp::kXor};
constexpr std::array<FillRule, 4> kRules{FillRule::kEvenOdd, FillRule::kNonZero,
                                         FillRule::kPositive, FillRule::kNegative};

std::int64_t clamp_coord(std::int64_t v) { return std::clamp(v, -kCoordBound, kCoordBound); }
Point64 clamped(std::int64_t x, std::int64_t y) { return {clamp_coord(x), clamp_coord(y)}; }

// Text for findings and logs, built only when something is found: on the small inputs fuzzing
// feeds, writing WKT for every operation cost as much as the operations (issue 18).
using Text = std::function<std::string()>;

// Turns geometry into text for findings and logs.
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

// ---- structure-aware decoding -----------------------------------------------------------
// Every point is drawn from a shared palette, so the two operands (and the steps of a
// sequence) reuse each other's vertices, lie on each other's edges and pass through the same
// pixels: the near-degenerate cases the clipper must survive.
class Decoder {
 public:
  explicit Decoder(Provider& in) : in_(in) {
    pick_window();
    const int n = in_.ConsumeIntegralInRange(3, 10);
    for (int i = 0; i < n; ++i) add_point();
  }

  // Adds a few vertices of `set` to the palette (continuous clipping: the next edit touches
  // what the previous ones made).
  void absorb(const PolygonSet& set) {
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

  // A valid set: the decoded shapes as they are when they already form a valid set (members
  // may then share edges), else normalized with a decoded fill rule.
  PolygonSet valid_set() {
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

  // Arbitrary rings for normalize (and invalid operands): palette points, repeats, and with
  // `out_of_range`, now and then a raw 64-bit coordinate.
  std::vector<Ring> raw_rings(bool out_of_range) {
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

  Provider& in() { return in_; }

 private:
  void pick_window() {
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

  std::int64_t coord() { return in_.ConsumeIntegralInRange(lo_, hi_); }
  Point64 fresh() { return {coord(), coord()}; }
  Point64 pick() {
    if (palette_.empty()) return fresh();
    return palette_[in_.ConsumeIntegralInRange<std::size_t>(0, palette_.size() - 1)];
  }
  void remember(Point64 p) {
    if (palette_.size() < kMaxPalette) {
      palette_.push_back(p);
    } else {
      palette_[in_.ConsumeIntegralInRange<std::size_t>(0, kMaxPalette - 1)] = p;
    }
  }
  Point64 unit_offset() {
    static constexpr std::array<Point64, 8> kUnits{
        {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}}};
    return in_.PickValueInArray(kUnits);
  }
  // A lattice point on the segment a-b (a vertex on an edge).
  Point64 on_segment(Point64 a, Point64 b) {
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    const std::int64_t g = std::gcd(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
    if (g == 0) return a;
    const std::int64_t k = in_.ConsumeIntegralInRange<std::int64_t>(0, g);
    return {a.x + dx / g * k, a.y + dy / g * k};
  }
  std::int64_t extreme_coord() {
    static constexpr std::array<std::int64_t, 4> kExtremes{-kCoordBound, -kCoordBound + 1,
                                                           kCoordBound - 1, kCoordBound};
    return in_.ConsumeBool() ? in_.PickValueInArray(kExtremes) : coord();
  }

  void add_point() {
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
  std::vector<Ring> shape() {
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
  Ring fan() {
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
  std::vector<Ring> strips() {
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

  Provider& in_;
  std::int64_t lo_ = 0, hi_ = 0;
  std::vector<Point64> palette_;
};

// ---- exact references -------------------------------------------------------------------

bool small(const std::vector<Ring>& rings) {
  for (const Ring& r : rings) {
    for (const Point64& p : r) {
      if (p.x < -kSmallBound || p.x > kSmallBound || p.y < -kSmallBound || p.y > kSmallBound) {
        return false;
      }
    }
  }
  return true;
}

// Whether p is farther than 1.5 units from segment a-b: 4 dist^2 > 9, exactly. Needs
// coordinates within kSmallBound (squared cross products fit in 128 bits).
bool far_from_segment(Point64 p, Point64 a, Point64 b) {
  const Int128 abx = b.x - a.x, aby = b.y - a.y, apx = p.x - a.x, apy = p.y - a.y;
  const Int128 len2 = abx * abx + aby * aby;
  const Int128 t = apx * abx + apy * aby;
  if (len2 == 0 || t <= 0) return 4 * (apx * apx + apy * apy) > 9;
  if (t >= len2) {
    const Int128 bpx = p.x - b.x, bpy = p.y - b.y;
    return 4 * (bpx * bpx + bpy * bpy) > 9;
  }
  const Int128 cross = abx * apy - aby * apx;
  return 4 * cross * cross > 9 * len2;
}

bool far_from_rings(Point64 p, const std::vector<Ring>& rings) {
  for (const Ring& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (!far_from_segment(p, r[i], r[(i + 1) % r.size()])) return false;
    }
  }
  return true;
}

// Lattice sample points: a 9x9 grid over the inputs' box (grown by 3) and points around
// every input vertex.
std::vector<Point64> sample_points(const std::vector<Ring>& rings) {
  std::vector<Point64> points;
  std::int64_t x0 = kSmallBound, y0 = kSmallBound, x1 = -kSmallBound, y1 = -kSmallBound;
  for (const Ring& r : rings) {
    for (const Point64& p : r) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
      for (const Point64 d : {Point64{2, 0}, Point64{-2, 0}, Point64{0, 2}, Point64{0, -2},
                              Point64{2, 2}, Point64{-2, -2}, Point64{2, -2}, Point64{-2, 2}}) {
        points.push_back({p.x + d.x, p.y + d.y});
      }
    }
  }
  if (x0 > x1) return points;
  x0 -= 3, y0 -= 3, x1 += 3, y1 += 3;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      points.push_back({x0 + (x1 - x0) * i / 8, y0 + (y1 - y0) * j / 8});
    }
  }
  return points;
}

bool op_keeps(ClipOp op, bool in_a, bool in_b) {
  switch (op) {
    case ClipOp::kUnion:
      return in_a || in_b;
    case ClipOp::kIntersection:
      return in_a && in_b;
    case ClipOp::kDifference:
      return in_a && !in_b;
    case ClipOp::kXor:
      break;
  }
  return in_a != in_b;
}

bool rule_fills(FillRule rule, int w) {
  switch (rule) {
    case FillRule::kEvenOdd:
      return (w % 2) != 0;
    case FillRule::kNonZero:
      return w != 0;
    case FillRule::kPositive:
      return w > 0;
    case FillRule::kNegative:
      break;
  }
  return w < 0;
}

std::string point_text(Point64 p) {
  return "(" + std::to_string(p.x) + " " + std::to_string(p.y) + ")";
}

std::optional<Finding> invalid_output(const Text& context, const PolygonSet& out,
                                      const Text& log_text) {
  const ValidationReport report = validate(out, 1);
  std::string problem;
  if (!report.ok()) {
    problem = "invalid: " + report.violations.front().describe();
  } else if (const auto order = canonical_violation(out)) {
    problem = "not canonical: " + order->describe();
  }
  if (problem.empty()) return std::nullopt;
  return Finding{"output (" + problem + ") of " + context() + "\n  output = " + to_wkt(out),
                 log_text()};
}

// ---- clip_pair --------------------------------------------------------------------------

struct Pair {
  PolygonSet a, b;
};

Pair decode_pair(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  Decoder decoder(in);
  Pair pair;
  pair.a = decoder.valid_set();
  pair.b = decoder.valid_set();
  return pair;
}

std::optional<Finding> check_pair_areas(const Pair& p, const std::array<ClipResult, 4>& r) {
  const Int128 a = twice_signed_area(p.a), b = twice_signed_area(p.b);
  const Int128 u = twice_signed_area(r[0].polygons), i = twice_signed_area(r[1].polygons);
  const Int128 d = twice_signed_area(r[2].polygons), x = twice_signed_area(r[3].polygons);
  bool exact = true;
  for (const ClipResult& res : r) exact = exact && res.stats.vertices_snapped == 0;
  // Accuracy contract: |area(out) - area(R)| <= perimeter(R) <= perimeter(A) + perimeter(B),
  // so each identity below is off by at most that per result involved (twice-area units: 2x).
  const Int128 p_ab = perimeter_bounds(p.a).hi + perimeter_bounds(p.b).hi;
  struct Identity {
    const char* name;
    Int128 error;
    Int128 bound;
  };
  const std::array<Identity, 3> identities{{
      {"|A n B| + |A - B| = |A|", i + d - a, 4 * p_ab},
      {"|A u B| = |A| + |B| - |A n B|", u - (a + b - i), 4 * p_ab},
      {"|A x B| = |A u B| - |A n B|", x - (u - i), 6 * p_ab},
  }};
  for (const Identity& id : identities) {
    const Int128 err = id.error < 0 ? -id.error : id.error;
    if ((exact && err != 0) || err > id.bound) {
      return Finding{
          std::string("area identity ") + id.name + (exact ? " (exact: nothing snapped)" : "") +
              " off by " + to_string(err) + "/2 (bound " + to_string(id.bound) +
              "/2)\n  A = " + to_wkt(p.a) + "\n  B = " + to_wkt(p.b),
          pair_log(ClipOp::kIntersection, p.a, p.b) + pair_log(ClipOp::kDifference, p.a, p.b)};
    }
  }
  return std::nullopt;
}

std::optional<Finding> check_pair_points(const Pair& p, const std::array<ClipResult, 4>& r) {
  std::vector<Ring> rings(p.a.begin(), p.a.end());
  rings.insert(rings.end(), p.b.begin(), p.b.end());
  if (!small(rings)) return std::nullopt;
  for (const Point64& q : sample_points(rings)) {
    if (!far_from_rings(q, rings)) continue;
    const bool in_a = locate(q, p.a) == PointLocation::kInside;
    const bool in_b = locate(q, p.b) == PointLocation::kInside;
    for (std::size_t k = 0; k < kOps.size(); ++k) {
      const bool expected = op_keeps(kOps[k], in_a, in_b);
      const bool actual = locate(q, r[k].polygons) != PointLocation::kOutside;
      if (expected != actual) {
        return Finding{std::string("point ") + point_text(q) +
                           " farther than 1.5 from both boundaries is " +
                           (actual ? "in" : "not in") + " the output but " +
                           (expected ? "in" : "not in") + " the exact result of " +
                           op_line(kOps[k], p.a, p.b) + "\n  output = " + to_wkt(r[k].polygons),
                       pair_log(kOps[k], p.a, p.b)};
      }
    }
  }
  return std::nullopt;
}

std::optional<Finding> clip_pair_checks(const Pair& p) {
  std::array<ClipResult, 4> results;
  for (std::size_t k = 0; k < kOps.size(); ++k) {
    const Text log_text = [&] { return pair_log(kOps[k], p.a, p.b); };
    const Text line = [&] { return op_line(kOps[k], p.a, p.b); };
    try {
      results[k] = clip(kOps[k], p.a, p.b, ClipOptions{.checked = true});
    } catch (const InternalError& e) {
      return Finding{std::string("InternalError: ") + e.what() + "\n  " + line(), log_text()};
    } catch (const std::exception& e) {
      return Finding{
          std::string("unexpected exception on valid inputs: ") + e.what() + "\n  " + line(),
          log_text()};
    }
    if (auto f = invalid_output(line, results[k].polygons, log_text)) return f;
  }
  if (auto f = check_pair_areas(p, results)) return f;
  return check_pair_points(p, results);
}

// The validating clip() (PolygonSet operands, which may be invalid here): InvalidInput exactly
// when validate() rejects an operand, naming the subject first and carrying validate()'s own
// first violation; otherwise exactly the ValidSet overload's result (clip/README.md,
// "Validating while clipping").
std::optional<Finding> validating_clip_agrees(ClipOp op, const PolygonSet& a, const PolygonSet& b,
                                              const Text& log) {
  const ValidationReport va = validate(a, 1), vb = validate(b, 1);
  const Text line = [&] { return op_line(op, a, b); };
  try {
    const ClipResult r = clip(op, a, b, ClipOptions{.checked = true});
    if (!va.ok() || !vb.ok()) {
      return Finding{"clip() accepted an invalid operand (" +
                         (va.ok() ? vb : va).violations.front().describe() + "): " + line(),
                     log()};
    }
    const ValidClipResult v =
        clip(op, ValidSet(a), ValidSet(b, Operand::kClip), ClipOptions{.checked = true});
    if (v.set.polygons() != r.polygons)
      return Finding{"clip() on PolygonSets and on ValidSets differ: " + line(), log()};
  } catch (const InvalidInput& e) {
    if (va.ok() && vb.ok())
      return Finding{std::string("InvalidInput on valid operands: ") + e.what() + "\n  " + line(),
                     log()};
    const Operand which = va.ok() ? Operand::kClip : Operand::kSubject;
    const Violation& expected = (va.ok() ? vb : va).violations.front();
    if (e.operand != which || e.violation.describe() != expected.describe()) {
      return Finding{std::string("clip() reports ") + e.what() + " where validate() finds " +
                         (va.ok() ? "clip: " : "subject: ") + expected.describe() + "\n  " + line(),
                     log()};
    }
  } catch (const InternalError& e) {
    return Finding{std::string("InternalError: ") + e.what() + "\n  " + line(), log()};
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what() + "\n  " + line(), log()};
  }
  return std::nullopt;
}

// ---- clip_sequence ----------------------------------------------------------------------

struct SequenceRun {
  std::optional<Finding> finding;
  std::string log;
};

SequenceRun run_sequence(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  Decoder decoder(in);
  log::EditLog recorder;
  log::EvolvingSet state(decoder.valid_set());
  recorder.record_set(state.current());
  const std::size_t steps = in.ConsumeIntegralInRange<std::size_t>(1, kMaxSteps);
  const ClipOptions checked{.checked = true};
  for (std::size_t s = 0; s < steps && in.remaining_bytes() > 0; ++s) {
    if (vertex_count(state.current()) > kMaxStateVertices) break;
    decoder.absorb(state.current());
    const ClipOp op = in.PickValueInArray(kOps);
    const bool raw = in.ConsumeIntegralInRange(0, 7) == 0;
    PolygonSet operand;
    if (raw) {
      for (Ring& ring : decoder.raw_rings(false)) operand.push_back(std::move(ring));
    } else {
      operand = decoder.valid_set();
    }
    const PolygonSet before = state.current();
    const Text context = [&] { return op_line(op, before, operand); };
    const Text log_so_far = [&] { return recorder.text(); };
    // Now and then the validating clip() on operands that may be invalid: the raw operand, or
    // the state and the operand merged into one set (members overlapping, nested, sharing
    // edges in one direction, or a valid set after all). Chosen from what is already decoded,
    // consuming no input: saved inputs keep decoding to the cases they were saved for.
    switch ((s + before.size() + 3 * operand.size()) % 4) {
      case 0: {
        PolygonSet merged = before;
        merged.insert(merged.end(), operand.begin(), operand.end());
        const bool merged_first = (s / 4) % 2 == 0;
        if (auto f = validating_clip_agrees(op, merged_first ? merged : operand,
                                            merged_first ? operand : merged, log_so_far))
          return {f, recorder.text()};
        break;
      }
      case 1:
        if (raw) {
          if (auto f = validating_clip_agrees(op, operand, before, log_so_far))
            return {f, recorder.text()};
        }
        break;
      default:
        break;
    }
    try {
      state.apply(op, operand, checked);
    } catch (const InvalidInput& e) {
      if (state.current() != before) {
        return {Finding{"a step rejected with InvalidInput changed the set: " + context(),
                        recorder.text()},
                recorder.text()};
      }
      if (e.operand != Operand::kClip || validate(operand, 0).ok()) {
        return {
            Finding{std::string("InvalidInput (") + e.what() +
                        ") for a step whose only bad operand could be the clip one: " + context(),
                    recorder.text()},
            recorder.text()};
      }
      continue;
    } catch (const InternalError& e) {
      recorder.comment(std::string("the next step failed: ") + e.what());
      recorder.record_clip(op, before, operand, before);
      return {
          Finding{std::string("InternalError: ") + e.what() + "\n  " + context(), recorder.text()},
          recorder.text()};
    }
    recorder.record_clip(op, before, operand, state.current());
    if (auto f = invalid_output(context, state.current(), log_so_far)) {
      return {f, recorder.text()};
    }
  }
  // The recorded log must replay to the same state (recorder, parser and determinism).
  const log::ParsedLog parsed = log::parse_log(recorder.text());
  if (parsed.error) {
    return {Finding{std::string("recorded log does not parse: ") + parsed.error->what(),
                    recorder.text()},
            recorder.text()};
  }
  log::EvolvingSet replayed;
  for (const log::Step& step : parsed.steps) replayed.apply(step);
  if (replayed.current() != state.current()) {
    return {Finding{"replaying the recorded log gives another state:\n  live = " +
                        to_wkt(state.current()) + "\n  replay = " + to_wkt(replayed.current()),
                    recorder.text()},
            recorder.text()};
  }
  return {std::nullopt, recorder.text()};
}

// ---- normalize --------------------------------------------------------------------------

// Runs `fill` (normalize or import_polygons of rings, checked mode) into `result`. A finding
// (wrapped) when it fails other than by the documented typed error for out-of-range rings,
// accepts such rings, or returns an invalid set; nullopt (unwrapped) when all is well, and a
// wrapped nullopt when the typed error was rightly thrown (nothing more to check).
template <class Fill>
std::optional<std::optional<Finding>> filled_checks(const Text& context, bool out_of_range,
                                                    ClipResult& result, Fill&& fill) {
  try {
    result = fill();
  } catch (const InternalError& e) {
    return Finding{std::string("InternalError: ") + e.what() + "\n  " + context(), ""};
  } catch (const InvalidInput& e) {
    if (out_of_range) return std::optional<Finding>{};  // the documented typed error
    return Finding{std::string("in-range rings rejected: ") + e.what() + "\n  " + context(), ""};
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what() + "\n  " + context(), ""};
  }
  if (out_of_range) return Finding{"out-of-range coordinate accepted: " + context(), ""};
  if (auto f = invalid_output(context, result.polygons, [] { return std::string(); })) return f;
  return std::nullopt;
}

// The same rings read as one OGC polygon (ring 0 its exterior, the rest its holes) by
// import_polygons: valid output, and far from every ring a point is inside exactly when the
// rings winding around it (exterior +1, holes -1) sum to more than zero (clip.hpp).
std::optional<Finding> import_checks(const std::vector<Ring>& rings, bool out_of_range) {
  if (rings.empty()) return std::nullopt;
  const std::vector<std::vector<Ring>> polygons{rings};
  const Text context = [&] {
    return "import_polygons of the polygon " + to_wkt(PolygonSet(rings.begin(), rings.end())) +
           " (ring 0 its exterior)";
  };
  ClipResult result;
  if (auto f = filled_checks(context, out_of_range, result, [&] {
        return import_polygons(polygons, ClipOptions{.checked = true});
      }))
    return *f;
  if (!small(rings)) return std::nullopt;
  for (const Point64& q : sample_points(rings)) {
    if (!far_from_rings(q, rings)) continue;
    int value = 0;
    for (std::size_t r = 0; r < rings.size(); ++r)
      value += (winding_number(q, rings[r]) != 0 ? 1 : 0) * (r == 0 ? 1 : -1);
    const bool actual = locate(q, result.polygons) != PointLocation::kOutside;
    if ((value > 0) != actual)
      return Finding{"point " + point_text(q) + (actual ? " is" : " is not") +
                         " in the output of " + context() +
                         "\n  output = " + to_wkt(result.polygons),
                     ""};
  }
  return std::nullopt;
}

std::optional<Finding> normalize_checks(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  Decoder decoder(in);
  const FillRule rule = in.PickValueInArray(kRules);
  const std::vector<Ring> rings = decoder.raw_rings(true);
  bool out_of_range = false;
  for (const Ring& r : rings) {
    for (const Point64& p : r) out_of_range = out_of_range || !in_range(p);
  }
  const Text context = [&] {
    return std::string("normalize ") + fill_rule_name(rule) +
           " rings = " + to_wkt(PolygonSet(rings.begin(), rings.end()));
  };
  ClipResult result;
  if (auto f = filled_checks(context, out_of_range, result,
                             [&] { return normalize(rings, rule, ClipOptions{.checked = true}); }))
    return *f;
  if (auto f = import_checks(rings, out_of_range)) return f;
  if (!small(rings)) return std::nullopt;
  for (const Point64& q : sample_points(rings)) {
    if (!far_from_rings(q, rings)) continue;
    int w = 0;
    for (const Ring& r : rings) w += winding_number(q, r);
    const bool expected = rule_fills(rule, w);
    const bool actual = locate(q, result.polygons) != PointLocation::kOutside;
    if (expected != actual) {
      return Finding{"point " + point_text(q) + " with winding number " + std::to_string(w) +
                         (actual ? " is" : " is not") + " in the output of " + context() +
                         "\n  output = " + to_wkt(result.polygons),
                     ""};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Finding> run_clip_pair(const std::uint8_t* data, std::size_t size) {
  Pair pair;
  try {
    pair = decode_pair(data, size);
  } catch (const std::exception& e) {  // decoding normalizes: a failure there is a finding too
    return Finding{std::string("decoding (normalize) failed: ") + e.what(), ""};
  }
  return clip_pair_checks(pair);
}

std::optional<Finding> run_clip_sequence(const std::uint8_t* data, std::size_t size) {
  try {
    return run_sequence(data, size).finding;
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what(), ""};
  }
}

std::optional<Finding> run_normalize(const std::uint8_t* data, std::size_t size) {
  try {
    return normalize_checks(data, size);
  } catch (const std::exception& e) {
    return Finding{std::string("unexpected exception: ") + e.what(), ""};
  }
}

std::optional<Finding> run_parse(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const WktGeometry g = read_wkt(text);
    for (const WktPolygon& polygon : g.polygons) {
      std::vector<const Ring*> rings{&polygon.exterior};
      for (const Ring& hole : polygon.holes) rings.push_back(&hole);
      for (const Ring* ring : rings) {
        for (const Point64& p : *ring) {
          if (!in_range(p)) return Finding{"read_wkt returned an out-of-range point", ""};
        }
      }
    }
  } catch (const WktError&) {
    // the documented typed error
  } catch (const std::exception& e) {
    return Finding{std::string("read_wkt threw an untyped exception: ") + e.what(), ""};
  }
  try {
    const log::ParsedLog parsed = log::parse_log(text);
    if (parsed.error) {
      const std::size_t lines =
          static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
      if (parsed.error->line == 0 || parsed.error->line > lines) {
        return Finding{"log error names line " + std::to_string(parsed.error->line) + " of " +
                           std::to_string(lines),
                       ""};
      }
    }
  } catch (const std::exception& e) {
    return Finding{std::string("parse_log threw: ") + e.what(), ""};
  }
  return std::nullopt;
}

Runner runner_for(std::string_view target) {
  if (target == "clip_pair") return run_clip_pair;
  if (target == "clip_sequence") return run_clip_sequence;
  if (target == "normalize") return run_normalize;
  if (target == "parse") return run_parse;
  if (target == "edit_sequence") return run_edit_sequence;
  if (target == "load") return run_load;
  if (target == "polygon_pieces") return run_polygon_pieces;
  if (target == "game_sequence") return run_game_sequence;
  return nullptr;
}

std::string input_as_log(std::string_view target, const std::uint8_t* data, std::size_t size) {
  try {
    if (target == "clip_pair") {
      const Pair pair = decode_pair(data, size);
      std::string text;
      for (const ClipOp op : kOps) text += pair_log(op, pair.a, pair.b);
      return text;
    }
    if (target == "clip_sequence") return run_sequence(data, size).log;
    if (target == "edit_sequence") return edit_sequence_log(data, size);
  } catch (const std::exception&) {
    // decoding itself failed: there is no log to give
  }
  return "";
}

}  // namespace edgeland::fuzz
