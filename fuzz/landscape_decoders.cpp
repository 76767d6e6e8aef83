// The landscape's fuzz targets (issue 15, "Verification"): edit sequences in checked mode, and
// arbitrary bytes as save files. Declared in decoders.hpp beside the clipper's targets; the
// decoding of worlds and edits (landscape_decoding.hpp) is shared with game_sequence.
#include <algorithm>
#include <exception>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "allocation_meter.hpp"
#include "decoders.hpp"
#include "edgeland/kernel/angle.hpp"
#include "edgeland/kernel/box_queries.hpp"
#include "edgeland/kernel/point_in_polygon.hpp"
#include "edgeland/kernel/predicates.hpp"
#include "edgeland/kernel/shapes.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/spatial/landscape.hpp"
#include "edgeland/spatial/log_format.hpp"
#include "edgeland/spatial/tree_boxes.hpp"
#include "landscape_decoding.hpp"

namespace edgeland::fuzz {
namespace {

std::int64_t clamp_coord(std::int64_t v) { return std::clamp(v, -kCoordBound, kCoordBound); }

// ---- decoding ---------------------------------------------------------------------------------
// The points as a fan around the lowest one, by angle: counter-clockwise and simple unless
// points repeat or line up with the pivot.
Polygon fan(Polygon pts) {
  std::iter_swap(pts.begin(), std::min_element(pts.begin(), pts.end(), [](Point64 a, Point64 b) {
                   return a.y != b.y ? a.y < b.y : a.x < b.x;
                 }));
  const Point64 o = pts.front();
  std::sort(pts.begin() + 1, pts.end(), [o](Point64 a, Point64 b) {
    return angle_less({a.x - o.x, a.y - o.y}, {b.x - o.x, b.y - o.y});
  });
  return pts;
}

}  // namespace

Box64 EditDecoder::world() {
  const int bits = in_.PickValueInArray({4, 6, 8, 10, 14, 31});
  const std::int64_t span = bits == 31 ? kCoordBound : std::int64_t{1} << bits;
  const std::int64_t x0 = in_.ConsumeIntegralInRange<std::int64_t>(-span, span - 1);
  const std::int64_t y0 = in_.ConsumeIntegralInRange<std::int64_t>(-span, span - 1);
  const std::int64_t x1 = in_.ConsumeIntegralInRange<std::int64_t>(x0 + 1, span);
  const std::int64_t y1 = in_.ConsumeIntegralInRange<std::int64_t>(y0 + 1, span);
  world_ = {{x0, y0}, {x1, y1}};
  return world_;
}

LandscapeConfig EditDecoder::config() {
  LandscapeConfig c;
  c.tree = in_.ConsumeBool() ? TreeKind::kQuadtree : TreeKind::kKdTree;
  c.edge_cap = in_.PickValueInArray<std::uint32_t>({32, 40, 64, 256});
  c.merge_below = c.edge_cap / 3;
  c.min_cell_size = in_.PickValueInArray<std::int64_t>({1, 2, 16});
  if (in_.ConsumeIntegralInRange(0, 6) == 0) c.grid_depth = in_.ConsumeIntegralInRange(0, 3);
  return c;
}

Point64 EditDecoder::point(const Landscape& l) {
  Point64 p;
  switch (in_.ConsumeIntegralInRange(0, 5)) {
    case 0:
      p = cell_line_point();
      break;
    case 1:
      p = landscape_vertex(l);
      break;
    case 2:
      p = {world_.min.x, in_.ConsumeIntegralInRange(world_.min.y, world_.max.y)};
      break;
    default:
      p = anywhere();
      break;
  }
  const std::int64_t dx = in_.ConsumeIntegralInRange(-1, 1), dy = in_.ConsumeIntegralInRange(-1, 1);
  return {clamp_coord(p.x + dx), clamp_coord(p.y + dy)};
}

PolygonSet EditDecoder::shape(const Landscape& l) {
  builder_problem_.clear();
  const int kind = in_.ConsumeIntegralInRange(0, 12);
  Polygon ring;
  if (kind >= 10) {
    ring = built_shape(l);
  } else if (kind <= 3) {
    const Point64 a = point(l), b = point(l);
    ring = {{std::min(a.x, b.x), std::min(a.y, b.y)},
            {std::max(a.x, b.x), std::min(a.y, b.y)},
            {std::max(a.x, b.x), std::max(a.y, b.y)},
            {std::min(a.x, b.x), std::max(a.y, b.y)}};
  } else {
    const std::size_t n =
        kind <= 5 ? 3 : in_.ConsumeIntegralInRange<std::size_t>(3, kMaxShapePoints);
    for (std::size_t i = 0; i < n; ++i) ring.push_back(point(l));
    // Mostly valid shapes (a fan around the lowest point, counter-clockwise); kind 8 keeps
    // the points as drawn (often crossing itself), kind 9 also leaves the coordinate range.
    if (kind < 8) ring = fan(std::move(ring));
    if (kind == 9 && !ring.empty())
      ring.back().x = kCoordBound + 1 + in_.ConsumeIntegralInRange(0, 5);
  }
  PolygonSet set{ring};
  if (in_.ConsumeIntegralInRange(0, 4) == 0) set.push_back(shape_rectangle(l));
  return set;
}

Polygon EditDecoder::shape_rectangle(const Landscape& l) {
  const Point64 a = point(l);
  const std::int64_t w = in_.ConsumeIntegralInRange(1, 40), h = in_.ConsumeIntegralInRange(1, 40);
  return {a,
          {clamp_coord(a.x + w), a.y},
          {clamp_coord(a.x + w), clamp_coord(a.y + h)},
          {a.x, clamp_coord(a.y + h)}};
}

namespace {

// What is wrong with a builder's polygon (shapes.hpp GUARANTEES: valid, strictly convex,
// counter-clockwise, in range), or nothing. Valid (simple) with a left turn at every vertex is
// strictly convex.
std::optional<std::string> broken_shape_contract(const Polygon& p) {
  if (p.size() < 3) return "fewer than 3 vertices";
  for (const Point64& v : p)
    if (!in_range(v)) return "a vertex beyond the bound";
  const ValidationReport report = validate(PolygonSet{p}, 1);
  if (!report.ok()) return "not valid: " + report.violations.front().describe();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (orientation(p[i], p[(i + 1) % p.size()], p[(i + 2) % p.size()]) !=
        Orientation::kCounterClockwise)
      return "not strictly convex at vertex " + std::to_string((i + 1) % p.size());
  return std::nullopt;
}

std::string point_text(Point64 p) {
  return "(" + std::to_string(p.x) + " " + std::to_string(p.y) + ")";
}

}  // namespace

// A centre near the world (point()), or now and then one to five units past the bound.
Point64 EditDecoder::shape_center(const Landscape& l, bool& in_range) {
  if (in_.ConsumeIntegralInRange(0, 15) != 0) return point(l);
  in_range = false;
  const std::int64_t past = kCoordBound + in_.ConsumeIntegralInRange(1, 5);
  return in_.ConsumeBool() ? Point64{past, 0} : Point64{0, -past};
}

// Radii of every scale up to kMaxShapeRadius (2^33: a shape covering the whole bound from any
// centre), now and then one out of its range.
std::int64_t EditDecoder::shape_radius(bool& in_range) {
  switch (in_.ConsumeIntegralInRange(0, 15)) {
    case 0:
      in_range = false;
      return in_.PickValueInArray<std::int64_t>({0, -1, kMaxShapeRadius + 1,
                                                 std::numeric_limits<std::int64_t>::min(),
                                                 std::numeric_limits<std::int64_t>::max()});
    case 1:
      return kMaxShapeRadius;
    default: {
      const int bits = in_.PickValueInArray({1, 2, 3, 4, 6, 8, 10, 14, 20, 33});
      return in_.ConsumeIntegralInRange<std::int64_t>(1, std::int64_t{1} << bits);
    }
  }
}

// One of the builders of kernel/shapes.hpp. Its result must keep the builder's guarantees, and
// it must refuse exactly the arguments out of their ranges (with the typed errors); whatever
// it broke is kept in builder_problem_. A refused call gives a rectangle instead.
Polygon EditDecoder::built_shape(const Landscape& l) {
  bool in_range = true;
  const Point64 c = shape_center(l, in_range);
  const std::int64_t r = shape_radius(in_range);
  std::string call;
  try {
    Polygon p;
    switch (in_.ConsumeIntegralInRange(0, 3)) {
      case 0:
        call = "circle(" + point_text(c) + ", " + std::to_string(r) + ")";
        p = circle(c, r);
        break;
      case 1: {
        std::int64_t sides = in_.ConsumeBool() ? in_.ConsumeIntegralInRange(3, 12)
                                               : in_.ConsumeIntegralInRange(3, 300);
        if (in_.ConsumeIntegralInRange(0, 15) == 0) {
          in_range = false;
          sides = in_.PickValueInArray<std::int64_t>({2, 0, -5, kMaxShapeSides + 1});
        }
        const Turn phase{in_.ConsumeIntegral<std::int64_t>(),
                         in_.ConsumeIntegralInRange<std::int64_t>(1, kMaxTurnDenominator)};
        call = "regular_polygon(" + point_text(c) + ", " + std::to_string(r) + ", " +
               std::to_string(sides) + ", {" + std::to_string(phase.num) + ", " +
               std::to_string(phase.den) + "})";
        p = regular_polygon(c, r, sides, phase);
        break;
      }
      case 2: {
        const Point64 b = shape_center(l, in_range);
        call = "capsule(" + point_text(c) + ", " + point_text(b) + ", " + std::to_string(r) + ")";
        p = capsule(c, b, r);
        break;
      }
      default: {
        const std::int64_t h = shape_radius(in_range);
        Turn angle{in_.ConsumeIntegralInRange<std::int64_t>(-64, 64),
                   in_.PickValueInArray<std::int64_t>({1, 3, 8, 12, 360, 65536})};
        if (in_.ConsumeIntegralInRange(0, 15) == 0) {
          in_range = false;
          angle.den = in_.PickValueInArray<std::int64_t>({0, -1, kMaxTurnDenominator + 1});
        }
        call = "rotated_box(" + point_text(c) + ", " + std::to_string(r) + ", " +
               std::to_string(h) + ", {" + std::to_string(angle.num) + ", " +
               std::to_string(angle.den) + "})";
        p = rotated_box(c, r, h, angle);
        break;
      }
    }
    if (!in_range)
      builder_problem_ = call + " accepted an argument out of its range";
    else if (auto why = broken_shape_contract(p))
      builder_problem_ = call + ": " + *why;
    return p;
  } catch (const CoordinateOutOfRange& e) {
    if (in_range) builder_problem_ = call + " refused arguments in range: " + e.what();
  } catch (const ArgumentOutOfRange& e) {
    if (in_range) builder_problem_ = call + " refused arguments in range: " + e.what();
  } catch (const std::exception& e) {
    builder_problem_ = call + " threw " + e.what();
  }
  return shape_rectangle(l);
}

MaterialMap EditDecoder::material_map() {
  MaterialMap map;
  for (std::uint8_t m = 0; m <= 4; ++m) map.set(m, in_.ConsumeIntegralInRange<std::uint8_t>(0, 4));
  return map;
}

Point64 EditDecoder::anywhere() {
  const std::int64_t mx = (world_.max.x - world_.min.x) / 4 + 2,
                     my = (world_.max.y - world_.min.y) / 4 + 2;
  return {clamp_coord(in_.ConsumeIntegralInRange(world_.min.x - mx, world_.max.x + mx)),
          clamp_coord(in_.ConsumeIntegralInRange(world_.min.y - my, world_.max.y + my))};
}

// The midpoint lines of the first three levels of a quadtree over the world.
Point64 EditDecoder::cell_line_point() {
  const int level = in_.ConsumeIntegralInRange(1, 3);
  const int k = in_.ConsumeIntegralInRange(0, (1 << level) - 1);
  const std::int64_t x = world_.min.x + (world_.max.x - world_.min.x) * (2 * k + 1) / (2 << level);
  return in_.ConsumeBool() ? Point64{x, in_.ConsumeIntegralInRange(world_.min.y, world_.max.y)}
                           : Point64{in_.ConsumeIntegralInRange(world_.min.x, world_.max.x),
                                     world_.min.y + (world_.max.y - world_.min.y) / 2};
}

Point64 EditDecoder::landscape_vertex(const Landscape& l) {
  std::vector<Point64> seen;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    seen.insert(seen.end(), v.polygon->begin(), v.polygon->end());
    return seen.size() < 256;
  });
  if (seen.empty()) return anywhere();
  return seen[in_.ConsumeIntegralInRange<std::size_t>(0, seen.size() - 1)];
}

DecodedEdit next_edit(Provider& in, EditDecoder& decode, const Landscape& l) {
  DecodedEdit e;
  e.kind = in.ConsumeIntegralInRange(0, 4);
  e.a = in.ConsumeIntegralInRange<std::uint8_t>(e.kind == 3 ? 0 : 1, 4);
  e.b = in.ConsumeIntegralInRange<std::uint8_t>(0, 4);
  if (e.kind == 4) e.map = decode.material_map();
  e.shape = decode.shape(l);
  e.builder_problem = decode.builder_problem();
  e.snapshot = in.ConsumeBool();
  return e;
}

Landscape decode_world(Provider& in, EditDecoder& decode) {
  const Box64 world = decode.world();
  const Material fill = in.ConsumeIntegralInRange<std::uint8_t>(0, 3);
  LandscapeConfig config = decode.config();
  // A grid deeper than min_cell_size lets this world split is refused (InvalidConfig): take
  // the deepest one it allows.
  config.grid_depth = std::min(config.grid_depth, max_grid_depth(world, config));
  return Landscape(world, fill, config, kLimits);
}

std::string edit_text(const DecodedEdit& d) {
  // The landscape log's own writer (log_format.hpp); kind is its LandscapeEditKind's order.
  std::string line = d.kind >= 4 ? log::relabel_line(d.shape, d.map)
                                 : log::edit_line(static_cast<log::LandscapeEditKind>(d.kind),
                                                  d.shape, d.kind == 3 ? d.b : d.a, d.a);
  line.pop_back();  // its '\n'
  return line;
}

ChangeSet apply(Landscape& l, const DecodedEdit& d) {
  switch (d.kind) {
    case 0:
      return l.carve(d.shape);
    case 1:
      return l.fill(d.shape, d.a);
    case 2:
      return l.fill_empty(d.shape, d.a);
    case 3:
      return l.replace(d.shape, d.a, d.b);
    default:
      return l.relabel(d.shape, d.map);
  }
}

// ---- checks -----------------------------------------------------------------------------------
namespace {

Finding finding(const std::string& what, const Landscape& l) {
  return {what + "\n  world after the last good edit: state hash " + std::to_string(l.state_hash()),
          l.log()};
}

// material_at, raycast and overlaps against a scan of every polygon (no tree), at a few points.
std::optional<std::string> check_queries(const Landscape& l, Provider& in, EditDecoder& decode) {
  std::vector<PolygonView> all;
  l.polygons_in(l.world(), [&](const PolygonView& v) {
    all.push_back(v);
    return true;
  });
  for (int k = 0; k < 4 && in.remaining_bytes() > 0; ++k) {
    const Point64 p = decode.point(l);
    Material want = kEmpty;
    for (const PolygonView& v : all)
      if (inside_half_open(p, *v.polygon)) want = v.material;
    if (l.material_at(p) != want)
      return "material_at disagrees with a scan of all polygons at (" + std::to_string(p.x) + " " +
             std::to_string(p.y) + ")";
    const Point64 q = decode.point(l);
    if (p == q) continue;
    std::optional<MaterialCrossing> first;
    for (const MaterialCrossing& c : l.crossings(p, q))
      if (c.after != kEmpty) {
        first = c;
        break;
      }
    const auto hit = l.raycast(p, q);
    if (hit.has_value() != first.has_value() || (hit && compare(hit->t, first->t) != 0))
      return "raycast disagrees with the first solid crossing of crossings()";
    const Box64 box{{std::min(p.x, q.x), std::min(p.y, q.y)},
                    {std::max(p.x, q.x), std::max(p.y, q.y)}};
    std::vector<Material> scan;
    for (const PolygonView& v : all)
      if (interiors_overlap(box, *v.polygon)) scan.push_back(v.material);
    std::sort(scan.begin(), scan.end());
    scan.erase(std::unique(scan.begin(), scan.end()), scan.end());
    if (l.overlaps(box) != scan) return "overlaps(box) disagrees with a scan of all polygons";
  }
  return std::nullopt;
}

std::optional<std::string> check_round_trips(const Landscape& l, const Landscape& snapshot,
                                             std::uint64_t snapshot_hash) {
  std::stringstream file;
  l.save(file);
  const Landscape back = Landscape::load(file, kLimits);
  if (back.state_hash() != l.state_hash()) return "save -> load changed the state hash";
  if (snapshot.state_hash() != snapshot_hash)
    return "a snapshot changed when its original was edited";
  return std::nullopt;
}

std::uint64_t fnv1a64(const std::uint8_t* data, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ data[i]) * 0x100000001b3ull;
  return h;
}

}  // namespace

std::optional<Finding> run_edit_sequence(const std::uint8_t* data, std::size_t size) {
  Provider in(data, size);
  EditDecoder decode(in);
  Landscape l = decode_world(in, decode);
  l.set_checked(true);
  l.start_log();
  Landscape snapshot = l;
  std::uint64_t snapshot_hash = l.state_hash();
  for (int i = 0; i < kMaxEdits && in.remaining_bytes() > 0; ++i) {
    const DecodedEdit d = next_edit(in, decode, l);
    if (!d.builder_problem.empty()) return finding("shape builder: " + d.builder_problem, l);
    if (d.snapshot) {
      snapshot = l;
      snapshot_hash = l.state_hash();
    }
    const std::uint64_t before = l.state_hash();
    try {
      apply(l, d);
    } catch (const LandscapeInternalError& e) {
      return Finding{std::string(e.what()) + "\n  edit: " + edit_text(d), e.log};
    } catch (const InvalidInput&) {  // CoordinateOutOfRange too
      if (l.state_hash() != before) return finding("a rejected shape changed the landscape", l);
    } catch (const LimitExceeded&) {
      if (l.state_hash() != before) return finding("an edit over a limit changed the landscape", l);
    } catch (const std::exception& e) {
      return finding(std::string("an edit threw ") + e.what() + "\n  edit: " + edit_text(d), l);
    }
  }
  const LandscapeReport report = l.check();
  if (!report.ok()) return finding("check() after the sequence: " + report.problems.front(), l);
  if (auto q = check_queries(l, in, decode)) return finding(*q, l);
  if (auto r = check_round_trips(l, snapshot, snapshot_hash)) return finding(*r, l);
  return std::nullopt;
}

// The memory a load may take (issue 27, point 1): a small multiple of the file, plus the world
// it returns; a refused file, the world it had read by then, which costs at most about 165
// bytes per byte of the file (an empty cell: 2 bytes in the file, a node in memory).
constexpr std::size_t kFileCopies = 4, kWorldCopies = 2, kRefusedBytesPerByte = 256;
constexpr std::size_t kLoadSlack = std::size_t{1} << 20;

std::optional<Finding> run_load(const std::uint8_t* data, std::size_t size) {
  // An odd first byte asks for the rest to be read with a correct checksum, so that mutations
  // reach the parser and the checks behind it instead of stopping at the checksum (the custom
  // mutator of load_fuzzer.cpp writes files with it set).
  std::string bytes(reinterpret_cast<const char*>(data), size);
  if (!bytes.empty()) {
    const bool fix = (bytes[0] & 1) != 0;
    bytes.erase(0, 1);
    if (fix && bytes.size() >= 8) {
      const std::uint64_t h =
          fnv1a64(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size() - 8);
      for (int i = 0; i < 8; ++i) bytes[bytes.size() - 8 + i] = static_cast<char>(h >> (8 * i));
    }
  }
  std::istringstream file(bytes);
  std::optional<Landscape> loaded;
  bool refused = false;
  std::string other_error;
  const std::size_t peak = peak_heap_during([&] {
    try {
      loaded.emplace(Landscape::load(file, kLimits));
    } catch (const LoadError&) {
      refused = true;
    } catch (const LimitExceeded&) {
      refused = true;
    } catch (const std::exception& e) {
      other_error = e.what();
    }
  });
  if (!other_error.empty())
    return Finding{"load threw something other than LoadError or LimitExceeded: " + other_error,
                   ""};
  if (refused) {
    if (peak > kRefusedBytesPerByte * bytes.size() + kLoadSlack)
      return Finding{"a refused load took " + std::to_string(peak) + " bytes for a file of " +
                         std::to_string(bytes.size()),
                     ""};
    return std::nullopt;
  }
  const Landscape& l = *loaded;
  if (peak > kFileCopies * bytes.size() + kWorldCopies * l.stats().bytes + kLoadSlack)
    return Finding{"load took " + std::to_string(peak) + " bytes for a file of " +
                       std::to_string(bytes.size()) + " and a world of " +
                       std::to_string(l.stats().bytes),
                   ""};
  const LandscapeReport report = l.check();
  if (!report.ok())
    return Finding{"load accepted a world that fails check(): " + report.problems.front(), ""};
  std::stringstream again;
  l.save(again);
  if (Landscape::load(again, kLimits).state_hash() != l.state_hash())
    return Finding{"a loaded world saved and loaded again has another state hash", ""};
  return std::nullopt;
}

std::string edit_sequence_log(const std::uint8_t* data, std::size_t size) {
  // Replays the decoding with recording on; a rejected edit becomes a comment.
  Provider in(data, size);
  EditDecoder decode(in);
  Landscape l = decode_world(in, decode);
  l.start_log();
  std::string text = l.log();
  for (int i = 0; i < kMaxEdits && in.remaining_bytes() > 0; ++i) {
    const DecodedEdit d = next_edit(in, decode, l);
    try {
      apply(l, d);
      const std::string full = l.log();
      text += full.substr(std::min(text.size(), full.size()));
    } catch (const std::exception& e) {
      std::string why = e.what();
      std::replace(why.begin(), why.end(), '\n', ' ');
      text += "# rejected (" + why + "): " + edit_text(d) + "\n";
    }
  }
  return text;
}

}  // namespace edgeland::fuzz
